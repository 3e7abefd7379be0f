"""The application layer: the use cases, assembled once — fetch, where is, teach.

The command line, the dialogue, the evaluations and the notebooks call these instead of
putting parser, robot, tasks, perception and describer together themselves:

* :class:`Fetcher` — :meth:`Fetcher.fetch`: a fetch command's words to the robot facing the
  object's furniture;
* :class:`Finder` — :meth:`Finder.where_is`: "where is my X?" — search (or remember, or read
  the world file), then describe;
* :func:`teach` — record a demonstration of an RDT node by driving the robot with keys;
* :class:`Result` with one :data:`Status` (the executor's status enum) and a message: what
  each of them returns; :func:`open_robot` makes the robot of any spec the factory knows;
* :func:`scan_sources`, :func:`scan_source`, :func:`open_scan`, :func:`analyse_scan` — the
  recordings and depth images a person explores, and what the detector makes of a frame.
"""

from assistant.app.fetching import Fetcher
from assistant.app.result import Result, Status
from assistant.app.robots import DEFAULT_ROBOT, open_robot, spec_world
from assistant.app.scans import ScanSource, analyse_scan, open_scan, scan_source, scan_sources
from assistant.app.stopping import StoppableRobot, Stopped
from assistant.app.teaching import teach
from assistant.app.where import Finder, asked_object, known_object_names, world_environment

__all__ = ["DEFAULT_ROBOT", "Fetcher", "Finder", "Result", "ScanSource", "Status", "StoppableRobot", "Stopped",
           "analyse_scan", "asked_object", "known_object_names", "open_robot", "open_scan", "scan_source",
           "scan_sources", "spec_world", "teach", "world_environment"]

"""Which robot a use case drives: any spec :func:`~assistant.robot.make_robot` knows.

The simulator needs the home and scene it simulates, where to start and its seeds; a recorded
session or a real robot brings its own world with it and takes none of those. :func:`open_robot`
passes each adapter what it takes, and refuses a simulator spec that names another home than
the one the use case runs in (the robot and the floor plan the tasks plan on must agree).
"""

from __future__ import annotations

from assistant.errors import AssistantError
from assistant.robot import make_robot, parse_robot_spec

__all__ = ["DEFAULT_ROBOT", "open_robot", "spec_world"]

#: the robot every use case drives unless told otherwise
DEFAULT_ROBOT = "sim"


def spec_world(spec: str) -> str | None:
    """The home a ``sim:WORLD[:SCENE]`` spec names (None for ``sim`` and other robots).
    Raises the factory's clear error for an unknown robot kind."""
    parsed = parse_robot_spec(spec)
    if parsed.scheme != "sim" or not parsed.argument:
        return None
    return parsed.argument.partition(":")[0] or None


def open_robot(spec: str, world, scene: str, *, seed: int = 0, noise: bool = True, start=None,
               clear: bool = False):
    """A new, unconnected robot for ``spec`` (use it in a ``with`` block), given the use case's
    home options (:data:`~assistant.robot.factory.HOME_OPTIONS`; each adapter takes those it
    needs): ``world`` (a :class:`~assistant.world.World`) in ``scene``, starting at ``start``
    (default: the world's start pose), with odometry noise when ``noise`` (the localizer
    corrects it) and ``seed``. ``clear``: a simulated robot starting at ``start`` (where an
    earlier task left it) starts backed off from anything it touches there
    (:func:`~assistant.sim.kinematics.clear_start`). A robot object (not a spec: a replay made by
    the caller) is returned as it is."""
    if not isinstance(spec, str):
        return spec
    parsed = parse_robot_spec(spec)
    named = spec_world(str(parsed))
    if named is not None and named != world.name:
        raise AssistantError(f"the robot {parsed} is in the {named} home but the task is in the {world.name}; "
                             f"give --world {named} or --robot sim")
    if clear and start is not None and parsed.scheme == "sim":  # where an earlier task left it
        from assistant.sim.kinematics import clear_start

        start = clear_start(world, scene, start)
    return make_robot(parsed, world=world, scene=scene, start=start, seed=seed, noise=noise)

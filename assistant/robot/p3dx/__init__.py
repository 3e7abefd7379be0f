"""The Pioneer P3-DX base over the ARCOS client protocol (pure Python on pyserial).

Modules, lowest first: :mod:`~assistant.robot.p3dx.packet` (framing and checksum),
:mod:`~assistant.robot.p3dx.commands` (command numbers and payloads),
:mod:`~assistant.robot.p3dx.sip` (status packets), :mod:`~assistant.robot.p3dx.params`
(``hardware/p3dx.yaml``), :mod:`~assistant.robot.p3dx.odometry` (SIPs → world-frame odometry),
:mod:`~assistant.robot.p3dx.link` (the serial connection, its reader thread and watchdog),
:mod:`~assistant.robot.p3dx.robot` (:class:`P3DX`, the Robot adapter) and
:mod:`~assistant.robot.p3dx.fake` (a simulated controller on a pseudo-terminal, for tests).
pyserial is imported only when a port is opened.
"""

from assistant.robot.p3dx.params import P3DXParams, load_p3dx_params
from assistant.robot.p3dx.robot import P3DX, DepthCamera, p3dx_robot_from_spec

__all__ = ["DepthCamera", "P3DX", "P3DXParams", "load_p3dx_params", "p3dx_robot_from_spec"]

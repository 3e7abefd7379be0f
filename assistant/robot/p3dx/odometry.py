"""SIPs → odometry in the product's frame (metres, radians, counter-clockwise, world frame).

The controller integrates its wheel encoders into XPOS/YPOS (15-bit counters that wrap) and
THPOS, in a frame fixed when it powered up. The tracker unwraps the counters, scales them with
the conversion factors of ``hardware/p3dx.yaml``, and re-expresses the motion since the first
SIP in the world frame, starting at ``start`` (the robot's pose when it connected).
"""

from __future__ import annotations

import math

from assistant.geometry import Pose2D
from assistant.robot.frames import Odometry
from assistant.robot.p3dx.params import P3DXParams
from assistant.robot.p3dx.sip import Sip

__all__ = ["OdometryTracker"]

_WRAP = 0x8000  # XPOS / YPOS are 15-bit counters


def _counter_delta(new: int, old: int) -> int:
    """The signed change of a 15-bit counter, assuming it moved less than half a wrap."""
    delta = (new - old) % _WRAP
    return delta - _WRAP if delta >= _WRAP // 2 else delta


class OdometryTracker:
    """Accumulates SIPs into an :class:`~assistant.robot.frames.Odometry` (world frame)."""

    def __init__(self, params: P3DXParams, start: Pose2D | None = None):
        self.params = params
        self.start = start or Pose2D(0.0, 0.0, 0.0)
        self._last_raw: tuple[int, int] | None = None
        self._x_mm = 0.0  # unwrapped controller position, mm
        self._y_mm = 0.0
        self._origin: Pose2D | None = None  # controller pose at the first SIP (metres, radians)

    def update(self, sip: Sip, timestamp_s: float) -> Odometry:
        p = self.params
        if self._last_raw is None:
            self._x_mm = sip.x_raw * p.distance_mm_per_unit
            self._y_mm = sip.y_raw * p.distance_mm_per_unit
        else:
            self._x_mm += _counter_delta(sip.x_raw, self._last_raw[0]) * p.distance_mm_per_unit
            self._y_mm += _counter_delta(sip.y_raw, self._last_raw[1]) * p.distance_mm_per_unit
        self._last_raw = (sip.x_raw, sip.y_raw)
        controller = Pose2D(self._x_mm / 1000.0, self._y_mm / 1000.0, sip.th_raw * p.angle_rad_per_unit)
        if self._origin is None:
            self._origin = controller
        pose = self.start.compose(controller.relative_to(self._origin))
        left = sip.left_vel_raw * p.velocity_mm_s_per_unit
        right = sip.right_vel_raw * p.velocity_mm_s_per_unit
        linear = (left + right) / 2.0 / 1000.0
        angular = (right - left) * p.diff_conv_factor / 2.0
        return Odometry(pose, linear, angular, timestamp_s)

    def sonar_m(self, sip: Sip) -> dict[int, float]:
        """The sonar readings of ``sip`` in metres, by sonar number."""
        return {n: r * self.params.range_mm_per_unit / 1000.0 for n, r in sip.sonar_raw.items()}


def heading_units(theta_rad: float, params: P3DXParams) -> int:
    """A heading in the controller's units (0…4095), for the fake controller."""
    return int(round((theta_rad % (2 * math.pi)) / params.angle_rad_per_unit)) % 4096

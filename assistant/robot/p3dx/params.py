"""The P3-DX's parameters (``hardware/p3dx.yaml``): conversion factors, geometry, limits, timing."""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, replace

from assistant.errors import DataFileError
from assistant.robot.hardware import load_hardware_file, number

__all__ = ["P3DXParams", "load_p3dx_params"]


@dataclass(frozen=True)
class P3DXParams:
    """What the driver needs to know about the base. Units in the names."""

    baud: int = 9600
    angle_rad_per_unit: float = 2 * math.pi / 4096
    distance_mm_per_unit: float = 1.0
    velocity_mm_s_per_unit: float = 1.0
    range_mm_per_unit: float = 1.0
    diff_conv_factor: float = 0.0056
    wheel_base_m: float = 2 / 0.0056 / 1000
    radius_m: float = 0.25
    max_linear_m_s: float = 0.75
    max_angular_rad_s: float = math.radians(100.0)
    linear_accel_m_s2: float = 0.3
    angular_accel_rad_s2: float = math.radians(100.0)
    sip_period_s: float = 0.1
    link_watchdog_s: float = 0.5
    keepalive_s: float = 0.25
    command_timeout_s: float = 2.0
    controller_watchdog_s: float = 2.0
    handshake_timeout_s: float = 3.0
    bump_stall: int = 3
    source: str = "built-in defaults"

    def with_timing(self, **changes: float) -> "P3DXParams":
        """A copy with some timing values changed (tests shorten the watchdogs)."""
        allowed = {"sip_period_s", "link_watchdog_s", "keepalive_s", "command_timeout_s",
                   "controller_watchdog_s", "handshake_timeout_s"}
        unknown = set(changes) - allowed
        if unknown:
            raise TypeError(f"not timing values: {', '.join(sorted(unknown))}")
        return replace(self, **changes)

    def limited(self, max_linear_m_s: float | None = None,
                max_angular_rad_s: float | None = None) -> "P3DXParams":
        """A copy with lower speed limits (never higher than the file's)."""
        linear = self.max_linear_m_s if max_linear_m_s is None else min(self.max_linear_m_s, max_linear_m_s)
        angular = (self.max_angular_rad_s if max_angular_rad_s is None
                   else min(self.max_angular_rad_s, max_angular_rad_s))
        if not (linear > 0 and angular > 0):
            raise ValueError("speed limits must be positive")
        return replace(self, max_linear_m_s=linear, max_angular_rad_s=angular)


def load_p3dx_params(folder: str | os.PathLike[str] | None = None) -> P3DXParams:
    """Read and check ``p3dx.yaml`` (from ``folder`` or the hardware folder)."""
    data = load_hardware_file("p3dx.yaml", folder)
    path = data["__path__"]
    serial = data.get("serial") or {}
    baud = serial.get("baud", 9600)
    if baud not in (9600, 19200, 38400, 57600, 115200):
        raise DataFileError(path, "serial.baud", f"expected 9600, 19200, 38400, 57600 or 115200, got {baud!r}")
    safety = data.get("safety") or {}
    bump_stall = safety.get("bump_stall", 3)
    if bump_stall not in (0, 1, 2, 3):
        raise DataFileError(path, "safety.bump_stall", f"expected 0, 1, 2 or 3, got {bump_stall!r}")
    conv = {k: number(data, "conversion", k) for k in (
        "angle_rad_per_unit", "distance_mm_per_unit", "velocity_mm_s_per_unit", "range_mm_per_unit",
        "diff_conv_factor")}
    wheel_base = number(data, "geometry", "wheel_base_m")
    implied = 2.0 / conv["diff_conv_factor"] / 1000.0
    if abs(wheel_base - implied) > 0.01 * implied:
        raise DataFileError(path, "geometry.wheel_base_m",
                            f"{wheel_base} m disagrees with conversion.diff_conv_factor, which implies "
                            f"{implied:.4f} m (2 / factor, in mm); change one of them")
    timing = {k: number(data, "timing", k) for k in (
        "sip_period_s", "link_watchdog_s", "keepalive_s", "command_timeout_s", "controller_watchdog_s",
        "handshake_timeout_s")}
    if timing["keepalive_s"] >= timing["controller_watchdog_s"]:
        raise DataFileError(path, "timing.keepalive_s", "must be shorter than controller_watchdog_s, "
                                                        "or the controller stops the motors between packets")
    if timing["command_timeout_s"] <= timing["keepalive_s"]:
        raise DataFileError(path, "timing.command_timeout_s", "must be longer than keepalive_s")
    if timing["link_watchdog_s"] <= timing["sip_period_s"]:
        raise DataFileError(path, "timing.link_watchdog_s", "must be longer than sip_period_s")
    return P3DXParams(
        baud=int(baud), **conv, wheel_base_m=wheel_base, radius_m=number(data, "geometry", "radius_m"),
        max_linear_m_s=number(data, "limits", "max_linear_m_s"),
        max_angular_rad_s=math.radians(number(data, "limits", "max_angular_deg_s")),
        linear_accel_m_s2=number(data, "limits", "linear_accel_m_s2"),
        angular_accel_rad_s2=math.radians(number(data, "limits", "angular_accel_deg_s2")),
        **timing, bump_stall=int(bump_stall), source=path)

"""Angles in radians, counter-clockwise from +x."""

from __future__ import annotations

import math

import numpy as np


def wrap_angle(theta_rad: float) -> float:
    """Wrap an angle to [-π, π)."""
    wrapped = (theta_rad + math.pi) % (2.0 * math.pi) - math.pi
    return wrapped


def wrap_angles(theta_rad: np.ndarray) -> np.ndarray:
    """Vectorised :func:`wrap_angle`."""
    return (np.asarray(theta_rad, dtype=float) + np.pi) % (2.0 * np.pi) - np.pi


def angle_difference(a_rad: float, b_rad: float) -> float:
    """Signed smallest difference ``a - b``, in [-π, π)."""
    return wrap_angle(a_rad - b_rad)


def angles_close(a_rad: float, b_rad: float, tolerance_rad: float = 1e-6) -> bool:
    """Whether two angles agree modulo 2π within ``tolerance_rad``."""
    return abs(angle_difference(a_rad, b_rad)) <= tolerance_rad

"""The robot's hardware description: the YAML files of the repository's ``hardware/`` folder.

``hardware/p3dx.yaml`` (the base: conversion factors, geometry, limits, timing) and
``hardware/kinect.yaml`` (the depth camera: intrinsics, mount, tilt motor) are the one home of
these numbers; the P3-DX driver, the Kinect adapter and the tests read them here. The folder is
``$ASSISTANT_HARDWARE`` when set (a robot with its own calibration), else the ``hardware/``
folder of the source checkout this package runs from.
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any

import yaml

from assistant.errors import DataFileError
from assistant.fileio import read_yaml
from assistant.robot.frames import CameraIntrinsics, CameraMount

__all__ = ["hardware_dir", "kinect_intrinsics", "kinect_mount", "load_hardware_file", "number"]

ENV_VAR = "ASSISTANT_HARDWARE"


def hardware_dir() -> Path:
    """The folder holding ``p3dx.yaml`` and ``kinect.yaml`` (see the module docstring)."""
    override = os.environ.get(ENV_VAR)
    if override:
        return Path(override).expanduser()
    return Path(__file__).resolve().parents[2] / "hardware"


def load_hardware_file(name: str, folder: str | os.PathLike[str] | None = None) -> dict[str, Any]:
    """The mapping in ``<hardware folder>/<name>`` (e.g. ``"p3dx.yaml"``).

    Raises :class:`~assistant.errors.DataFileError` naming the file when it is missing, not
    YAML, or not a mapping.
    """
    path = Path(folder) / name if folder is not None else hardware_dir() / name
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise DataFileError(str(path), "", f"missing; set ${ENV_VAR} to the folder holding {name} "
                                           "or run from a source checkout") from None
    except OSError as error:
        raise DataFileError(str(path), "", f"cannot read: {error.strerror}") from error
    try:
        data = read_yaml(text)
    except yaml.YAMLError as error:
        raise DataFileError(str(path), "", f"not valid YAML: {error}") from error
    if not isinstance(data, dict):
        raise DataFileError(str(path), "", "expected a mapping at the top level")
    data["__path__"] = str(path)
    return data


def number(data: dict[str, Any], section: str, key: str, *, positive: bool = True) -> float:
    """``data[section][key]`` as a finite float (positive unless told), or a DataFileError."""
    path = data.get("__path__", "hardware file")
    block = data.get(section)
    if not isinstance(block, dict):
        raise DataFileError(path, section, "missing section (expected a mapping)")
    if key not in block:
        raise DataFileError(path, f"{section}.{key}", "missing")
    value = block[key]
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise DataFileError(path, f"{section}.{key}", f"expected a number, got {value!r}")
    if positive and value <= 0:
        raise DataFileError(path, f"{section}.{key}", f"expected a positive number, got {value}")
    return float(value)


def kinect_intrinsics(folder: str | os.PathLike[str] | None = None) -> CameraIntrinsics:
    """The Kinect depth camera's intrinsics from ``kinect.yaml``."""
    data = load_hardware_file("kinect.yaml", folder)
    size = {k: number(data, "depth", k) for k in ("width", "height")}
    for key, value in size.items():
        if value != int(value):
            raise DataFileError(data["__path__"], f"depth.{key}", f"expected whole pixels, got {value}")
    return CameraIntrinsics(int(size["width"]), int(size["height"]),
                            *(number(data, "depth", k) for k in ("fx", "fy", "cx", "cy")))


def kinect_mount(folder: str | os.PathLike[str] | None = None) -> CameraMount:
    """Where the Kinect sits on the base (height, forward offset, tilt) from ``kinect.yaml``."""
    data = load_hardware_file("kinect.yaml", folder)
    return CameraMount(height_m=number(data, "mount", "height_m"),
                       tilt_rad=math.radians(number(data, "mount", "tilt_deg", positive=False)),
                       forward_m=number(data, "mount", "forward_m", positive=False))

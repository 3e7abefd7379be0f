"""Read a depth image from disk (16-bit PNG) into a :class:`DepthFrame`."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np

from assistant.errors import AssistantError
from assistant.fileio import check_readable_file
from assistant.robot.frames import CameraIntrinsics, CameraMount, DepthFrame

#: largest depth image read, in pixels (a Kinect frame has 0.3 million; 4096 × 4096 = 16.8 million)
MAX_PIXELS = 4096 * 4096
#: image modes that hold 16-bit (or wider) integer depth; 8-bit grey ("L") is a picture, not depth
DEPTH_MODES = ("I;16", "I;16B", "I;16L", "I;16N", "I")
#: the camera mount values accepted (metres above the floor, degrees of pitch down)
CAMERA_HEIGHT_RANGE_M = (0.05, 3.0)
TILT_RANGE_DEG = (-90.0, 90.0)


def check_mount(camera_height_m: float | None, tilt_deg: float | None) -> None:
    """Refuse a camera height or tilt that is not a finite number in its range."""
    for name, value, (low, high), unit in (("--camera-height", camera_height_m, CAMERA_HEIGHT_RANGE_M, "m"),
                                           ("--tilt", tilt_deg, TILT_RANGE_DEG, "degrees")):
        if value is None:
            continue
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
                or not low <= value <= high:
            raise AssistantError(f"{name} must be a number from {low:g} to {high:g} {unit}, got {value!r}")


def _read_depth_pixels(image, file: Path) -> np.ndarray:
    """The pixels of an opened image, after checking its size and mode from the header."""
    with image as im:
        width, height = im.size
        if width * height > MAX_PIXELS:
            raise AssistantError(f"{file}: {width}×{height} pixels is more than a depth camera "
                                 f"gives (at most {MAX_PIXELS:,} pixels); give a depth frame")
        if im.mode not in DEPTH_MODES:
            raise AssistantError(f"{file}: a {im.mode!r} image is not depth; give a 16-bit "
                                 "single-channel PNG (depth units, 0 for no reading)")
        return np.asarray(im)


_V1 = CameraIntrinsics.kinect_v1()
#: nominal pinhole intrinsics (fx, fy, cx, cy; pixels) of the common depth cameras, by frame size
NOMINAL_INTRINSICS = {(_V1.width, _V1.height): (_V1.fx, _V1.fy, _V1.cx, _V1.cy),   # Kinect v1, Xtion (NYU, TUM)
                      (512, 424): (365.0, 365.0, 255.5, 211.5),   # Kinect v2
                      (730, 530): (529.5, 529.5, 364.0, 264.0)}   # Kinect v2 as SUN RGB-D crops it
#: the median depth (metres) a room seen by a depth camera has; outside it the scale is wrong
PLAUSIBLE_MEDIAN_M = (0.3, 10.0)


def nominal_intrinsics(width: int, height: int) -> tuple[float, float, float, float]:
    """A Kinect's nominal intrinsics for a ``width`` × ``height`` frame: the table's, or a
    Kinect v1's 63° field of view scaled to the width, centred."""
    if (width, height) in NOMINAL_INTRINSICS:
        return NOMINAL_INTRINSICS[(width, height)]
    f = _V1.fx * width / _V1.width
    return f, f, (width - 1) / 2.0, (height - 1) / 2.0


def guess_depth_scale(median_units: float, width: int, height: int) -> tuple[float, str]:
    """(metres per unit, what it assumes) for a frame whose valid readings have the median
    ``median_units``: millimetres when that makes a room-sized median (the usual 16-bit
    encoding), else a Kinect v2's 0.1 mm for a 512×424 frame or TUM's 1/5000 m."""
    if median_units * 1e-3 <= 6.0:
        return 1e-3, "millimetres"
    if (width, height) == (512, 424):
        return 1e-4, "0.1 mm (a Kinect v2's encoding)"
    return 2e-4, "1/5000 m (the TUM RGB-D encoding)"


def load_depth_png(path: str | Path, intrinsics: tuple[float, float, float, float] | None,
                   depth_scale: float | None, *, camera_height_m: float | None = None,
                   tilt_deg: float | None = None, invalid_values: tuple[int, ...] = (65535,),
                   notes: list[str] | None = None) -> tuple[DepthFrame, bool]:
    """Load a 16-bit depth PNG.

    ``intrinsics`` is ``(fx, fy, cx, cy)`` in 0-based pixels; ``depth_scale`` the metres per
    unit (1e-3 for millimetres, 1e-4 for Kinect v2 0.1 mm, 2e-4 for TUM's 1/5000). Either may
    be None: then :func:`nominal_intrinsics` and :func:`guess_depth_scale` stand in, and what was
    assumed is appended to ``notes``. A scale that puts the median reading outside
    :data:`PLAUSIBLE_MEDIAN_M` is refused with the scale that would fit.
    Returns the frame and whether a mount (height *and* tilt) was given; without one the floor
    is searched for rather than predicted.
    """
    from PIL import Image, UnidentifiedImageError

    check_mount(camera_height_m, tilt_deg)
    file = Path(path)
    try:
        check_readable_file(file, "depth PNG file")  # a named pipe nobody writes to waited for ever
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", Image.DecompressionBombWarning)  # refused below, by our bound
            raw = _read_depth_pixels(Image.open(file), file)
    except FileNotFoundError:
        raise AssistantError(f"{file}: no such depth image") from None
    except IsADirectoryError:
        raise AssistantError(f"{file} is a folder; give a depth PNG file") from None
    except Image.DecompressionBombError as error:
        raise AssistantError(f"{file}: refused, too many pixels for a depth frame ({error})") from None
    except (UnidentifiedImageError, OSError, ValueError, SyntaxError) as error:
        raise AssistantError(f"{file}: not a readable image ({error.strerror or error if isinstance(error, OSError) else error})") from None
    if raw.ndim != 2:
        raise AssistantError(f"{file}: expected a single-channel (16-bit) depth image, "
                             f"got shape {raw.shape}")
    h, w = raw.shape
    readings = raw[(raw > 0) & ~np.isin(raw, invalid_values)]
    median_units = float(np.median(readings)) if readings.size else 0.0
    if depth_scale is None:
        depth_scale, unit = guess_depth_scale(median_units, w, h)
        if notes is not None:
            notes.append(f"no --depth-scale given: the readings taken as {unit} (--depth-scale {depth_scale:g}); "
                         "give --depth-scale for your camera")
    if not (0 < depth_scale <= 1):  # (1e300 overflowed into warnings and an empty frame)
        raise AssistantError(f"--depth-scale must be a positive number of metres per unit, at most 1 "
                             f"(0.001 for millimetres), got {depth_scale}")
    median_m = median_units * depth_scale
    if readings.size and not PLAUSIBLE_MEDIAN_M[0] <= median_m <= PLAUSIBLE_MEDIAN_M[1]:
        fit, unit = guess_depth_scale(median_units, w, h)
        raise AssistantError(f"{file}: with --depth-scale {depth_scale:g} the readings' median would be "
                             f"{median_m:,.2f} m, not a room; the median reading is {median_units:,.0f} units — "
                             f"try --depth-scale {fit:g} ({unit})")
    if intrinsics is None:
        intrinsics = nominal_intrinsics(w, h)
        if notes is not None:
            notes.append(f"no --intrinsics given: assuming a Kinect's for {w}×{h} "
                         f"(--intrinsics {','.join(f'{v:g}' for v in intrinsics)}); give yours for exact positions")
    fx, fy, cx, cy = intrinsics
    if not (fx > 0 and fy > 0):
        raise AssistantError(f"--intrinsics: focal lengths must be positive, got fx={fx}, fy={fy}")
    depth = raw.astype(np.float32)
    for value in invalid_values:
        depth[raw == value] = 0.0
    depth *= np.float32(depth_scale)
    k = CameraIntrinsics(w, h, float(fx), float(fy), float(cx), float(cy))
    has_mount = camera_height_m is not None and tilt_deg is not None
    mount = CameraMount(height_m=camera_height_m if camera_height_m is not None else 1.05,
                        tilt_rad=math.radians(tilt_deg if tilt_deg is not None else 15.0))
    return DepthFrame(depth, k, mount), has_mount

"""Read a depth image from disk into a :class:`DepthFrame`: a 16-bit PNG or TIFF (depth units),
a 32-bit float TIFF (metres, or millimetres when its readings say so), or a NumPy ``.npy``
array of either; SUN RGB-D's bit-rotated millimetres are recognised and decoded."""

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
#: image modes that hold 16-bit (or wider) integer depth, or 32-bit float depth ("F"); 8-bit
#: grey ("L") is a picture, not depth
DEPTH_MODES = ("I;16", "I;16B", "I;16L", "I;16N", "I", "F")
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
            kind = {"L": "an 8-bit grey picture", "P": "a palette (colour-mapped) picture",
                    "RGB": "a colour picture", "RGBA": "a colour picture", "1": "a black-and-white picture"
                    }.get(im.mode, f"a {im.mode!r} image")
            raise AssistantError(f"{file}: {kind}, not depth; give a 16-bit single-channel PNG "
                                 "(depth units, 0 for no reading), a 32-bit float TIFF or a .npy array")
        return np.asarray(im)


def _read_npy(file: Path) -> np.ndarray:
    """A NumPy ``.npy`` depth array (no pickled objects), its size checked as an image's."""
    try:
        array = np.load(file, allow_pickle=False, mmap_mode="r")
    except ValueError as error:
        raise AssistantError(f"{file}: not a plain NumPy depth array ({error})") from None
    if array.ndim == 2 and array.shape[0] * array.shape[1] > MAX_PIXELS:
        raise AssistantError(f"{file}: {array.shape[1]}×{array.shape[0]} values is more than a depth "
                             f"camera gives (at most {MAX_PIXELS:,} pixels); give a depth frame")
    if array.dtype.kind not in "uif":
        raise AssistantError(f"{file}: a {array.dtype} array is not depth; give numbers (depth "
                             "units or metres)")
    return np.array(array)


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


def guess_depth_scale(median_units: float, width: int, height: int, *, floating: bool = False
                      ) -> tuple[float, str]:
    """(metres per unit, what it assumes) for a frame whose valid readings have the median
    ``median_units``: for a floating-point image metres when that makes a room-sized median
    (the usual float encoding), else millimetres; for integers millimetres when that makes a
    room-sized median (the usual 16-bit encoding), else a Kinect v2's 0.1 mm for a 512×424 frame
    or TUM's 1/5000 m."""
    if floating:
        if median_units <= PLAUSIBLE_MEDIAN_M[1]:
            return 1.0, "metres (a floating-point image)"
        return 1e-3, "millimetres (a floating-point image)"
    if median_units * 1e-3 <= 6.0:
        return 1e-3, "millimetres"
    if (width, height) == (512, 424):
        return 1e-4, "0.1 mm (a Kinect v2's encoding)"
    return 2e-4, "1/5000 m (the TUM RGB-D encoding)"


def sun_rgbd_rotated(readings: np.ndarray) -> bool:
    """Whether integer readings look like SUN RGB-D's raw depth: millimetres rotated left by 3
    bits (``(mm << 3) | (mm >> 13)``), so every reading nearer than 8.19 m is a multiple of 8
    and read as millimetres the room would be 8 times too deep. Asked only when millimetres
    give no room: at least 90 % of at least 100 readings multiples of 8 (a camera's own
    millimetres have an eighth of them; readings beyond 8.19 m wrap round and are not)."""
    return readings.size >= 100 and float(np.mean(readings.astype(np.int64) % 8 == 0)) >= 0.9


def unrotate_sun_rgbd(raw: np.ndarray) -> np.ndarray:
    """SUN RGB-D's raw 16-bit depth → millimetres (its toolbox's ``bitor(bitshift(d, -3),
    bitshift(d, 16 - 3))``)."""
    r = raw.astype(np.uint32)
    return ((r >> 3) | (r << 13)) & 0xFFFF


def load_depth_png(path: str | Path, intrinsics: tuple[float, float, float, float] | None,
                   depth_scale: float | None, *, camera_height_m: float | None = None,
                   tilt_deg: float | None = None, invalid_values: tuple[int, ...] = (65535,),
                   notes: list[str] | None = None) -> tuple[DepthFrame, bool]:
    """Load a depth image: a 16-bit PNG or TIFF, a 32-bit float TIFF, or a ``.npy`` array.

    ``intrinsics`` is ``(fx, fy, cx, cy)`` in 0-based pixels; ``depth_scale`` the metres per
    unit (1e-3 for millimetres, 1e-4 for Kinect v2 0.1 mm, 2e-4 for TUM's 1/5000, 1 for a float
    image in metres). Either may be None: then :func:`nominal_intrinsics` and
    :func:`guess_depth_scale` stand in (integer readings that look like SUN RGB-D's bit-rotated
    millimetres, :func:`sun_rgbd_rotated`, are decoded), and what was assumed is appended to
    ``notes``. A scale that puts the median reading outside :data:`PLAUSIBLE_MEDIAN_M` is refused
    with the scale that would fit. ``camera_height_m`` and ``tilt_deg`` go together.
    Returns the frame and whether a mount (height *and* tilt) was given; without one the floor
    is searched for rather than predicted.
    """
    from PIL import Image, UnidentifiedImageError

    check_mount(camera_height_m, tilt_deg)
    if (camera_height_m is None) != (tilt_deg is None):
        raise AssistantError("--camera-height and --tilt go together (the floor is predicted from "
                             "both); give both, or neither to have the floor searched for")
    file = Path(path)
    try:
        check_readable_file(file, "depth image file")  # a named pipe nobody writes to waited for ever
        if file.suffix.lower() == ".npy":
            raw = _read_npy(file)
        else:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", Image.DecompressionBombWarning)  # refused below, by our bound
                raw = _read_depth_pixels(Image.open(file), file)
    except FileNotFoundError:
        raise AssistantError(f"{file}: no such depth image") from None
    except IsADirectoryError:
        raise AssistantError(f"{file} is a folder; give a depth image file") from None
    except Image.DecompressionBombError as error:
        raise AssistantError(f"{file}: refused, too many pixels for a depth frame ({error})") from None
    except (UnidentifiedImageError, OSError, ValueError, SyntaxError) as error:
        raise AssistantError(f"{file}: not a readable image ({error.strerror or error if isinstance(error, OSError) else error}); "
                             "give a 16-bit PNG, a float TIFF or a .npy array") from None
    if raw.ndim != 2:
        raise AssistantError(f"{file}: expected a single-channel depth image, got shape {raw.shape}"
                             + (" (a colour or RGB-D image? give its depth channel alone)" if raw.ndim == 3 else ""))
    h, w = raw.shape
    floating = raw.dtype.kind == "f"
    if floating:
        raw = np.where(np.isfinite(raw), raw, 0.0)  # NaN and inf: no reading
        readings = raw[raw > 0]
    else:
        readings = raw[(raw > 0) & ~np.isin(raw, invalid_values)]
    median_units = float(np.median(readings)) if readings.size else 0.0
    if depth_scale is None:
        depth_scale, unit = guess_depth_scale(median_units, w, h, floating=floating)
        if not floating and depth_scale != 1e-3 and sun_rgbd_rotated(readings):
            raw = np.where(np.isin(raw, invalid_values), raw, unrotate_sun_rgbd(raw))
            readings = raw[(raw > 0) & ~np.isin(raw, invalid_values)]
            median_units = float(np.median(readings))
            depth_scale, unit = 1e-3, "SUN RGB-D's bit-rotated millimetres, decoded"
        if notes is not None:
            notes.append(f"no --depth-scale given: the readings taken as {unit} (--depth-scale {depth_scale:g}); "
                         "give --depth-scale for your camera")
    if not (0 < depth_scale <= 1):  # (1e300 overflowed into warnings and an empty frame)
        raise AssistantError(f"--depth-scale must be a positive number of metres per unit, at most 1 "
                             f"(0.001 for millimetres), got {depth_scale}")
    median_m = median_units * depth_scale
    if readings.size and not PLAUSIBLE_MEDIAN_M[0] <= median_m <= PLAUSIBLE_MEDIAN_M[1]:
        fit, unit = guess_depth_scale(median_units, w, h, floating=floating)
        if not floating and sun_rgbd_rotated(readings) and median_units * 1e-3 > 6.0:
            hint = "the readings look like SUN RGB-D's bit-rotated millimetres: leave out --depth-scale to decode them"
        elif fit != depth_scale and PLAUSIBLE_MEDIAN_M[0] <= median_units * fit <= PLAUSIBLE_MEDIAN_M[1]:
            hint = f"try --depth-scale {fit:g} ({unit})"
        else:
            hint = ("no common depth encoding makes a room of it — check how the file was saved (depth "
                    "in whole metres or decimetres has lost its detail: save millimetres, or metres as floats)")
        raise AssistantError(f"{file}: with --depth-scale {depth_scale:g} the readings' median would be "
                             f"{median_m:,.2f} m, not a room; the median reading is {median_units:,.4g} units — {hint}")
    if intrinsics is None:
        intrinsics = nominal_intrinsics(w, h)
        if notes is not None:
            notes.append(f"no --intrinsics given: assuming a Kinect's for {w}×{h} "
                         f"(--intrinsics {','.join(f'{v:g}' for v in intrinsics)}); give yours for exact positions")
    fx, fy, cx, cy = intrinsics
    if not (fx > 0 and fy > 0):
        raise AssistantError(f"--intrinsics: focal lengths must be positive, got fx={fx}, fy={fy}")
    if not (-0.5 * w <= cx <= 1.5 * w and -0.5 * h <= cy <= 1.5 * h):
        raise AssistantError(f"--intrinsics: the principal point ({cx:g}, {cy:g}) lies far outside the "
                             f"{w}×{h} image; give it in pixels (about {w / 2:g}, {h / 2:g})")
    if not 0.2 * w <= fx <= 5.0 * w:
        raise AssistantError(f"--intrinsics: a focal length of {fx:g} pixels for a {w}-pixel-wide image is a "
                             f"field of view no depth camera has; give it in pixels (a Kinect's is about {0.82 * w:.0f})")
    depth = raw.astype(np.float32)
    if not floating:
        for value in invalid_values:
            depth[raw == value] = 0.0
    depth *= np.float32(depth_scale)
    k = CameraIntrinsics(w, h, float(fx), float(fy), float(cx), float(cy))
    has_mount = camera_height_m is not None and tilt_deg is not None
    mount = CameraMount(height_m=camera_height_m if camera_height_m is not None else 1.05,
                        tilt_rad=math.radians(tilt_deg if tilt_deg is not None else 15.0))
    return DepthFrame(depth, k, mount), has_mount

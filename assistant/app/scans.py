"""Scans a person can open and look at: recordings of the robot and depth images.

The scan explorer (``notebooks/explore_scans.ipynb``) lists :func:`scan_sources` — the
recordings of a folder (``sample_scans/``) and the real depth frames of a realdata folder
(``../shared/realdata``, read in place, never copied) — and opens any file a person names with
:func:`scan_source`. :func:`open_scan` reads a source's frames and :func:`analyse_scan` runs the
detector on one the right way: a recording's frames carry the robot's pose and the camera's
mount (the floor is predicted from it); a depth image has neither (the floor is searched for,
and positions are in the camera-floor frame).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from assistant.errors import AssistantError

__all__ = ["ScanSource", "analyse_scan", "open_scan", "scan_source", "scan_sources"]

#: metres per unit of a depth PNG nobody says otherwise of (millimetres, as the Kinect v1 and
#: ``assistant sim render`` write)
DEFAULT_DEPTH_SCALE_M = 1e-3


@dataclass(frozen=True)
class ScanSource:
    """A file to explore: ``kind`` "recording" (MCAP) or "depth" (a 16-bit PNG, read with
    ``intrinsics`` (fx, fy, cx, cy), ``depth_scale_m`` metres per unit, ``invalid`` raw values
    and readings nearer than ``min_depth_m`` dropped); ``label`` names it in a list."""

    label: str
    path: Path
    kind: str
    intrinsics: tuple[float, float, float, float] | None = None
    depth_scale_m: float = DEFAULT_DEPTH_SCALE_M
    invalid: tuple[int, ...] = (65535,)
    min_depth_m: float = 0.0

    @property
    def use_mount(self) -> bool:
        """Whether the camera's height and tilt are known (a recording) or searched for."""
        return self.kind == "recording"

    def spec(self) -> dict:
        return {"intrinsics": self.intrinsics, "depth_scale_m": self.depth_scale_m,
                "invalid": self.invalid, "min_depth_m": self.min_depth_m}


def scan_sources(scans_dir: str | Path, realdata: str | Path | None = None) -> list[ScanSource]:
    """The recordings (``*.mcap``) of ``scans_dir``, then every real depth frame of
    ``realdata`` that :func:`~assistant.perception.realdata.real_folders` can read (none when
    it is None or absent)."""
    from assistant.perception.realdata import real_folders

    out = [ScanSource(f"recording {p.name}", p, "recording") for p in sorted(Path(scans_dir).glob("*.mcap"))]
    if realdata is not None and Path(realdata).is_dir():
        for folder, spec in real_folders(realdata).items():
            for name in spec["frames"]:
                path = spec["path"] / name
                if path.exists():
                    out.append(ScanSource(f"real {folder}/{name}", path, "depth", tuple(spec["intrinsics"]),
                                          spec["depth_scale_m"], tuple(spec["invalid"]), spec["min_depth_m"]))
    return out


def scan_source(path: str | Path, intrinsics: tuple[float, float, float, float] | None = None,
                depth_scale_m: float | None = None) -> ScanSource:
    """The source of a file a person names: a recording (``.mcap``) or a depth PNG. A PNG in a
    folder of real frames (:func:`~assistant.perception.realdata.folder_spec`) is read as its
    folder says unless ``intrinsics`` / ``depth_scale_m`` are given; any other PNG with the
    Kinect's intrinsics (``hardware/kinect.yaml``) and millimetres by default.
    AssistantError, in one line, for a missing file or another kind of file."""
    from assistant.perception.realdata import folder_spec

    file = Path(path).expanduser()
    if not file.is_file():
        raise AssistantError(f"{file}: no such file; give a recording (.mcap) or a depth PNG")
    if file.suffix.lower() == ".mcap":
        return ScanSource(f"recording {file.name}", file, "recording")
    if file.suffix.lower() != ".png":
        raise AssistantError(f"{file}: not a recording (.mcap) or a depth image (.png)")
    spec = folder_spec(file.parent) or {}
    if intrinsics is None:
        intrinsics = tuple(spec["intrinsics"]) if spec else _kinect_intrinsics()
    if depth_scale_m is None:
        depth_scale_m = spec.get("depth_scale_m", DEFAULT_DEPTH_SCALE_M)
    return ScanSource(f"depth {file.name}", file, "depth", tuple(float(v) for v in intrinsics),
                      float(depth_scale_m), tuple(spec.get("invalid", (65535,))), spec.get("min_depth_m", 0.0))


def _kinect_intrinsics() -> tuple[float, float, float, float]:
    from assistant.robot.hardware import kinect_intrinsics

    k = kinect_intrinsics()
    return (k.fx, k.fy, k.cx, k.cy)


def open_scan(source: ScanSource, limit: int = 40) -> list:
    """The first ``limit`` depth frames of a recording, or the one frame of a depth image
    (:class:`~assistant.robot.frames.DepthFrame`)."""
    if source.kind == "recording":
        from assistant.robot.replay import ReplayRobot

        frames = []
        with ReplayRobot(source.path, on_end="hold") as robot:
            for frame in robot.frames():
                frames.append(frame)
                if len(frames) >= limit:
                    break
        if not frames:
            raise AssistantError(f"{source.path}: the recording holds no depth frames")
        return frames
    from assistant.perception.realdata import load_real_frame

    return [load_real_frame(source.path, source.spec())]


def analyse_scan(detector, source: ScanSource, frame):
    """The detector's :class:`~assistant.perception.detector.DetectionResult` of one frame of
    ``source``: the floor predicted from the mount of a recording, searched for in an image."""
    return detector.analyse(frame, use_mount=source.use_mount)

"""Which reader a recording needs: :func:`open_source` looks at the path."""

from __future__ import annotations

import os
from pathlib import Path

from assistant.robot.recording.foreign import BagSource, TumSource
from assistant.robot.recording.reader import Event, McapSource, RecordingError

__all__ = ["open_source", "read_events"]


def open_source(path: str | os.PathLike[str], **options):
    """The reader for ``path``: an ``.mcap`` file, a ROS 1 ``.bag``, a ROS 2 bag folder
    (``metadata.yaml``) or a TUM RGB-D folder (``depth.txt``)."""
    target = Path(path)
    if target.is_file() and target.suffix.lower() == ".mcap":
        return McapSource(target, depth_topic=options.get("depth_topic"))
    if target.is_dir() and (target / "depth.txt").is_file():
        return TumSource(target, **{k: v for k, v in options.items() if k != "depth_topic"})
    if (target.is_file() and target.suffix.lower() == ".bag") or (target / "metadata.yaml").is_file():
        return BagSource(target, **options)
    if not target.exists():
        raise RecordingError(f"no recording at {target}; give the path of an .mcap file, a ROS bag or a "
                             "TUM RGB-D folder")
    raise RecordingError(f"{target} is not a recording this product reads: an .mcap file, a ROS 1 .bag, a "
                         "ROS 2 bag folder (with metadata.yaml) or a TUM RGB-D folder (with depth.txt)")


def read_events(path: str | os.PathLike[str], **options) -> list[Event]:
    """Every event of a recording in a list (for tests and small files)."""
    return list(open_source(path, **options).events())

"""What a recording holds, in numbers: :func:`recording_summary`."""

from __future__ import annotations

import os
from collections import Counter
from pathlib import Path

from assistant.robot.recording import messages as msgs
from assistant.robot.recording.sources import open_source

__all__ = ["recording_summary"]


def recording_summary(path: str | os.PathLike[str], **options) -> dict:
    """Counts of frames, odometry readings, commands and dialogue turns, the recorded span
    (seconds), the size on disk (bytes), whether the file was cut, and its metadata."""
    source = open_source(path, **options)
    counts: Counter = Counter()
    first = last = None
    for event in source.events():
        counts[event.kind] += 1
        first = event.t_ns if first is None else first
        last = event.t_ns
    target = Path(path)
    size = target.stat().st_size if target.is_file() else sum(p.stat().st_size for p in target.rglob("*") if p.is_file())
    return {"path": str(path), "frames": counts["frame"], "odometry": counts["odometry"],
            "commands": counts["command"], "turns": counts["turn"],
            "seconds": 0.0 if first is None else round(msgs.from_ns(last - first), 3),
            "bytes": size, "truncated": bool(source.truncated), "metadata": dict(source.metadata)}

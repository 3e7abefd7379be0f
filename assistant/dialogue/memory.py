"""Object memory: what the robot has seen, where and when, kept in a JSON file.

Every sighting is stored per home (world name) and object name: the furniture it was on (id,
word and a short phrase such as "on the table to the right of the bed"), the room, the
position (metres, world frame), the time (seconds since the epoch) and which task saw it
(``fetch``, ``search``; every object the robot's object detector reports during a task is
recorded, see :mod:`assistant.dialogue.seen`). The file is rewritten atomically (:func:`assistant.fileio.atomic_write_text`)
after every change, so a crash leaves the old or the new memory, never half of one.
"""

from __future__ import annotations

import json
import os
import threading
import time
from dataclasses import asdict, dataclass
from pathlib import Path

from assistant.fileio import atomic_write_text

#: version written into the file; version 1 files (no position) are read too, others refused
MEMORY_VERSION = 2
READABLE_VERSIONS = (1, 2)


@dataclass
class MemoryEntry:
    """What memory holds about one object: where it was last seen (room, furniture, phrase,
    position) and when (``time_s``: seconds since the epoch), by which task (``source``)."""

    object: str
    world: str
    room: str | None
    furniture: str | None = None  # furniture id
    furniture_word: str | None = None  # "table"
    phrase: str | None = None  # "on the table to the right of the bed"
    time_s: float = 0.0
    source: str = "fetch"
    x_m: float | None = None  # where the object was seen (world frame, metres)
    y_m: float | None = None

    def to_dict(self) -> dict:
        return asdict(self)


def default_data_dir() -> Path:
    """Where chat keeps its memory and transcripts: ``$ASSISTANT_DATA`` or
    ``~/.local/share/assistant``."""
    root = os.environ.get("ASSISTANT_DATA") or os.path.join(
        os.environ.get("XDG_DATA_HOME") or os.path.expanduser("~/.local/share"), "assistant")
    return Path(root)


def age_phrase(seconds: float) -> str:
    """``just now``, ``3 minutes ago``, ``2 hours ago``, ``yesterday``, ``4 days ago``."""
    s = max(0.0, float(seconds))
    if s < 45:
        return "just now"
    minutes = round(s / 60)
    if minutes < 60:
        return "a minute ago" if minutes <= 1 else f"{minutes} minutes ago"
    hours = round(s / 3600)
    if hours < 24:
        return "an hour ago" if hours <= 1 else f"{hours} hours ago"
    days = round(s / 86400)
    return "yesterday" if days <= 1 else f"{days} days ago"


class ObjectMemory:
    """Sightings by (world, object), persisted to ``path`` (None: kept in memory only).

    A missing file starts an empty memory; an unreadable one too, with the problem kept in
    :attr:`load_problem` (the chat says it) — the robot keeps working.
    """

    def __init__(self, path: str | os.PathLike[str] | None = None, clock=time.time):
        self.path = None if path is None else Path(path)
        self.clock = clock
        self.load_problem: str | None = None
        self._items: dict[tuple[str, str], MemoryEntry] = {}
        self._lock = threading.Lock()
        if self.path is not None and self.path.exists():
            self._load()

    def _load(self) -> None:
        try:
            data = json.loads(self.path.read_text(encoding="utf-8"))
            if not isinstance(data, dict) or data.get("version") not in READABLE_VERSIONS:
                raise ValueError(f"expected an object with version {MEMORY_VERSION}")
            sightings = data.get("sightings", [])
            if not isinstance(sightings, list):
                raise ValueError("sightings: expected a list")
            for i, item in enumerate(sightings):
                try:
                    s = MemoryEntry(**item)
                    s.time_s = float(s.time_s)
                    s.x_m = None if s.x_m is None else float(s.x_m)
                    s.y_m = None if s.y_m is None else float(s.y_m)
                except (TypeError, ValueError) as error:
                    raise ValueError(f"sightings[{i}]: {error}") from None
                self._items[(s.world, s.object)] = s
        except (OSError, ValueError) as error:  # json.JSONDecodeError is a ValueError
            self._items.clear()
            kept = self._keep_unreadable()
            self.load_problem = (f"{self.path}: {error}; starting with an empty memory"
                                 + (f" (the unreadable file is kept as {kept})" if kept else ""))

    def _keep_unreadable(self) -> Path | None:
        """Move an unreadable memory file aside, so the next save does not overwrite what it
        held (``NAME.unreadable-<time>``); None when it cannot be moved."""
        target = self.path.with_name(f"{self.path.name}.unreadable-{int(self.clock())}")
        n = 1
        while target.exists():  # never over an earlier one
            target = self.path.with_name(f"{self.path.name}.unreadable-{int(self.clock())}-{n}")
            n += 1
        try:
            os.replace(self.path, target)
        except OSError:
            return None
        return target

    def save(self) -> None:
        if self.path is None:
            return
        with self._lock:
            items = [s.to_dict() for s in sorted(self._items.values(), key=lambda s: (s.world, s.object))]
        atomic_write_text(self.path, json.dumps({"version": MEMORY_VERSION, "sightings": items}, indent=1) + "\n")

    def remember(self, world: str, name: str, room: str | None, furniture: str | None = None,
                 furniture_word: str | None = None, phrase: str | None = None,
                 time_s: float | None = None, source: str = "fetch", x_m: float | None = None,
                 y_m: float | None = None, save: bool = True) -> MemoryEntry:
        """Store (or replace) where ``name`` was seen, and save (unless ``save`` is False:
        several changes, then one :meth:`save`)."""
        s = MemoryEntry(name, world, room, furniture, furniture_word, phrase,
                     self.clock() if time_s is None else float(time_s), source,
                     None if x_m is None else round(float(x_m), 3), None if y_m is None else round(float(y_m), 3))
        with self._lock:
            self._items[(world, name)] = s
        if save:
            self.save()
        return s

    def recall(self, world: str, name: str) -> MemoryEntry | None:
        with self._lock:
            return self._items.get((world, name))

    def forget(self, world: str, name: str) -> None:
        with self._lock:
            self._items.pop((world, name), None)
        self.save()

    def sightings(self, world: str | None = None) -> list[MemoryEntry]:
        with self._lock:
            return [s for s in self._items.values() if world is None or s.world == world]

    def age(self, sighting: MemoryEntry) -> str:
        return age_phrase(self.clock() - sighting.time_s)

"""Object memory: what the robot has seen, where and when, kept in a JSON file.

Every sighting is stored per home (world name) and object name: the furniture it was on (id,
word and a short phrase such as "on the table to the right of the bed"), the room, the
position (metres, world frame), the time (seconds since the epoch) and which task saw it
(``fetch``, ``search``; every object the robot's object detector reports during a task is
recorded, see :mod:`assistant.dialogue.seen`). The file is rewritten atomically (:func:`assistant.fileio.atomic_write_text`)
after every change, so a crash leaves the old or the new memory, never half of one; it is
readable by its owner only. Several sessions may share one file: each save happens under the
file's lock and first re-reads the file, keeping the newest sighting of every object (and the
other session's forgetting), so no session loses another's update. A malformed entry is
reported and skipped; a copy of the file as it was is kept beside it.
"""

from __future__ import annotations

import datetime as _dt
import json
import math
import os
import shutil
import threading
import time
from dataclasses import asdict, dataclass, fields
from pathlib import Path

from assistant.fileio import PRIVATE_FILE_MODE, atomic_write_text, file_lock, private_dir

#: version written into the file; version 1 files (no position) are read too, others refused
MEMORY_VERSION = 2
READABLE_VERSIONS = (1, 2)


#: where a remembered place came from, besides what the robot saw it in ("fetch", "search"): the
#: person said so, or the person said so and the robot then looked there and did not see it
TOLD = "told"
TOLD_NOT_SEEN = "told, not seen"


@dataclass
class MemoryEntry:
    """One remembered object: ``time_s`` is seconds since the epoch; ``source`` where the place
    came from (:data:`TOLD`, :data:`TOLD_NOT_SEEN`, or what the robot saw it in)."""

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

    @property
    def told(self) -> bool:
        """Whether the place is one the person said (seen there by the robot or not)."""
        return self.source in (TOLD, TOLD_NOT_SEEN)

    def to_dict(self) -> dict:
        return asdict(self)

    @classmethod
    def from_dict(cls, item) -> "MemoryEntry":
        """A sighting read from a memory file; ValueError names the first bad field."""
        if not isinstance(item, dict):
            raise ValueError(f"expected an object, got {type(item).__name__}")
        known = {f.name for f in fields(cls)}
        if unknown := sorted(set(item) - known):
            raise ValueError(f"unknown field {unknown[0]!r}")
        for key in ("object", "world"):
            if not isinstance(item.get(key), str) or not item[key].strip():
                raise ValueError(f"{key}: expected a non-empty string, got {item.get(key)!r}")
        for key in ("room", "furniture", "furniture_word", "phrase"):
            if item.get(key) is not None and not isinstance(item[key], str):
                raise ValueError(f"{key}: expected a string or null, got {item[key]!r}")
        if not isinstance(item.get("source", "fetch"), str):
            raise ValueError(f"source: expected a string, got {item['source']!r}")
        for key, optional in (("time_s", False), ("x_m", True), ("y_m", True)):
            value = item.get(key, None if optional else 0.0)
            if value is None and optional:
                continue
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
                    or abs(value) > (1e11 if key == "time_s" else 1e4):
                raise ValueError(f"{key}: expected a number in range, got {value!r}")
        out = cls(**item)
        out.time_s = float(out.time_s)
        out.x_m = None if out.x_m is None else float(out.x_m)
        out.y_m = None if out.y_m is None else float(out.y_m)
        return out


def default_data_dir() -> Path:  # the dialogue's name for it
    """Where chat keeps its memory and transcripts: ``$ASSISTANT_DATA`` or
    ``$XDG_DATA_HOME/assistant`` (``~/.local/share/assistant``)."""
    from assistant.fileio import user_data_dir

    return user_data_dir()


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


def earlier_phrase(then_s: float, now_s: float) -> str:
    """When a sighting of an earlier session was made, by the local calendar: ``earlier
    today``, ``yesterday``, ``on 28 November`` (``on 28 November 2025`` in another year)."""
    then = _dt.datetime.fromtimestamp(then_s)
    now = _dt.datetime.fromtimestamp(max(now_s, then_s))
    days = (now.date() - then.date()).days
    if days == 0:
        return "earlier today"
    if days == 1:
        return "yesterday"
    date = f"{then.day} {then:%B}" + ("" if then.year == now.year else f" {then.year}")
    return f"on {date}"


class ObjectMemory:
    """Sightings by (world, object), persisted to ``path`` (None: kept in memory only).

    A missing file starts an empty memory; an unreadable one too, with the problem kept in
    :attr:`load_problem` (the chat says it) — the robot keeps working. Sightings made before
    this object was created (by an earlier session) are dated by :meth:`age` as "earlier
    today" or "on 28 November", those of this session as "3 minutes ago".
    """

    def __init__(self, path: str | os.PathLike[str] | None = None, clock=time.time):
        self.path = None if path is None else Path(path)
        self.clock = clock
        self.session_start_s = float(clock())
        self.load_problem: str | None = None
        self._items: dict[tuple[str, str], MemoryEntry] = {}
        self._forgotten: dict[tuple[str, str], float] = {}  # key -> when this session forgot it
        self._synced: dict[tuple[str, str], float] = {}  # the file as last read or written: key -> time_s
        self._lock = threading.Lock()
        if self.path is not None and self.path.exists() and not self.path.is_file():
            from assistant.errors import AssistantError

            raise AssistantError(f"the memory file {self.path} is a folder (or not a regular file); give a file "
                                 f"name, e.g. --memory {self.path / 'memory.json'}")
        if self.path is not None and self.path.exists():
            self._load()

    def _read_file(self) -> tuple[dict[tuple[str, str], MemoryEntry], list[str]]:
        """The file's sightings and the problems of the entries skipped; ValueError/OSError
        when the file as a whole cannot be read."""
        data = json.loads(self.path.read_text(encoding="utf-8"))
        if not isinstance(data, dict) or data.get("version") not in READABLE_VERSIONS:
            raise ValueError(f"expected an object with version {MEMORY_VERSION}")
        sightings = data.get("sightings", [])
        if not isinstance(sightings, list):
            raise ValueError("sightings: expected a list")
        items: dict[tuple[str, str], MemoryEntry] = {}
        problems: list[str] = []
        for i, item in enumerate(sightings):
            try:
                s = MemoryEntry.from_dict(item)
            except (TypeError, ValueError) as error:
                problems.append(f"sightings[{i}]: {error}")
                continue
            items[(s.world, s.object)] = s
        return items, problems

    def _load(self) -> None:
        try:
            items, problems = self._read_file()
        except (OSError, ValueError, UnicodeDecodeError) as error:  # JSONDecodeError is a ValueError
            kept = self._keep_unreadable(move=True)
            self.load_problem = (f"{self.path}: {error}; starting with an empty memory"
                                 + (f" (the unreadable file is kept as {kept})" if kept else ""))
            return
        self._items = items
        self._synced = {key: s.time_s for key, s in items.items()}
        if problems:
            kept = self._keep_unreadable(move=False)
            more = f" and {len(problems) - 1} more" if len(problems) > 1 else ""
            self.load_problem = (f"{self.path}: skipped {problems[0]}{more}"
                                 + (f"; the file as it was is kept as {kept}" if kept else "")
                                 + "; the other sightings are loaded")

    def _keep_unreadable(self, move: bool) -> Path | None:
        """Move (or copy) an unreadable memory file aside, so the next save does not overwrite
        what it held (``NAME.unreadable-<time>``); None when it cannot be kept. Only a regular
        file is ever moved."""
        if not self.path.is_file():
            return None
        target = self.path.with_name(f"{self.path.name}.unreadable-{int(self.clock())}")
        n = 1
        while target.exists():  # never over an earlier one
            target = self.path.with_name(f"{self.path.name}.unreadable-{int(self.clock())}-{n}")
            n += 1
        try:
            if move:
                os.replace(self.path, target)
            else:
                shutil.copyfile(self.path, target)
                os.chmod(target, PRIVATE_FILE_MODE)
        except OSError:
            return None
        return target

    def save(self) -> None:
        """Write the memory: under the file's lock, re-read it and merge (the newest sighting
        of each object wins; what this session forgot stays forgotten unless seen again
        since; what another session forgot is dropped unless this one saw it since), then
        replace the file atomically."""
        if self.path is None:
            return
        private_dir(self.path.parent)
        with file_lock(self.path):
            try:
                on_disk, _ = self._read_file() if self.path.exists() else ({}, [])
            except (OSError, ValueError, UnicodeDecodeError):
                on_disk = {}  # unreadable now: what this session holds is written
            with self._lock:
                for key, theirs in on_disk.items():
                    ours = self._items.get(key)
                    if key in self._forgotten and theirs.time_s <= self._forgotten[key]:
                        continue
                    if ours is None or theirs.time_s > ours.time_s:
                        self._items[key] = theirs
                for key in [k for k in self._items if k not in on_disk and k in self._synced]:
                    if self._items[key].time_s <= self._synced[key]:  # forgotten elsewhere
                        del self._items[key]
                self._synced = {key: s.time_s for key, s in self._items.items()}
                items = [s.to_dict() for s in sorted(self._items.values(), key=lambda s: (s.world, s.object))]
            atomic_write_text(self.path, json.dumps({"version": MEMORY_VERSION, "sightings": items}, indent=1)
                              + "\n", mode=PRIVATE_FILE_MODE)

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
            self._forgotten.pop((world, name), None)
        if save:
            self.save()
        return s

    def recall(self, world: str, name: str) -> MemoryEntry | None:
        with self._lock:
            return self._items.get((world, name))

    def forget(self, world: str, name: str) -> None:
        with self._lock:
            self._items.pop((world, name), None)
            self._forgotten[(world, name)] = float(self.clock())
        self.save()

    def sightings(self, world: str | None = None) -> list[MemoryEntry]:
        with self._lock:
            return [s for s in self._items.values() if world is None or s.world == world]

    def from_earlier_session(self, sighting: MemoryEntry) -> bool:
        """True when ``sighting`` was made before this memory was opened (another session)."""
        return sighting.time_s < self.session_start_s

    def age(self, sighting: MemoryEntry) -> str:
        """"3 minutes ago" for a sighting of this session; "earlier today", "yesterday" or
        "on 28 November" for one of an earlier session."""
        now = self.clock()
        if self.from_earlier_session(sighting):
            return earlier_phrase(sighting.time_s, now)
        return age_phrase(now - sighting.time_s)

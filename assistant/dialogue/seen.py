"""Remembering every object the robot sees during a task (fetch, search).

Tasks report what their object detector sees as ``objects_seen`` events, ``{"seen":
[Sighting, …], "pose": Pose2D}`` (:mod:`assistant.executor.sightings`): the object's
position, its room (floor plan) and the perceived furniture it lies on. A
:class:`SeenRecorder` turns them into the object memory:

* the first sighting of an object in a task, or one that has moved more than
  :data:`MOVED_M` from the remembered place, is written at once (so a stopped or crashed task
  still leaves what it saw), with the furniture's word as the phrase ("on the table");
* :meth:`SeenRecorder.finish` (end of the task, stopped or not) writes every object's latest
  sighting once more, now with a phrase composed by the generation layer from the furniture the
  robot itself perceived ("on the table against the right wall by the chair"), and says which
  objects were seen and which of them had moved since they were last remembered.

Times are wall-clock seconds since the epoch (the memory's clock), not the simulator's clock.
"""

from __future__ import annotations

import dataclasses
import math
import re
import threading

#: an object seen this far (metres) from where memory had it counts as moved
MOVED_M = 0.75


def category_word(category: str | None) -> str | None:
    """The everyday word for a perceived furniture category ("small table" → "table")."""
    if not category:
        return None
    from assistant.world.catalogue import category_word as word

    return word(category)


class SeenRecorder:
    """Collects one task's ``objects_seen`` events into an :class:`ObjectMemory`.

    ``memory``: the object memory; ``world``: the world name; ``source``: which task
    (``fetch``, ``search``). Thread-safe: events arrive in the task's worker thread.
    """

    def __init__(self, memory, world: str, source: str = "fetch"):
        self.memory = memory
        self.world = world
        self.source = source
        self.latest: dict[str, tuple[object, float, object]] = {}  # name → (placed Sighting, time_s, pose)
        self.before: dict[str, object] = {}  # name → the memory's entry before this task (or None)
        self._lock = threading.Lock()

    # ----------------------------------------------------------------- events
    def on_event(self, name: str, data: dict) -> list[str]:
        """Feed one task event; the names of objects seen for the first time in this task."""
        if name != "objects_seen":
            return []
        return self.add(data.get("seen") or [], data.get("pose"))

    def add(self, seen, pose=None) -> list[str]:
        new = []
        now = self.memory.clock()
        for placed in seen:
            obj = placed.name
            with self._lock:
                first = obj not in self.latest
                if first:
                    self.before[obj] = self.memory.recall(self.world, obj)
                self.latest[obj] = (placed, now, pose)
            if first:
                new.append(obj)
            remembered = self.memory.recall(self.world, obj)
            if first or _moved(remembered, placed):
                word = category_word(placed.furniture_category)
                self.memory.remember(self.world, obj, placed.room, placed.furniture_id, word,
                                     f"on the {word}" if word else None, time_s=now, source=self.source,
                                     x_m=placed.x_m, y_m=placed.y_m)
        return new

    # ----------------------------------------------------------------- end of task
    def finish(self, furniture=None, describer=None, floorplan=None) -> dict:
        """Write every object's latest sighting with a phrase made from ``furniture`` (the
        perceived entities at the end of the task; None: keep the word-only phrase). Returns
        ``{"seen": [names], "moved": [names], "places": {name: memory dict}}`` — ``moved``: objects
        memory had somewhere else (more than :data:`MOVED_M` away, or another room) before."""
        with self._lock:
            latest = dict(self.latest)
        moved, places = [], {}
        words = {e.id: e.name for e in furniture or []}
        for obj, (placed, when, pose) in sorted(latest.items()):
            before = self.before.get(obj)
            if before is not None and _moved(before, placed):
                moved.append(obj)
            word = words.get(placed.furniture_id) or category_word(placed.furniture_category)
            phrase = None
            if furniture is not None and describer is not None and floorplan is not None \
                    and placed.furniture_id is not None:
                phrase = compose_phrase(describer, placed, pose, furniture, floorplan)
            if phrase is None and word and placed.furniture_id is not None:
                phrase = f"on the {word}"
            s = self.memory.remember(self.world, obj, placed.room, placed.furniture_id,
                                     word if placed.furniture_id is not None else None, phrase,
                                     time_s=when, source=self.source, x_m=placed.x_m,
                                     y_m=placed.y_m, save=False)
            places[obj] = s.to_dict()
        if latest:
            self.memory.save()
        return {"seen": sorted(latest), "moved": moved, "places": places}


def _moved(remembered, placed) -> bool:
    """Whether ``placed`` is somewhere else than the memory's ``remembered`` sighting."""
    if remembered is None:
        return False
    if remembered.room is not None and placed.room is not None and remembered.room != placed.room:
        return True
    if remembered.x_m is None or remembered.y_m is None:
        return False
    return math.hypot(remembered.x_m - placed.x_m, remembered.y_m - placed.y_m) > MOVED_M


def compose_phrase(describer, placed, pose, furniture, floorplan) -> str | None:
    """"on the table against the right wall by the chair": the generation layer's description of
    the object among the perceived ``furniture``, for a listener inside its room (so the room is
    not part of the phrase); None when it cannot be composed."""
    from assistant.geometry import Pose2D

    s = placed
    room = placed.room
    listener = None
    if room is not None:
        try:
            c = floorplan.room(room).centre
            listener = Pose2D(float(c[0]), float(c[1]), 0.0)
        except Exception:
            listener = None
    seen_from = pose if pose is not None else Pose2D(s.x_m, s.y_m, 0.0)
    sighting = dataclasses.replace(placed, seen_from=seen_from)
    try:
        result = describer.describe(sighting, list(furniture), floorplan, listener_pose=listener)
    except Exception:  # no furniture under it, etc.: the word-only phrase will do
        return None
    if not getattr(result, "found", True):
        return None
    text = result.description.strip().rstrip(".")
    text = re.sub(rf"^the {re.escape(s.name)} (is|are) ", "", text, flags=re.I)
    if room:
        text = re.sub(rf"^in the {re.escape(room)} ", "", text)
        text = re.sub(rf",? in the {re.escape(room)}$", "", text)
    return text if text.startswith(("on ", "by ", "at ", "near ", "under ", "next ")) else None

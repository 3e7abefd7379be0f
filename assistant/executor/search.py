"""Searching the home for an object, room by room, with the robot's own perception.

The first step of "where is my X?" (dissertation chapter 6; issue item 1): the robot starts
where it stands and explores the rooms of the floor plan — the room it is in first, then
always the nearest room not yet searched (by the door graph, :class:`RoomGraph`) — until its
object detector reports the object.

In each room it

1. enters it (:func:`~assistant.executor.entry.enter_room`, insisting: through the doors, a
   door closed on the map by depth noise cleared and tried again, an open-plan room entered by
   driving to the nearest free spot inside it),
2. looks around on the spot (eight 45° turns with the 57° camera: a full circle),
3. picks the next *vantage point* by greedy coverage: the room's floor is sampled every
   :attr:`SearchTask.sample_m`; a sample counts as covered once a look-around was made
   between :attr:`~SearchTask.view_min_m` and :attr:`~SearchTask.view_max_m` from it with
   the segment between them inside the room; samples on furniture perception has found count
   :attr:`~SearchTask.furniture_weight` times (objects lie on furniture); the free, reachable
   spot that covers the most uncovered weight per metre of driving is next, until
   :attr:`~SearchTask.coverage` of the weight is covered or :attr:`~SearchTask.max_vantages`
   are used.

Every frame goes to two perceptions: furniture from depth (the task context's
:class:`~assistant.executor.sensing.FurnitureSource`, e.g. a
:class:`~assistant.executor.sensing.SensedFurniture`: :class:`FurnitureDetector` +
:class:`EnvironmentModel`; throttled while driving) and small objects from the object detector
behind :class:`~assistant.perception.objects.ObjectDetector` (in the simulator the hit-id
sensor model :class:`~assistant.perception.objects.SimObjectDetector`, with its miss rate; a
real detector on hardware). Every frame in which objects are seen is reported as an
``objects_seen`` event ``{"seen": [Sighting…], "pose": Pose2D}`` (placed) so memory can record
them; progress as ``search_room`` ``{"room"}`` and ``vantage`` ``{"room", "pose"}`` events.

When the object is seen, the look-around under way is finished (the furniture around it gets
perceived), and if the object was far (more than :attr:`~SearchTask.confirm_distance_m`) or
no perceived furniture lies under it, the robot drives to a spot near it and looks around
again. Then (:attr:`~SearchTask.survey_found_room`) it finishes covering the object's room
the same way, so the environment model holds every piece of furniture there: the description
has to tell the support from look-alikes, and it can only do so for furniture it has seen.
``found_at_wall_s`` is the computer time to the sighting; ``wall_seconds`` includes this. The
:class:`SearchResult` carries the sighting, the perceived furniture (the environment model the
description is composed from), the rooms searched, the path length and the simulated and
wall-clock time. The search runs in the :class:`~assistant.executor.context.TaskContext` it is
handed and never reads the world file's furniture or objects: only the floor plan (told) and
the two perceptions.
"""

from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass, field

import networkx as nx
import numpy as np

from assistant.executor.context import BudgetSpent, TaskContext, moved_enough
from assistant.executor.entry import enter_room
from assistant.executor.outcome import ExecutionStatus
from assistant.executor.rooms import RoomGraph, room_of
from assistant.executor.sightings import place_sightings
from assistant.executor.viewing import point_viewing_spot
from assistant.geometry import point_in_polygon, polygon_lattice
from assistant.perception.objects import Sighting

__all__ = ["SEARCH_BUDGET_S", "SearchResult", "SearchTask", "room_order"]

#: robot seconds a search may use (the budget of its task context)
SEARCH_BUDGET_S = 2400.0


@dataclass
class SearchResult:
    """What a search found.

    ``found``: whether the object was seen; ``sighting``: where (a
    :class:`~assistant.perception.objects.Sighting` placed on the perceived furniture, with
    the pose it was seen from); ``furniture``: the perceived
    furniture entities at the end (the environment model); ``rooms_searched``: rooms in the
    order entered (the room where it was found last); ``vantages``: poses looked around from;
    ``path_m``: metres driven; ``sim_seconds``: robot time; ``wall_seconds``: computer time;
    ``frames``: depth frames perceived; ``seen``: every object name seen on the way → its last
    placed sighting; ``status``: ``success`` (found), ``not_found`` or ``timeout``
    (:class:`~assistant.executor.outcome.ExecutionStatus`), ``message`` in words.
    """

    object: str
    found: bool
    status: ExecutionStatus
    message: str
    sighting: Sighting | None = None
    furniture: list = field(default_factory=list)
    rooms_searched: list[str] = field(default_factory=list)
    vantages: list = field(default_factory=list)
    path_m: float = 0.0
    sim_seconds: float = 0.0
    wall_seconds: float = 0.0
    frames: int = 0
    seen: dict = field(default_factory=dict)
    found_at_wall_s: float | None = None

    def to_dict(self) -> dict:
        placed = self.sighting
        return {
            "object": self.object, "found": self.found, "status": self.status.value, "message": self.message,
            "sighting": self.sighting.to_dict() if self.sighting else None,
            "room": self.sighting.room if self.sighting else None,
            "support": None if placed is None else {"id": placed.furniture_id, "category": placed.furniture_category},
            "rooms_searched": list(self.rooms_searched),
            "vantages": [[round(p.x, 3), round(p.y, 3), round(p.theta, 4)] for p in self.vantages],
            "path_m": round(self.path_m, 2), "sim_seconds": round(self.sim_seconds, 2),
            "wall_seconds": round(self.wall_seconds, 3), "frames": self.frames,
            "furniture": [{"id": e.id, "name": e.name, "category": e.category, "room": e.room}
                          for e in self.furniture],
            "seen": sorted(self.seen),
        }


def room_order(world, start_room: str | None, start_xy=None) -> list[str]:
    """Rooms in search order: ``start_room`` first, then repeatedly the nearest room not yet
    searched from the last one (door-graph path length; straight-line between centres for
    rooms no door joins)."""
    graph = RoomGraph(world).graph
    rooms = [r.name for r in world.floorplan.rooms]
    centres = {r.name: np.asarray(r.centre, dtype=float) for r in world.floorplan.rooms}
    lengths = dict(nx.all_pairs_dijkstra_path_length(graph, weight="weight"))

    def distance(a, b):
        if a in lengths and b in lengths[a]:
            return float(lengths[a][b])
        return 2.0 * float(np.linalg.norm(centres[a] - centres[b])) + 5.0  # no doors: a detour

    order = []
    current = start_room
    if current is None and start_xy is not None:
        current = min(rooms, key=lambda r: float(np.linalg.norm(centres[r] - np.asarray(start_xy))))
    if current in rooms:
        order.append(current)
    while len(order) < len(rooms):
        left = [r for r in rooms if r not in order]
        here = order[-1] if order else None
        nxt = min(left, key=lambda r: (distance(here, r) if here else 0.0, rooms.index(r)))
        order.append(nxt)
    return order


@dataclass
class SearchTask:
    """Explores the home with the robot of the :class:`TaskContext` it is handed until
    ``detector`` reports the object (module docstring).

    ``detector``: an :class:`~assistant.perception.objects.ObjectDetector`; the context's
    perception is the environment model being built and its ``on_event(name, data)`` gets
    progress and ``objects_seen`` events. Distances in metres, times in seconds.
    """

    detector: object
    view_min_m: float = 0.6
    view_max_m: float = 3.0
    sample_m: float = 0.3
    furniture_weight: float = 4.0
    coverage: float = 0.9
    max_vantages: int = 6
    min_gain: float = 0.04  # a vantage must add this share of the room's weight
    clearance_m: float = 0.4
    confirm_distance_m: float = 2.2
    perceive_every_m: float = 0.5
    perceive_every_rad: float = 0.6
    survey_found_room: bool = True

    # ------------------------------------------------------------------ set-up
    def _setup(self, ctx: TaskContext, name: str) -> None:
        self.ctx = ctx
        self._name = " ".join(name.lower().split())
        self._wall0 = time.perf_counter()
        self._frames = 0
        self._found = None  # (perception sighting, pose)
        self._at_sighting = None  # the perceived furniture right after the sighting
        self._last_perceived = None
        self._vantages: list = []
        self._covered_from: list = []
        self._failed: list = []
        ctx.add_frame_listener(self._moving_frame)

    # ------------------------------------------------------------------ perception
    def _perceive(self, frame, pose, furniture: bool = True) -> bool:
        """Both perceptions on one frame; True when the object is among the sightings."""
        if frame is None:
            return False
        if furniture:
            self.ctx.perception.observe(frame, pose)
        self._frames += 1
        if pose is not None and frame.robot_pose != pose:
            frame = dataclasses.replace(frame, robot_pose=pose)
        sightings = self.detector.detect(frame)
        if not sightings:
            return False
        self.ctx.report_sightings(sightings, pose)
        hit = next((s for s in sightings if s.name.lower() == self._name), None)
        if hit is not None and (self._found is None or hit.distance_m < self._found[0].distance_m):
            self._found = (hit, pose)
        return hit is not None

    def _moving_frame(self, frame, pose) -> None:
        """The localizer's frames while driving: objects on every one, furniture every
        :attr:`perceive_every_m` metres or :attr:`perceive_every_rad` of turning."""
        furniture = moved_enough(self._last_perceived, pose, self.perceive_every_m, self.perceive_every_rad)
        if furniture:
            self._last_perceived = pose
        self._perceive(frame, pose, furniture)

    def _look_around(self, room: str) -> bool:
        """A full turn on the spot, perceiving at each stop; True when the object was seen (the
        turn is finished anyway so the furniture around is perceived)."""
        pose = self.ctx.pose()
        self.ctx.event("vantage", room=room, pose=pose)
        self._vantages.append(pose)
        seen = [False]

        def on_frame(frame, p):
            self.ctx.obstacles.add_frame(frame, p)
            seen[0] |= self._perceive(frame, p)
            return False

        self.ctx.look_around(on_frame)
        self._covered_from.append((pose.x, pose.y))
        return seen[0] or self._found is not None

    # ------------------------------------------------------------------ coverage
    def _samples(self, room) -> tuple[np.ndarray, np.ndarray]:
        pts = polygon_lattice(room.polygon_array, self.sample_m)
        weights = np.ones(len(pts))
        for e in self.ctx.perception.furniture():
            cells = e.points_m()
            if len(cells) == 0:
                continue
            lo_e, hi_e = cells.min(axis=0) - 0.15, cells.max(axis=0) + 0.15
            inside = np.all((pts >= lo_e) & (pts <= hi_e), axis=1)
            weights[inside] = self.furniture_weight
        return pts, weights

    def _sees(self, room, origins: np.ndarray, pts: np.ndarray) -> np.ndarray:
        """(len(origins), len(pts)) — which samples a look-around from each origin covers."""
        poly = room.polygon_array
        d = np.linalg.norm(origins[:, None, :] - pts[None, :, :], axis=2)
        ok = (d >= self.view_min_m) & (d <= self.view_max_m)
        # line of sight: the segment stays inside the room (three points along it)
        for t in (0.25, 0.5, 0.75):
            mid = origins[:, None, :] * (1 - t) + pts[None, :, :] * t
            flat = mid.reshape(-1, 2)
            inside = point_in_polygon(flat, poly).reshape(d.shape)
            ok &= inside
        return ok

    def _next_vantage(self, room):
        """The free reachable spot of ``room`` covering the most uncovered weight per metre
        (None when coverage is reached or nothing adds enough)."""
        pts, weights = self._samples(room)
        if len(pts) == 0:
            return None
        covered = np.zeros(len(pts), dtype=bool)
        if self._covered_from:
            covered = self._sees(room, np.asarray(self._covered_from), pts).any(axis=0)
        total = float(weights.sum())
        if float(weights[covered].sum()) >= self.coverage * total:
            return None
        occ = self.ctx.obstacles.occupancy()
        cand = polygon_lattice(room.polygon_array, 0.3)
        if len(cand) == 0:
            return None
        cand = cand[occ.clearance_at(cand) >= self.clearance_m]
        reachable = occ.reachable_from(self.ctx.pose(), cand)
        if reachable.any():  # (none: the robot stands in a gap the map closes; let the planner try)
            cand = cand[reachable]
        for tried in self._failed:
            cand = cand[np.hypot(cand[:, 0] - tried[0], cand[:, 1] - tried[1]) > 0.5]
        if len(cand) == 0:
            return None
        sees = self._sees(room, cand, pts[~covered])
        gain = sees.astype(float) @ weights[~covered]
        pose = self.ctx.pose()
        travel = np.hypot(cand[:, 0] - pose.x, cand[:, 1] - pose.y)
        score = gain / (1.0 + 0.25 * travel)
        best = int(np.argmax(score))
        if gain[best] < self.min_gain * total:
            return None
        return float(cand[best, 0]), float(cand[best, 1])

    def _cover(self, room_name: str, stop_when_found: bool) -> bool:
        """Drive to vantage points of the room and look around from each until it is covered;
        True when the object was seen (and ``stop_when_found``)."""
        room = self.ctx.world.floorplan.room(room_name)
        for _ in range(self.max_vantages):
            goal = self._next_vantage(room)
            if goal is None:
                break
            moved = self.ctx.go_to(goal)
            if stop_when_found and self._found is not None:
                return True
            if not moved.success and math.hypot(self.ctx.pose().x - goal[0], self.ctx.pose().y - goal[1]) > 0.6:
                self._failed.append(goal)
                continue
            if self._look_around(room_name) and stop_when_found:
                return True
        return False

    # ------------------------------------------------------------------ the search
    def run(self, ctx: TaskContext, name: str) -> SearchResult:
        """Search for ``name`` with the context's robot (connected, where it stands). Never
        raises for what happens in a home; returns a :class:`SearchResult`."""
        self._setup(ctx, name)
        searched: list[str] = []
        status, message = ExecutionStatus.NOT_FOUND, ""
        found_wall = None
        try:
            self._search_rooms(searched)
            if self._found is not None:
                found_wall = time.perf_counter() - self._wall0
                self._confirm()
                self._at_sighting = ctx.perception.furniture()
                if self.survey_found_room:
                    self._survey(searched)
                status, message = ExecutionStatus.SUCCESS, f"saw the {self._found[0].name}"
            else:
                message = f"did not see a {name} in " + ", ".join(searched) if searched else "could enter no room"
        except BudgetSpent:
            status = ExecutionStatus.SUCCESS if self._found is not None else ExecutionStatus.TIMEOUT
            message = f"search used up its budget of {ctx.max_sim_seconds:.0f} s of robot time"
        return self._result(name, status, message, searched, found_wall)

    def _search_rooms(self, searched: list[str]) -> None:
        """Rooms in :func:`room_order`, each entered, looked around and covered, until the
        object is seen; ``searched`` gets the rooms entered."""
        ctx = self.ctx
        start_room = room_of(ctx.world, ctx.pose())
        for room_name in room_order(ctx.world, start_room, (ctx.pose().x, ctx.pose().y)):
            if self._found is not None:
                return
            ctx.event("search_room", room=room_name)
            entered = enter_room(ctx, room_name, insist=True)
            if not entered.success:
                ctx.event("room_skipped", room=room_name, reason=entered.message)
                continue
            searched.append(room_name)
            self._covered_from = []
            self._failed = []
            if self._look_around(room_name) or self._cover(room_name, stop_when_found=True):
                return

    def _survey(self, searched: list[str]) -> None:
        """Finish covering the room the object is in, so that the environment model holds all
        its furniture: the description must tell the support from look-alikes the robot has
        not seen yet."""
        hit, _ = self._found
        room_name = room_of(self.ctx.world, (hit.x_m, hit.y_m))
        if room_name is None:
            return
        if room_of(self.ctx.world, self.ctx.pose()) != room_name:
            entered = enter_room(self.ctx, room_name, insist=True)
            if not entered.success:
                return
            self._covered_from = []
            self._failed = []
            self._look_around(room_name)
        if room_name not in searched:
            searched.append(room_name)
        self._cover(room_name, stop_when_found=False)

    def _confirm(self) -> None:
        """A closer look when the object was seen from afar or nothing perceived lies under it."""
        hit, pose = self._found
        placed = place_sightings(self.ctx.world, self.ctx.perception.furniture(), [hit])[0]
        if hit.distance_m <= self.confirm_distance_m and placed.furniture_id is not None:
            return
        spot = point_viewing_spot(self.ctx.obstacles.occupancy(), self.ctx.pose(), (hit.x_m, hit.y_m),
                                  self.clearance_m)
        if spot is None:
            return
        x, y = spot
        room = self.ctx.world.floorplan.room_at(x, y)
        moved = self.ctx.go_to((x, y), math.atan2(hit.y_m - y, hit.x_m - x))
        if moved.success:
            self._look_around(room.name if room else "")
            self.ctx.turn_to(math.atan2(hit.y_m - self.ctx.pose().y, hit.x_m - self.ctx.pose().x))

    def _result(self, name, status, message, searched, found_wall) -> SearchResult:
        ctx = self.ctx
        furniture = ctx.perception.furniture()
        sighting = None
        if self._found is not None:
            hit, pose = self._found
            placed = place_sightings(ctx.world, furniture, [hit])[0]
            if placed.furniture_id is None and self._at_sighting:
                # the environment model may drop a small table it missed from later views; the
                # robot keeps the one it saw the object on
                before = place_sightings(ctx.world, self._at_sighting, [hit])[0]
                if before.furniture_id is not None:
                    furniture = furniture + [e for e in self._at_sighting if e.id == before.furniture_id]
                    placed = before
            room = placed.room or room_of(ctx.world, (hit.x_m, hit.y_m))
            sighting = dataclasses.replace(placed, room=room, seen_from=pose)
        return SearchResult(
            object=name, found=self._found is not None, status=status, message=message,
            sighting=sighting, furniture=furniture, rooms_searched=searched,
            vantages=list(self._vantages), path_m=ctx.distance_m, sim_seconds=ctx.spent(),
            wall_seconds=time.perf_counter() - self._wall0, frames=self._frames, seen=dict(ctx.seen),
            found_at_wall_s=found_wall)

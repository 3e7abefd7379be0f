"""Searching the home for an object, room by room, with the robot's own perception.

The first step of "where is my X?" (dissertation chapter 6; issue item 1): the robot starts
where it stands and explores the rooms of the floor plan — the room it is in first, then
always the nearest room not yet searched (by the door graph, :class:`RoomGraph`) — until its
object detector reports the object.

In each room it

1. enters through the door (:meth:`Navigator.enter_room`; an open-plan room with no door on
   the way is entered by driving to the nearest free spot inside it),
2. looks around on the spot (eight 45° turns with the 57° camera: a full circle),
3. picks the next *vantage point* by greedy coverage: the room's floor is sampled every
   :attr:`ObjectSearch.sample_m`; a sample counts as covered once a look-around was made
   between :attr:`~ObjectSearch.view_min_m` and :attr:`~ObjectSearch.view_max_m` from it with
   the segment between them inside the room; samples on furniture perception has found count
   :attr:`~ObjectSearch.furniture_weight` times (objects lie on furniture); the free, reachable
   spot that covers the most uncovered weight per metre of driving is next, until
   :attr:`~ObjectSearch.coverage` of the weight is covered or :attr:`~ObjectSearch.max_vantages`
   are used.

Every frame goes to two perceptions: furniture from depth (a
:class:`~assistant.executor.sensing.SensedFurniture`: :class:`FurnitureDetector` +
:class:`EnvironmentModel`; throttled while driving) and small objects from the object detector
behind :class:`~assistant.perception.objects.ObjectDetector` (in the simulator the hit-id
sensor model :class:`~assistant.perception.objects.SimObjectDetector`, with its miss rate; a
real detector on hardware). Every frame in which objects are seen is reported as an
``objects_seen`` event ``{"seen": [PlacedSighting…], "pose": Pose2D}`` so memory can record
them; progress as ``search_room`` ``{"room"}`` and ``vantage`` ``{"room", "pose"}`` events.

When the object is seen, the look-around under way is finished (the furniture around it gets
perceived), and if the object was far (more than :attr:`~ObjectSearch.confirm_distance_m`) or
no perceived furniture lies under it, the robot drives to a spot near it and looks around
again. Then (:attr:`~ObjectSearch.survey_found_room`) it finishes covering the object's room
the same way, so the environment model holds every piece of furniture there: the description
has to tell the support from look-alikes, and it can only do so for furniture it has seen.
``found_at_wall_s`` is the computer time to the sighting; ``wall_seconds`` includes this. The :class:`SearchResult` carries the sighting, the perceived furniture (the
environment model the description is composed from), the rooms searched, the path length and
the simulated and wall-clock time. The search never reads the world file's furniture or
objects: only the floor plan (told) and the two perceptions.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from assistant.executor.task import BudgetSpent, TaskSteps
from assistant.generation.types import ObjectSighting

__all__ = ["ObjectSearch", "SearchResult", "room_order", "search_for", "to_generation_sighting"]


@dataclass
class SearchResult:
    """What a search found.

    ``found``: whether the object was seen; ``sighting``: where (a generation
    :class:`ObjectSighting`: position in metres, room, the pose it was seen from, seconds since
    the search began); ``placed``: the detector's sighting placed on the perceived furniture
    (:class:`~assistant.executor.sightings.PlacedSighting`); ``furniture``: the perceived
    furniture entities at the end (the environment model); ``rooms_searched``: rooms in the
    order entered (the room where it was found last); ``vantages``: poses looked around from;
    ``path_m``: metres driven; ``sim_seconds``: robot time; ``wall_seconds``: computer time;
    ``frames``: depth frames perceived; ``seen``: every object name seen on the way → its last
    placed sighting; ``status``/``message``: ``found``, ``not_found`` or why the search stopped.
    """

    object: str
    found: bool
    status: str
    message: str
    sighting: ObjectSighting | None = None
    placed: object | None = None
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
        placed = self.placed
        return {
            "object": self.object, "found": self.found, "status": self.status, "message": self.message,
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


class _Found(Exception):
    """Raised inside the search loop once the object is seen and the view finished."""


def to_generation_sighting(sighting, room: str | None, seen_from, time_s: float) -> ObjectSighting:
    """The detector's :class:`~assistant.perception.objects.ObjectSighting` as the generation
    layer's :class:`ObjectSighting` (room from the floor plan, pose seen from, search time)."""
    return ObjectSighting(sighting.name, float(sighting.x_m), float(sighting.y_m), float(sighting.z_m),
                          room, seen_from, float(time_s))


def room_order(world, start_room: str | None, start_xy=None) -> list[str]:
    """Rooms in search order: ``start_room`` first, then repeatedly the nearest room not yet
    searched from the last one (door-graph path length; straight-line between centres for
    rooms no door joins)."""
    import networkx as nx

    from assistant.executor.rooms import RoomGraph

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
class ObjectSearch(TaskSteps):
    """Explores ``world`` with a robot until ``detector`` reports the object (module docstring).

    ``perception``: a :class:`~assistant.executor.sensing.FurnitureSource` (the environment model
    being built; default a new :class:`SensedFurniture`); ``detector``: an
    :class:`~assistant.perception.objects.ObjectDetector`; ``on_event(name, data)``: progress and
    ``objects_seen`` events. Distances in metres, times in seconds.
    """

    world: object
    detector: object
    perception: object | None = None
    on_event: Callable[[str, dict], None] | None = None
    localize: bool = True
    max_sim_seconds: float = 2400.0
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
    def _setup(self, robot, name: str) -> None:
        from assistant.executor.localization import FloorplanLocalizer
        from assistant.executor.navigation import Navigator
        from assistant.executor.obstacles import DepthObstacles

        if self.perception is None:
            from assistant.executor.sensing import SensedFurniture

            self.perception = SensedFurniture(self.world)
        self._robot = robot
        self._name = " ".join(name.lower().split())
        self._t0 = robot.odometry().timestamp_s
        self._wall0 = time.perf_counter()
        self._dist = 0.0
        self._frames = 0
        self._found = None  # (perception sighting, pose)
        self._at_sighting = None  # the perceived furniture right after the sighting
        self._seen: dict = {}
        self._last_perceived = None
        self.obstacles = DepthObstacles(self.world, entities=self.perception.furniture)
        listeners = [self.obstacles.add_frame, self._moving_frame]
        self.localizer = FloorplanLocalizer(self.world, listeners=listeners) if self.localize else None
        self.navigator = Navigator(self.world, self.obstacles.occupancy, localizer=self.localizer, max_replans=10)

    # ------------------------------------------------------------------ perception
    def _perceive(self, frame, pose, furniture: bool = True) -> bool:
        """Both perceptions on one frame; True when the object is among the sightings."""
        if frame is None:
            return False
        if furniture:
            self.perception.observe(frame, pose)
        self._frames += 1
        if pose is not None and frame.robot_pose != pose:
            import dataclasses

            frame = dataclasses.replace(frame, robot_pose=pose)
        sightings = self.detector.detect(frame)
        if not sightings:
            return False
        self._report_sightings(sightings, pose)
        hit = next((s for s in sightings if s.name.lower() == self._name), None)
        if hit is not None and (self._found is None or hit.distance_m < self._found[0].distance_m):
            self._found = (hit, pose)
        return hit is not None

    def _moving_frame(self, frame, pose) -> None:
        """The localizer's frames while driving: objects on every one, furniture every
        :attr:`perceive_every_m` metres or :attr:`perceive_every_rad` of turning."""
        furniture = self._moved_enough(self._last_perceived, pose)
        if furniture:
            self._last_perceived = pose
        self._perceive(frame, pose, furniture)

    def _look_around(self, room: str) -> bool:
        """A full turn on the spot, perceiving at each stop; True when the object was seen (the
        turn is finished anyway so the furniture around is perceived)."""
        pose = self._pose()
        self._event("vantage", room=room, pose=pose)
        self._vantages.append(pose)
        seen = [False]

        def on_frame(frame, p):
            self.obstacles.add_frame(frame, p)
            seen[0] |= self._perceive(frame, p)
            return False

        self._step(self.navigator.look_around(self._robot, on_frame))
        self._covered_from.append((pose.x, pose.y))
        return seen[0] or self._found is not None

    # ------------------------------------------------------------------ coverage
    def _samples(self, room) -> tuple[np.ndarray, np.ndarray]:
        from assistant.geometry import polygon_lattice

        pts = polygon_lattice(room.polygon_array, self.sample_m)
        weights = np.ones(len(pts))
        for e in self.perception.furniture():
            cells = e.points_m()
            if len(cells) == 0:
                continue
            lo_e, hi_e = cells.min(axis=0) - 0.15, cells.max(axis=0) + 0.15
            inside = np.all((pts >= lo_e) & (pts <= hi_e), axis=1)
            weights[inside] = self.furniture_weight
        return pts, weights

    def _sees(self, room, origins: np.ndarray, pts: np.ndarray) -> np.ndarray:
        """(len(origins), len(pts)) — which samples a look-around from each origin covers."""
        from assistant.geometry import point_in_polygon

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
        from assistant.geometry import polygon_lattice

        pts, weights = self._samples(room)
        if len(pts) == 0:
            return None
        covered = np.zeros(len(pts), dtype=bool)
        if self._covered_from:
            covered = self._sees(room, np.asarray(self._covered_from), pts).any(axis=0)
        total = float(weights.sum())
        if float(weights[covered].sum()) >= self.coverage * total:
            return None
        occ = self.obstacles.occupancy()
        cand = polygon_lattice(room.polygon_array, 0.3)
        if len(cand) == 0:
            return None
        cand = cand[occ.clearance_at(cand) >= self.clearance_m]
        reachable = occ.reachable_from(self._pose(), cand)
        if reachable.any():  # (none: the robot stands in a gap the map closes; let the planner try)
            cand = cand[reachable]
        for tried in self._failed:
            cand = cand[np.hypot(cand[:, 0] - tried[0], cand[:, 1] - tried[1]) > 0.5]
        if len(cand) == 0:
            return None
        sees = self._sees(room, cand, pts[~covered])
        gain = sees.astype(float) @ weights[~covered]
        pose = self._pose()
        travel = np.hypot(cand[:, 0] - pose.x, cand[:, 1] - pose.y)
        score = gain / (1.0 + 0.25 * travel)
        best = int(np.argmax(score))
        if gain[best] < self.min_gain * total:
            return None
        return float(cand[best, 0]), float(cand[best, 1])

    # ------------------------------------------------------------------ moving
    def _enter(self, room: str):
        from assistant.executor.outcome import ExecutionResult, ExecutionStatus
        from assistant.executor.rooms import room_of

        if room_of(self.world, self._pose()) == room:
            return ExecutionResult.ok(f"in the {room}")
        entered = self._step(self.navigator.enter_room(self._robot, room))
        if entered.success and room_of(self.world, self._pose()) == room \
                and self.world.floorplan.room_at(self._pose().x, self._pose().y) is not None:
            return entered
        self._event("enter_failed", room=room, result=entered)
        # a door is narrow on the map: depth noise at its frame can close it. Forget the seen
        # obstacle cells within a metre of the doors on the way (the floor plan says they are
        # open) and try once more
        if self._clear_doors(room):
            entered = self._step(self.navigator.enter_room(self._robot, room))
            if entered.success and room_of(self.world, self._pose()) == room \
                    and self.world.floorplan.room_at(self._pose().x, self._pose().y) is not None:
                return entered
        # open plan (no door on the way) or a blocked door: the nearest free spot inside
        from assistant.geometry import polygon_lattice

        r = self.world.floorplan.room(room)
        occ = self.obstacles.occupancy()
        pts = polygon_lattice(r.polygon_array, 0.2, offset_m=0.2)
        pts = pts[(occ.clearance_at(pts) >= self.clearance_m) & occ.reachable_from(self._pose(), pts)]
        pose = self._pose()
        for _ in range(3):
            if len(pts) == 0:
                break
            i = int(np.argmin(np.hypot(pts[:, 0] - pose.x, pts[:, 1] - pose.y)))
            x, y = pts[i]
            moved = self._step(self.navigator.go_to(self._robot, (float(x), float(y)), snap_goal=False))
            if room_of(self.world, self._pose()) == room:
                return ExecutionResult.ok(f"entered the {room}", details={"open_plan": True})
            if moved.details.get("bumped"):
                break
            pts = pts[np.hypot(pts[:, 0] - x, pts[:, 1] - y) > 0.5]
        return ExecutionResult.failed(ExecutionStatus.NO_PATH, f"no way into the {room} was found")

    def _clear_doors(self, room: str) -> bool:
        """Zero the depth-obstacle counts within 1 m of every door of the floor plan that leads
        towards ``room``; True when any were cleared."""
        from assistant.executor.rooms import RoomGraph, room_of

        here = room_of(self.world, self._pose())
        doors = RoomGraph(self.world).doors_between(here, room) if here else None
        doors = doors or self.world.floorplan.doors_of(room)
        grid = self.obstacles.grid
        cleared = False
        for door in doors:
            cx, cy = door.centre
            xs, ys = np.meshgrid(np.arange(cx - 1.0, cx + 1.0, grid.resolution_m / 2),
                                 np.arange(cy - 1.0, cy + 1.0, grid.resolution_m / 2))
            cells = grid.world_to_cell(np.column_stack([xs.ravel(), ys.ravel()]))
            cells = cells[grid.contains_cells(cells)]
            if len(cells) and (self.obstacles.hits[cells[:, 0], cells[:, 1]] > 0).any():
                self.obstacles.hits[cells[:, 0], cells[:, 1]] = 0
                cleared = True
        return cleared

    # ------------------------------------------------------------------ the search
    def run(self, robot, name: str) -> SearchResult:
        """Search for ``name`` with ``robot`` (connected, at its start). Never raises for what
        happens in a home; returns a :class:`SearchResult`."""
        from assistant.executor.rooms import room_of

        self._setup(robot, name)
        self._vantages: list = []
        self._covered_from: list = []
        self._failed: list = []
        searched: list[str] = []
        status, message = "not_found", ""
        found_wall = None
        try:
            start_room = room_of(self.world, self._pose())
            for room_name in room_order(self.world, start_room, (self._pose().x, self._pose().y)):
                if self._found is not None:
                    break
                self._event("search_room", room=room_name)
                entered = self._enter(room_name)
                if not entered.success:
                    self._event("room_skipped", room=room_name, reason=entered.message)
                    continue
                searched.append(room_name)
                self._covered_from = []
                self._failed = []
                room = self.world.floorplan.room(room_name)
                if self._look_around(room_name):
                    break
                for _ in range(self.max_vantages):
                    goal = self._next_vantage(room)
                    if goal is None:
                        break
                    moved = self._step(self.navigator.go_to(self._robot, goal))
                    if self._found is not None:
                        break
                    if not moved.success and math.hypot(self._pose().x - goal[0], self._pose().y - goal[1]) > 0.6:
                        self._failed.append(goal)
                        continue
                    if self._look_around(room_name):
                        break
                if self._found is not None:
                    break
            if self._found is not None:
                found_wall = time.perf_counter() - self._wall0
                self._confirm()
                self._at_sighting = self.perception.furniture()
                if self.survey_found_room:
                    self._survey(searched)
                status, message = "found", f"saw the {self._found[0].name}"
            else:
                message = f"did not see a {name} in " + ", ".join(searched) if searched else "could enter no room"
        except BudgetSpent:
            status = "found" if self._found is not None else "timeout"
            message = f"search used up its budget of {self.max_sim_seconds:.0f} s of robot time"
        return self._result(name, status, message, searched, found_wall)

    def _survey(self, searched: list[str]) -> None:
        """Finish covering the room the object is in, so that the environment model holds all
        its furniture: the description must tell the support from look-alikes the robot has
        not seen yet."""
        from assistant.executor.rooms import room_of

        hit, _ = self._found
        room_name = room_of(self.world, (hit.x_m, hit.y_m))
        if room_name is None:
            return
        if room_of(self.world, self._pose()) != room_name:
            entered = self._enter(room_name)
            if not entered.success:
                return
            self._covered_from = []
            self._failed = []
            self._look_around(room_name)
        if room_name not in searched:
            searched.append(room_name)
        room = self.world.floorplan.room(room_name)
        for _ in range(self.max_vantages):
            goal = self._next_vantage(room)
            if goal is None:
                break
            moved = self._step(self.navigator.go_to(self._robot, goal))
            if not moved.success and math.hypot(self._pose().x - goal[0], self._pose().y - goal[1]) > 0.6:
                self._failed.append(goal)
                continue
            self._look_around(room_name)

    def _confirm(self) -> None:
        """A closer look when the object was seen from afar or nothing perceived lies under it."""
        from assistant.executor.sightings import place_sightings

        hit, pose = self._found
        placed = place_sightings(self.world, self.perception.furniture(), [hit])[0]
        if hit.distance_m <= self.confirm_distance_m and placed.furniture_id is not None:
            return
        occ = self.obstacles.occupancy()
        angles = np.linspace(0, 2 * math.pi, 16, endpoint=False)
        here = self._pose()
        best = None
        for r in (1.3, 1.6, 1.9):
            for a in angles:
                x, y = hit.x_m + r * math.cos(a), hit.y_m + r * math.sin(a)
                pt = np.array([[x, y]])
                if occ.clearance_at(pt)[0] < self.clearance_m or not occ.reachable_from(here, pt)[0]:
                    continue
                cost = math.hypot(x - here.x, y - here.y) + abs(r - 1.5)
                if best is None or cost < best[0]:
                    best = (cost, x, y)
        if best is None:
            return
        _, x, y = best
        room = self.world.floorplan.room_at(x, y)
        moved = self._step(self.navigator.go_to(self._robot, (x, y), math.atan2(hit.y_m - y, hit.x_m - x)))
        if moved.success:
            self._look_around(room.name if room else "")
            self._step(self.navigator.follower.turn_to(
                self._robot, math.atan2(hit.y_m - self._pose().y, hit.x_m - self._pose().x),
                localizer=self.localizer))

    def _result(self, name, status, message, searched, found_wall) -> SearchResult:
        from assistant.executor.rooms import room_of
        from assistant.executor.sightings import place_sightings

        furniture = self.perception.furniture()
        sighting = placed = None
        if self._found is not None:
            hit, pose = self._found
            placed = place_sightings(self.world, furniture, [hit])[0]
            if placed.furniture_id is None and getattr(self, "_at_sighting", None):
                # the environment model may drop a small table it missed from later views; the
                # robot keeps the one it saw the object on
                before = place_sightings(self.world, self._at_sighting, [hit])[0]
                if before.furniture_id is not None:
                    furniture = furniture + [e for e in self._at_sighting if e.id == before.furniture_id]
                    placed = before
            room = placed.room or room_of(self.world, (hit.x_m, hit.y_m))
            sighting = to_generation_sighting(hit, room, pose, hit.timestamp_s - self._t0)
        return SearchResult(
            object=name, found=self._found is not None, status=status, message=message,
            sighting=sighting, placed=placed, furniture=furniture, rooms_searched=searched,
            vantages=list(self._vantages), path_m=self._dist, sim_seconds=self._spent(),
            wall_seconds=time.perf_counter() - self._wall0, frames=self._frames, seen=dict(self._seen),
            found_at_wall_s=found_wall)


def search_for(name: str, world, scene: str = "original", *, detector=None, furniture_detector=None,
               miss_rate: float = 0.0, seed: int = 0, noise: bool = True, on_event=None,
               start=None, **params) -> SearchResult:
    """Search the simulated ``scene`` of ``world`` (a :class:`World` or name) for ``name`` from
    its start pose (or ``start``): a :class:`~assistant.sim.SimRobot` with odometry noise (the
    localizer corrects it), sensed furniture perception and, unless ``detector`` is given, a
    :class:`~assistant.perception.objects.SimObjectDetector` for the scene's objects with
    ``miss_rate``. ``furniture_detector`` shares a loaded :class:`FurnitureDetector` between
    searches. ``params`` go to :class:`ObjectSearch`."""
    from assistant.executor.sensing import SensedFurniture
    from assistant.perception.objects import SimObjectDetector
    from assistant.sim import OdometryNoise, SimRobot
    from assistant.world import load_world

    w = world if not isinstance(world, str) else load_world(world)
    sc = w.scene(scene)
    if detector is None:
        detector = SimObjectDetector.for_scene(sc, miss_rate=miss_rate, seed=seed)
    search = ObjectSearch(w, detector, SensedFurniture(w, detector=furniture_detector), on_event=on_event, **params)
    with SimRobot(w, sc.name, start=start, seed=seed,
                  odometry_noise=OdometryNoise() if noise else None) as robot:
        return search.run(robot, name)

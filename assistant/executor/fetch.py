"""The fetch task (dissertation 4.3 II.D, Fig. 5.8): from a grounded plan to a pose facing the
furniture the object is on.

The high tier is a sequence of three sub-tasks:

1. **enter the target room** through its door (:meth:`Navigator.enter_room` on the room graph),
   then look around once so perception sees the room;
2. **follow the RDT nodes** in order (the low tier, Fig. 5.8: collect sensory data, build the
   world state feature, decide the move-to target with the node's policy model, drive there):

   * a *dynamic* node (``move``/``room``/``wall`` reference, no target) asks its policy model
     for the move-to pose relative to the robot, the room or the wall ahead;
   * a *static* node looks for its reference and target furniture among what perception has
     reported in the room, trying the node's reference-direction pairs in order; when a
     reference or target is not seen it moves to the room's middle for a better view and looks
     around again; the (reference, target) instance pair that best fits the direction is handed
     to the policy model, whose move-to pose the robot drives to;
3. **face the target furniture**: when it is farther than :attr:`FetchTask.view_distance_m` or
   outside the camera's view, drive to a viewing pose beside it (the free side nearest the
   robot) and turn to it.

Recovery (the dissertation's future work, 5.7): when the reference or target is never found,
or the nodes run out without target furniture in view, the robot searches the surfaces the plan
makes likely — the room's furniture of the target's kind, nearest the robot's view first —
before giving up with ``reference_not_found``.

Everything ends in a :class:`FetchResult` (status: success or why not). All driving is bounded
by the follower's own budgets and by :attr:`FetchTask.max_sim_seconds` over the whole task.
The task reads the floor plan (told), the perception source and the robot's odometry — never
the world file's furniture or objects (only :class:`~assistant.executor.sensing.OracleFurniture`
does, and only when asked for).
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from assistant.executor.describe import description_fit
from assistant.executor.localization import FloorplanLocalizer
from assistant.executor.navigation import Navigator
from assistant.executor.obstacles import DepthObstacles
from assistant.executor.outcome import ExecutionResult, ExecutionStatus
from assistant.executor.rooms import room_of
from assistant.executor.sensing import (
    FurnitureSource,
    entity_centre,
    entity_polygon,
    entity_room,
    environment_items,
)
from assistant.executor.task import BudgetSpent, TaskSteps
from assistant.geometry import Pose2D, polygon_lattice, wrap_angle
from assistant.rdt import NO_TARGET, PLACE_REFERENCES
from assistant.spatial.resolve import DIRECTION_ANGLES, WALL_ANGLES, resolve
from assistant.world import Entity, World

#: half the Kinect's horizontal field of view (57°), radians
HALF_FOV_RAD = math.radians(28.5)


@dataclass
class NodeReport:
    """What happened at one RDT node."""

    rdt: str
    kind: str  # "dynamic" or "static"
    status: str
    message: str = ""
    model: str | None = None  # the policy model used (may be a fallback RDT)
    reference: str | None = None  # entity id
    target: str | None = None  # entity id
    move_to: list | None = None  # [x, y, heading]
    score: float | None = None
    tried: list = field(default_factory=list)  # [reference, direction] pairs tried

    def to_dict(self) -> dict:
        return {"rdt": self.rdt, "kind": self.kind, "status": self.status, "message": self.message,
                "model": self.model, "reference": self.reference, "target": self.target,
                "move_to": self.move_to, "score": self.score, "tried": self.tried}


@dataclass
class FetchResult:
    """The outcome of one fetch: ``status`` (success or the failure reason), the plan, each
    node's report, the robot's final pose (its own estimate, world frame), the target
    furniture chosen (id, centre) and simulated seconds."""

    status: ExecutionStatus
    message: str
    plan: dict | None = None
    nodes: list[NodeReport] = field(default_factory=list)
    final_pose: Pose2D | None = None
    target_furniture: dict | None = None
    sim_seconds: float = 0.0
    distance_m: float = 0.0
    recovered: bool = False
    details: dict = field(default_factory=dict)
    score_map: tuple | None = None  # (poses (N, 3), scores (N,)) of the last policy search
    seen: list = field(default_factory=list)  # PlacedSighting: the latest of each object seen

    @property
    def success(self) -> bool:
        return self.status is ExecutionStatus.SUCCESS

    def to_dict(self) -> dict:
        p = self.final_pose
        return {"status": self.status.value, "success": self.success,
                "failure": None if self.success else self.status.value, "message": self.message,
                "plan": self.plan, "nodes": [n.to_dict() for n in self.nodes],
                "final_pose": None if p is None else [round(p.x, 3), round(p.y, 3), round(p.theta, 4)],
                "target_furniture": self.target_furniture, "recovered": self.recovered,
                "sim_seconds": round(self.sim_seconds, 2), "distance_m": round(self.distance_m, 2),
                "seen": [s.to_dict() for s in self.seen], "details": self.details}


@dataclass
class FetchTask(TaskSteps):
    """Carries out grounded plans in ``world`` with a robot.

    ``perception``: a :class:`~assistant.executor.sensing.FurnitureSource`; ``policies``: a
    :class:`~assistant.policy.library.PolicyLibrary` (anything with ``model(rdt)`` returning an
    object with ``.model.infer_move_to`` and ``.used``), or None for the geometric fallback
    only. ``view_distance_m``: the final pose stands at most this far from the target's centre;
    ``standoff_m``: gap from the furniture's edge to the robot's centre at the viewing pose.
    ``weak_fit`` / ``weak_description``: a best pair scoring below the first, or a target
    fitting the words said about it ("the desk", "the round table") below the second, sends the
    robot for a better view before it commits. ``survey_range_m`` / ``max_unseen_share``: before its first static node the robot looks
    around again from further in when more than that share of the room lies farther than that
    range (metres) from everywhere it has looked (perception finds furniture reliably within a
    few metres). ``reference_range_m`` / ``max_looks_for_reference``: when a node names
    furniture not yet seen in the room ("the table in front of the chair" and no chair seen),
    the robot looks again, at most that many times, from the free spot that brings the most of
    the room within that range (metres) of where it has looked, before it settles for the
    node's other pairs ("against the back wall").
    ``object_detector``: an ``ObjectDetector`` (``assistant/perception/objects.py``) run on every
    depth frame the task receives (the localizer's frames while driving, the look-around and
    observe frames); each frame in which it reports objects becomes an ``objects_seen`` event
    (``seen``: :class:`~assistant.executor.sightings.PlacedSighting` list, ``pose``: the
    robot's pose at the frame) and the latest sighting of each object is kept in
    :attr:`FetchResult.seen`. The task reads objects only through this interface.
    """

    world: World
    perception: FurnitureSource
    policies: object | None = None
    localize: bool = True
    max_sim_seconds: float = 900.0
    view_distance_m: float = 1.8
    standoff_m: float = 0.75
    on_event: Callable[[str, dict], None] | None = None
    perceive_every_m: float = 1.0
    perceive_every_rad: float = 0.8
    weak_fit: float = 0.1
    object_detector: object | None = None
    survey_range_m: float = 4.5
    weak_description: float = 0.6
    max_unseen_share: float = 0.5
    reference_range_m: float = 3.0
    max_looks_for_reference: int = 2

    # ------------------------------------------------------------------ set-up
    def _setup(self, robot) -> None:
        self._robot = robot
        self._sim = 0.0
        self._dist = 0.0
        self._t0 = robot.odometry().timestamp_s
        self.obstacles = DepthObstacles(self.world, entities=self.perception.furniture)
        self._last_perceived: Pose2D | None = None
        self._perceive_room: str | None = None
        self._seen: dict[str, object] = {}  # object name → latest PlacedSighting
        self._looked_from: list[Pose2D] = []  # where the robot has looked around
        self._surveyed = False
        self._support: str | None = None  # words said about the current target
        self._descriptors: tuple[str, ...] = ()
        listeners = [self.obstacles.add_frame, self._observe_moving, self._detect_objects]
        self.localizer = FloorplanLocalizer(self.world, listeners=listeners) if self.localize else None
        self.navigator = Navigator(self.world, self.obstacles.occupancy, localizer=self.localizer, max_replans=10)
        self._last_map = None

    def _observe_moving(self, frame, pose: Pose2D) -> None:
        """Perception on the localizer's frames while driving: only in the target room, and
        only every :attr:`perceive_every_m` metres or :attr:`perceive_every_rad` of turning
        (detection is the costly part of a fetch)."""
        if self._perceive_room is None or room_of(self.world, pose) != self._perceive_room:
            return
        if not self._moved_enough(self._last_perceived, pose):
            return
        self._last_perceived = pose
        self.perception.observe(frame, pose)

    def _detect_objects(self, frame, pose: Pose2D) -> None:
        """Run the object detector on ``frame`` (taken at ``pose``); report what it sees."""
        if self.object_detector is None:
            return
        sightings = self.object_detector.detect(frame)
        if sightings:
            self._report_sightings(sightings, pose)

    def _observe_here(self) -> None:
        frame = self._robot.depth_frame()
        pose = self._pose()
        self.obstacles.add_frame(frame, pose)
        self.perception.observe(frame, pose)
        self._detect_objects(frame, pose)

    def _look_around(self) -> ExecutionResult:
        def on_frame(frame, pose):
            self.obstacles.add_frame(frame, pose)
            self.perception.observe(frame, pose)
            self._detect_objects(frame, pose)
            return False

        self._looked_from.append(self._pose())
        return self._step(self.navigator.look_around(self._robot, on_frame))

    def _room_points(self, room: str, step_m: float = 0.25) -> np.ndarray:
        """Floor points (N, 2) of ``room`` on a ``step_m`` lattice."""
        r = next((r for r in self.world.floorplan.rooms if r.name == room), None)
        return np.zeros((0, 2)) if r is None else polygon_lattice(r.polygon_array, step_m)

    def _unseen(self, points: np.ndarray, range_m: float | None = None) -> np.ndarray:
        """Which ``points`` lie farther than ``range_m`` (default :attr:`survey_range_m`) from
        every pose the robot has looked around from."""
        range_m = self.survey_range_m if range_m is None else range_m
        unseen = np.ones(len(points), dtype=bool)
        for p in self._looked_from:
            unseen &= np.hypot(points[:, 0] - p.x, points[:, 1] - p.y) > range_m
        return unseen

    def _survey(self, room: str, toward: tuple[float, float] | None = None,
                max_unseen_share: float | None = None, range_m: float | None = None) -> bool:
        """When more than ``max_unseen_share`` (default :attr:`max_unseen_share`) of a room
        lies beyond ``range_m`` (default :attr:`survey_range_m`) from everywhere the robot has
        looked (the hk-studio studio seen from its door), look again from the free spot that
        brings most of the rest within that range (or the one nearest ``toward``, the side the
        command points to). True when it moved and looked."""
        share = self.max_unseen_share if max_unseen_share is None else max_unseen_share
        range_m = self.survey_range_m if range_m is None else range_m
        pts = self._room_points(room)
        if len(pts) == 0:
            return False
        unseen = self._unseen(pts, range_m)
        if unseen.mean() <= share:
            return False
        if toward is None:
            occ = self.obstacles.occupancy()
            spots = self._room_points(room, 0.5)
            spots = spots[(occ.clearance_at(spots) >= 0.4) & occ.reachable_from(self._pose(), spots)]
            if len(spots) == 0:
                return False
            rest = pts[unseen]
            gain = (np.hypot(rest[:, None, 0] - spots[None, :, 0], rest[:, None, 1] - spots[None, :, 1])
                    <= range_m).sum(axis=0)
            toward = tuple(spots[int(np.argmax(gain))])
        self._better_view(room, toward)
        return True

    # ------------------------------------------------------------------ the task
    def run(self, robot, plan) -> FetchResult:
        """Carry out ``plan`` (a :class:`~assistant.grounding.GroundingPlan`) with ``robot``
        (connected). Never raises for what happens in a home; returns a :class:`FetchResult`."""
        self._setup(robot)
        plan_dict = plan.to_dict() if hasattr(plan, "to_dict") else dict(plan)
        reports: list[NodeReport] = []
        out = dict(plan=plan_dict, nodes=reports)
        try:
            result = self._run(plan, reports, out)
        except BudgetSpent:
            result = FetchResult(ExecutionStatus.TIMEOUT,
                                 f"the fetch used up its budget of {self.max_sim_seconds:.0f} s of robot time",
                                 **out)
        result.final_pose = self._pose()
        result.sim_seconds = self._spent()
        result.distance_m = self._dist
        if self.localizer is not None:
            result.details["localizer_updates"] = len(getattr(self.localizer, "updates", []) or [])
        result.details["frames_perceived"] = getattr(self.perception, "frames", None)
        result.seen = sorted(self._seen.values(), key=lambda p: p.name)
        return result

    def _run(self, plan, reports: list[NodeReport], out: dict) -> FetchResult:
        rooms = [r.name for r in self.world.floorplan.rooms]
        if not plan.nodes and not plan.room and not plan.object:
            return FetchResult(ExecutionStatus.PARSE, "the command could not be understood: no room, "
                               "place or object was found in it", **out)
        if not plan.room:
            here = room_of(self.world, self._pose())
            if not plan.nodes or not plan.nodes[0].dynamic:  # nothing says where to go from here
                unused = [w for w in getattr(plan, "unused", []) or []]
                extra = f" (words not understood: {', '.join(unused)})" if unused else ""
                return FetchResult(ExecutionStatus.NO_ROOM, "the command names no room of this home"
                                   f"{extra}; say which room ({', '.join(rooms)})", **out)
            room = here
        else:
            room = plan.room
        if room not in rooms:
            return FetchResult(ExecutionStatus.NO_ROOM, f"this home has no room called {room!r}; "
                               f"its rooms are {', '.join(rooms)}", **out)
        # 1. enter the target room, look around
        entered = self._enter(room)
        self._event("entered", room=room, result=entered)
        if not entered.success:
            return FetchResult(entered.status, f"could not enter the {room}: {entered.message}", **out)
        self._perceive_room = room
        entry = self._pose()
        self._look_around()
        # back to the heading it entered with: "on your right", "turn left" are said from there
        self._step(self.navigator.follower.turn_to(self._robot, entry.theta, localizer=self.localizer))
        # 2. RDT nodes
        target: Entity | None = None
        node_failure: tuple[ExecutionStatus, str] | None = None
        last_map = None
        for node in plan.nodes:
            report, chosen, score_map = self._run_node(node, room)
            reports.append(report)
            last_map = score_map or last_map
            self._event("node", report=report)
            if report.status == ExecutionStatus.SUCCESS.value:
                if chosen is not None:
                    target = chosen
            elif report.status in (ExecutionStatus.COLLISION.value, ExecutionStatus.TIMEOUT.value):
                return FetchResult(ExecutionStatus(report.status), f"node {report.rdt}: {report.message}",
                                   score_map=last_map, **out)
            else:
                node_failure = (ExecutionStatus(report.status), f"node {report.rdt}: {report.message}")
        # 3. face the target furniture (or search the likely surfaces)
        recovered = False
        wanted = self._target_word(plan)
        if plan.nodes:
            self._describe(plan.nodes[-1])
        if target is None or not self._in_view(target):
            if target is None:
                candidates = self._likely_surfaces(room, wanted)
                if not candidates:
                    self._better_view(room)
                    candidates = self._likely_surfaces(room, wanted)
                if not candidates:
                    status, message = node_failure or (
                        ExecutionStatus.REFERENCE_NOT_FOUND, f"no {wanted} was seen in the {room}")
                    return FetchResult(status, message, score_map=last_map, **out)
                target = candidates[0]
                recovered = True
        faced = self._face(target)
        info = {"id": target.id, "name": target.name, "centre": [round(v, 3) for v in entity_centre(target)]}
        if not faced.success:
            return FetchResult(faced.status, f"could not reach a view of the {target.name}: {faced.message}",
                               target_furniture=info, recovered=recovered, score_map=last_map, **out)
        if not self._in_view(target):
            return FetchResult(ExecutionStatus.NOT_VISIBLE, f"the {target.name} is not in view at the end",
                               target_furniture=info, recovered=recovered, score_map=last_map, **out)
        message = f"facing the {target.name} in the {room}"
        if recovered:
            message += " (found by searching the likely surfaces)"
        return FetchResult(ExecutionStatus.SUCCESS, message, target_furniture=info, recovered=recovered,
                           score_map=last_map, **out)

    def _enter(self, room: str) -> ExecutionResult:
        """Through the doors of the room graph; when no door leads there (rooms of an open
        plan share a boundary with no wall), straight to the nearest free spot well inside."""
        entered = self._step(self.navigator.enter_room(self._robot, room))
        if entered.success or entered.status is not ExecutionStatus.NO_PATH or "goal" in entered.details:
            return entered
        r = next(r for r in self.world.floorplan.rooms if r.name == room)
        poly = r.polygon_array
        cx, cy = poly.mean(axis=0)
        result = entered
        tried: list[np.ndarray] = []
        for _ in range(4):  # candidates from the latest occupancy: depth shows more on the way
            pose = self._pose()
            occ = self.obstacles.occupancy()
            pts = np.zeros((0, 2))
            for inset, clearance in ((0.6, 0.4), (0.3, 0.32)):  # well inside if there is room, else just inside
                lo, hi = poly.min(axis=0) + inset, poly.max(axis=0) - inset
                if np.any(hi < lo):
                    lo = hi = poly.mean(axis=0)
                xs, ys = np.meshgrid(np.arange(lo[0], hi[0] + 1e-9, 0.1), np.arange(lo[1], hi[1] + 1e-9, 0.1))
                pts = np.column_stack([xs.ravel(), ys.ravel()])
                keep = (occ.clearance_at(pts) >= clearance) & occ.reachable_from(pose, pts)
                for t in tried:  # not again near a spot that failed
                    keep &= np.hypot(pts[:, 0] - t[0], pts[:, 1] - t[1]) > 0.5
                pts = pts[keep]
                if len(pts):
                    break
            if len(pts) == 0:
                break
            x, y = pts[int(np.argmin(np.hypot(pts[:, 0] - pose.x, pts[:, 1] - pose.y)))]
            tried.append(np.array([x, y]))
            result = self._step(self.navigator.go_to(self._robot, (float(x), float(y)),
                                                     math.atan2(cy - y, cx - x), snap_goal=False))
            inside = room_of(self.world, self._pose()) == room
            if inside and (result.success or result.status is ExecutionStatus.NO_PATH):
                # in the room already (the spot aimed at turned out to be taken): good enough to look
                return ExecutionResult.ok(f"entered the {room}", final_pose=self._pose(),
                                          details={"room": room, "open_plan": True})
            if result.status in (ExecutionStatus.TIMEOUT,) or result.details.get("bumped"):
                break
        if result.success:  # arrived somewhere, but not in the room
            result = ExecutionResult.failed(ExecutionStatus.NO_PATH, f"no way into the {room} was found",
                                            final_pose=self._pose())
        return result

    # ------------------------------------------------------------------ nodes
    def _run_node(self, node, room: str):
        rdts = node.rdts
        if node.dynamic:
            return self._dynamic_node(rdts[0], room)
        report = NodeReport(str(node), "static", ExecutionStatus.REFERENCE_NOT_FOUND.value)
        # furniture references first: "between the two chairs" singles a table out better than
        # "across the room"; the other pairs still weigh in (:meth:`_agreement`)
        rdts = sorted(rdts, key=lambda r: r.reference in PLACE_REFERENCES)
        looked_again = False
        said_from = self._pose()  # "on your right" keeps meaning this pose's right after a look elsewhere
        self._describe(node)
        if not self._surveyed:  # a room too large to see from its door: look from further in first
            self._surveyed = True
            toward = next((t for t in (self._toward(r, said_from) for r in rdts) if t is not None), None)
            self._survey(room, toward)
        self._look_for(room, [r.reference for r in rdts if r.reference not in PLACE_REFERENCES] + [node.target])
        for attempt in range(2):
            for rdt in rdts:
                report.tried.append([rdt.reference, rdt.direction])
                others = [r for r in rdts if r is not rdt]
                pair = self._choose_pair(rdt, room, said_from, others)
                if pair is None:
                    continue
                unsure = pair[2] < self.weak_fit or self._described(pair[1]) < self.weak_description
                if unsure and not looked_again:  # nothing fits well, or not what was said ("the desk")
                    self._better_view(room, self._toward(rdt, said_from))  # unsure: a better view first
                    looked_again = True
                    pair = self._choose_pair(rdt, room, said_from, others) or pair
                reference, target, fit = pair
                report.reference = None if reference is None else reference.id
                report.target = target.id
                moved, score_map = self._move_by_policy(str(rdt), reference, target, report)
                report.status = moved.status.value
                report.message = moved.message
                if moved.status is ExecutionStatus.NO_PATH:  # the policy's pose is unreachable: go near the target
                    moved = self._face(target)
                    report.status, report.message = moved.status.value, moved.message
                elif self._recover_from_bump(moved):  # touched something unseen near the goal
                    moved = self._face(target)
                    report.status = moved.status.value
                    report.message = f"bumped near the move-to pose, backed off; {moved.message}"
                return report, target if moved.success else None, score_map
            if looked_again:
                break
            self._better_view(room)
            looked_again = True
        wanted = " or ".join(sorted({r.reference for r in rdts if r.reference not in ("robot", "room")}))
        report.message = (f"no {wanted} with a {node.target} " if wanted else f"no {node.target} ") + f"seen in the {room}"
        return report, None, None

    def _look_for(self, room: str, words) -> None:
        """While some furniture the node names (``words``: reference and target words) is not
        seen in ``room``, look again from further in (:meth:`_survey` with
        :attr:`reference_range_m`), at most :attr:`max_looks_for_reference` times."""
        words = sorted({w for w in words if w and w != NO_TARGET})
        for _ in range(self.max_looks_for_reference):
            if all(self._in_room(room, w) for w in words):
                return
            if not self._survey(room, max_unseen_share=0.05, range_m=self.reference_range_m):
                return

    def _dynamic_node(self, rdt, room: str):
        report = NodeReport(str(rdt), "dynamic", ExecutionStatus.SUCCESS.value)
        report.tried.append([rdt.reference, rdt.direction])
        reference = None
        here = room_of(self.world, self._pose()) or room
        if rdt.reference == "room":
            reference = f"room:{here}"
        elif rdt.reference == "wall":
            reference = self._wall_ahead(here)
        moved, score_map = self._move_by_policy(str(rdt), reference, None, report)
        report.status, report.message = moved.status.value, moved.message
        if moved.status is ExecutionStatus.NO_PATH:  # a dynamic step that cannot be taken: stay, go on
            report.status = ExecutionStatus.SUCCESS.value
            report.message = f"skipped ({moved.message})"
        return report, None, score_map

    def _move_by_policy(self, rdt: str, reference, target, report: NodeReport):
        pose = self._pose()
        env = environment_items(self.world, self.perception.furniture())
        ref_id = reference if isinstance(reference, str) or reference is None else reference.id
        tar_id = None if target is None else target.id
        goal, score_map = None, None
        if self.policies is not None:
            try:
                choice = self.policies.model(rdt)
                found = choice.model.infer_move_to(env, pose, ref_id, tar_id)
                report.model = choice.used
                if len(found.scores):
                    goal = found.pose
                    report.score = float(found.score)
                    score_map = (found.poses, found.scores)
            except Exception as error:  # no model, unknown entity: fall back to geometry
                report.model = f"none ({type(error).__name__}: {error})"
        if goal is None:
            goal = self._geometric_goal(rdt, pose, reference, target)
            report.model = report.model or "geometric"
        report.move_to = [round(goal.x, 3), round(goal.y, 3), round(goal.theta, 4)]
        self._event("move_to", rdt=rdt, goal=goal, score_map=score_map)
        result = self._step(self.navigator.go_to(self._robot, (goal.x, goal.y), goal.theta))
        return result, score_map

    def _geometric_goal(self, rdt: str, pose: Pose2D, reference, target) -> Pose2D:
        """A move-to pose without a policy model: beside the target, else 1 m in the
        direction said."""
        if target is not None:
            cx, cy = entity_centre(target)
            return Pose2D(cx, cy, math.atan2(cy - pose.y, cx - pose.x))
        direction = rdt.split("-")[1]
        turn = DIRECTION_ANGLES.get(direction, 0.0)
        heading = wrap_angle(pose.theta + turn)
        return Pose2D(pose.x + math.cos(heading), pose.y + math.sin(heading), heading)

    def _wall_ahead(self, room: str) -> str | None:
        pose = self._pose()
        env = [e for e in environment_items(self.world, ()) if e.id.startswith("wall:") and e.room == room]
        from assistant.geometry import point_in_polygon

        for step in np.arange(0.1, 12.0, 0.1):
            p = np.array([[pose.x + step * math.cos(pose.theta), pose.y + step * math.sin(pose.theta)]])
            for item in env:
                if point_in_polygon(p, item.polygon_array())[0]:
                    return item.id
        return None

    # ------------------------------------------------------------------ choosing furniture
    def _in_room(self, room: str, word: str | None = None) -> list[Entity]:
        out = []
        for e in self.perception.furniture():
            if word is not None and e.name != word:
                continue
            if entity_room(self.world, e) == room:
                out.append(e)
        return out

    def _choose_pair(self, rdt, room: str, pose: Pose2D | None = None, others=()):
        """The (reference, target, fit) that best fit ``rdt`` among the furniture seen in
        ``room`` (:func:`assistant.spatial.resolve`); None when the reference or target is not
        seen. ``pose``: the robot's pose the command's "your left" is said from (default: now);
        ``others``: the node's other RDTs, which the target should fit too."""
        readings = resolve(rdt, self._in_room(room), pose or self._pose(),
                           floorplan=self.world.floorplan, also=others, prior=self._described)
        if not readings:
            return None
        best = readings[0]
        return best.reference, best.target, best.fit

    def _describe(self, node) -> None:
        """Remember the words said about ``node``'s target (support word, size/shape words)."""
        self._support = getattr(node, "support", None)
        self._descriptors = tuple(getattr(node, "descriptors", ()) or ())

    def _described(self, entity: Entity) -> float:
        """How well ``entity`` fits the words said about the current target (1 = no words)."""
        return description_fit(getattr(self, "_support", None), getattr(self, "_descriptors", ()), entity)

    def _target_word(self, plan) -> str:
        if plan.nodes:
            return plan.nodes[-1].target if plan.nodes[-1].target != "non" else "table"
        return "table"

    def _likely_surfaces(self, room: str, word: str) -> list[Entity]:
        """Furniture of the target's kind in the room, the one most in the robot's view first."""
        pose = self._pose()
        items = self._in_room(room, word) or self._in_room(room, "table")

        def rank(e):
            x, y = entity_centre(e)
            d = math.hypot(x - pose.x, y - pose.y)
            bearing = abs(wrap_angle(math.atan2(y - pose.y, x - pose.x) - pose.theta))
            return -(math.exp(-d / 3.0) * (1.0 + math.cos(bearing)) * self._described(e))

        return sorted(items, key=rank)

    def _toward(self, rdt, said_from: Pose2D) -> tuple[float, float] | None:
        """Where to look from when the robot itself is the reference ("on your right", or an
        unreferenced target after some steps): a few metres that way from where it was said."""
        if rdt.reference not in ("robot", "room", "move", "wall"):
            return None
        angles = WALL_ANGLES if rdt.reference == "wall" else DIRECTION_ANGLES
        turn = angles.get(rdt.direction, 0.0) / 2  # that side and ahead: the room lies ahead
        heading = said_from.theta + turn
        return (said_from.x + 4.0 * math.cos(heading), said_from.y + 4.0 * math.sin(heading))

    def _better_view(self, room: str, toward: tuple[float, float] | None = None) -> None:
        """Move to the middle of the room — or, given ``toward``, to the free spot of the room
        nearest that point — and look around."""
        r = next((r for r in self.world.floorplan.rooms if r.name == room), None)
        if r is None:
            return
        cx, cy = r.polygon_array.mean(axis=0)
        if toward is not None:
            occ = self.obstacles.occupancy()
            lo, hi = r.polygon_array.min(axis=0) + 0.4, r.polygon_array.max(axis=0) - 0.4
            xs, ys = np.meshgrid(np.arange(lo[0], hi[0] + 1e-9, 0.2), np.arange(lo[1], hi[1] + 1e-9, 0.2))
            pts = np.column_stack([xs.ravel(), ys.ravel()])
            pts = pts[(occ.clearance_at(pts) >= 0.4) & occ.reachable_from(self._pose(), pts)]
            if len(pts):
                cx, cy = pts[int(np.argmin(np.hypot(pts[:, 0] - toward[0], pts[:, 1] - toward[1])))]
        moved = self._step(self.navigator.go_to(self._robot, (float(cx), float(cy))))
        self._event("better_view", result=moved)
        self._look_around()

    # ------------------------------------------------------------------ facing the target
    def _in_view(self, target: Entity, pose: Pose2D | None = None) -> bool:
        """Whether ``target`` is near enough, inside the field of view and not hidden behind
        other perceived furniture (:meth:`_clear_sight`) from ``pose`` (default: now)."""
        pose = pose or self._pose()
        x, y = entity_centre(target)
        local = pose.to_local(np.array([[x, y]]))[0]
        dist = math.hypot(*local)
        radius = float(np.hypot(*(entity_polygon(target) - [x, y]).T).max())  # large tables stand farther off
        return (dist <= self.view_distance_m + radius and abs(math.atan2(local[1], local[0])) < HALF_FOV_RAD * 0.8
                and self._clear_sight(target, pose.x, pose.y))

    def _clear_sight(self, target: Entity, x: float, y: float, step_m: float = 0.05) -> bool:
        """Whether the straight line from ``(x, y)`` to ``target``'s centre crosses no other
        perceived furniture before it reaches the target's own cells: an arm of the couch
        between the robot and a low table hides what lies on the table."""
        tx, ty = entity_centre(target)
        length = math.hypot(tx - x, ty - y)
        if length < step_m:
            return True
        t = np.arange(step_m, length, step_m) / length
        line = np.column_stack([x + t * (tx - x), y + t * (ty - y)])
        own = target.points_m()
        if len(own):  # the part of the line over the target itself does not count
            from scipy.spatial import cKDTree

            d, _ = cKDTree(own).query(line, k=1)
            line = line[d > target.grid.resolution_m]
        if len(line) == 0:
            return True
        for other in self.perception.furniture():
            if other.id == target.id:
                continue
            cells = other.points_m()
            if len(cells) == 0:
                continue
            lo, hi = cells.min(axis=0) - 0.1, cells.max(axis=0) + 0.1
            near = line[np.all((line >= lo) & (line <= hi), axis=1)]
            if len(near) == 0:
                continue
            from scipy.spatial import cKDTree

            d, _ = cKDTree(cells).query(near, k=1)
            if np.any(d <= other.grid.resolution_m * 0.75):  # inside a cell (half its diagonal is 0.71)
                return False
        return True

    def _face(self, target: Entity) -> ExecutionResult:
        """Drive to a viewing pose of ``target`` (if not already there) and turn to it."""
        pose = self._pose()
        cx, cy = entity_centre(target)
        if not self._in_view(target):
            last = None
            for goal in self._viewing_poses(target, self._pose())[:4]:
                last = self._step(self.navigator.go_to(self._robot, goal[:2], goal[2]))
                if last.success:
                    break
                if not self._recover_from_bump(last):
                    break
                if self._in_view(target):  # backed off with the target in view: close enough
                    last = ExecutionResult.ok("backed off after a bump, the target in view", final_pose=self._pose())
                    break
            if last is not None and not last.success:
                return last
        turned = self._step(self.navigator.follower.face_point(self._robot, cx, cy, localizer=self.localizer)
                            if _accepts_localizer(self.navigator.follower.face_point)
                            else self.navigator.follower.face_point(self._robot, cx, cy))
        self._observe_here()
        return turned

    def _recover_from_bump(self, result: ExecutionResult) -> bool:
        """After a bump (``result`` a collision with ``bumped``): back off a little and say
        True so the caller tries another way; False for any other result, or when backing
        off bumped too (boxed in: the collision stands)."""
        if result.status is not ExecutionStatus.COLLISION or not result.details.get("bumped"):
            return False
        backed = self._step(self.navigator.follower.back_off(self._robot, localizer=self.localizer))
        self._observe_here()  # what it touched may now be in view
        return backed.success

    def _viewing_poses(self, target: Entity, pose: Pose2D) -> list[tuple[float, float, float]]:
        """Free poses ``standoff_m`` off the furniture's edge, facing its centre, nearest the
        robot first; poses from which other furniture hides the target come last."""
        cx, cy = entity_centre(target)
        poly = entity_polygon(target)
        occ = self.obstacles.occupancy()
        room = entity_room(self.world, target)
        out = []
        for k in range(16):
            a = 2 * math.pi * k / 16
            u = np.array([math.cos(a), math.sin(a)])
            extent = float(((poly - [cx, cy]) @ u).max())
            for extra in (0.0, 0.25):
                r = extent + self.standoff_m + extra
                x, y = cx + r * u[0], cy + r * u[1]
                if not occ.is_free(x, y) or float(occ.clearance_at(np.array([[x, y]]))[0]) < 0.35 \
                        or not occ.reachable_from(pose, np.array([[x, y]]))[0]:
                    continue
                here = self.world.floorplan.room_at(x, y)
                penalty = 0.0 if here is not None and here.name == room else 3.0
                if not self._clear_sight(target, x, y):  # other furniture in the way: a last resort
                    penalty += 2.0
                cost = math.hypot(x - pose.x, y - pose.y) + penalty + extra
                out.append((cost, (x, y, math.atan2(cy - y, cx - x))))
                break
        out.sort(key=lambda c: c[0])
        return [g for _, g in out]


def _accepts_localizer(method) -> bool:
    import inspect

    try:
        return "localizer" in inspect.signature(method).parameters
    except (TypeError, ValueError):
        return False


def fetch(world: World, plan, robot, perception: FurnitureSource, policies=None, **params) -> FetchResult:
    """Run one :class:`FetchTask` (convenience)."""
    return FetchTask(world, perception, policies, **params).run(robot, plan)


__all__ = ["DIRECTION_ANGLES", "FetchResult", "FetchTask", "NodeReport", "fetch"]

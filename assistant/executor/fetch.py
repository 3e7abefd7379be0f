"""The fetch task (dissertation 4.3 II.D, Fig. 5.8): from a grounded plan to a pose facing the
furniture the object is on.

The high tier is a sequence of three sub-tasks:

1. **enter the target room** (:func:`~assistant.executor.entry.enter_room`), look around once;
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

The task runs in the :class:`~assistant.executor.context.TaskContext` it is handed and ends in
a :class:`FetchResult`; driving is bounded by the follower's budgets and the context's
``max_sim_seconds``. Choosing furniture is :mod:`~assistant.executor.choosing`, seeing it
:mod:`~assistant.executor.viewing`, entering the room :mod:`~assistant.executor.entry`. It never
reads the world file's furniture or objects (only the oracle perception source does).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from assistant.errors import UnknownNameError
from assistant.executor.choosing import NOTHING_SAID, PlaceChooser, Said, is_landmark
from assistant.rdt import PLACE_REFERENCES
from assistant.spatial.resolve import DIRECTION_ANGLES, WALL_ANGLES
from assistant.executor.context import BudgetSpent, TaskContext, moved_enough
from assistant.executor.entry import enter_room
from assistant.executor.outcome import ExecutionResult, ExecutionStatus
from assistant.executor.reports import FetchResult, NodeReport
from assistant.executor.rooms import room_of
from assistant.executor.sensing import entity_centre, entity_room, environment_items
from assistant.executor.spoken import nearest_first, room_from_here, run_moves, spoken_node
from assistant.grounding.motion import is_motion_plan
from assistant.grounding.rooms import furniture_room
from assistant.executor.survey import Surveyor
from assistant.executor.viewing import in_view, point_viewing_spot, viewing_poses
from assistant.geometry import Pose2D, point_in_polygon, wrap_angle
from assistant.grounding.vocabulary import NO_TARGET
from assistant.policy.model import NotFittedError
from assistant.world import Entity

#: robot seconds a fetch may use (the budget of its task context)
FETCH_BUDGET_S = 900.0


@dataclass
class FetchTask:
    """Carries out grounded plans in the :class:`~assistant.executor.context.TaskContext` that
    :meth:`run` is handed (its world, robot and furniture perception).

    ``policies``: a
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
    (``seen``: placed :class:`~assistant.perception.objects.Sighting` list, ``pose``: the
    robot's pose at the frame) and the latest sighting of each object is kept in
    :attr:`FetchResult.seen`. The task reads objects only through this interface.
    """

    policies: object | None = None
    view_distance_m: float = 1.8
    standoff_m: float = 0.75
    perceive_every_m: float = 1.0
    perceive_every_rad: float = 0.8
    weak_fit: float = 0.1
    object_detector: object | None = None
    survey_range_m: float = 4.5
    weak_description: float = 0.6
    max_unseen_share: float = 0.5
    reference_range_m: float = 3.0
    max_looks_for_reference: int = 2
    max_other_surfaces: int = 3  # surfaces looked at when the object is not seen on the target
    spot_clearance_m: float = 0.4  # free space around the spot to look at an object seen from afar
    by_target_m: float = 0.3  # a thing seen this near the target's cells is by it (metres)

    # ------------------------------------------------------------------ set-up
    def _setup(self, ctx: TaskContext) -> None:
        self.ctx = ctx
        self.chooser = PlaceChooser(ctx.world, ctx.perception, ctx.seen)  # objects seen are landmarks too
        self._last_perceived: Pose2D | None = None
        self._perceive_room: str | None = None
        self.surveyor = Surveyor(ctx, self._on_frame, self.survey_range_m, self.max_unseen_share)
        self._surveyed = False
        self._said = NOTHING_SAID  # words said about the current target
        self._said_from: Pose2D | None = None  # where "on your left" is said from, when not the node's start
        self._detector_blind = False  # the object detector cannot read this robot's frames
        ctx.add_frame_listener(self._observe_moving)
        ctx.add_frame_listener(self._detect_objects)

    def _observe_moving(self, frame, pose: Pose2D) -> None:
        """Perception on the localizer's frames while driving: only in the target room, and
        only every :attr:`perceive_every_m` metres or :attr:`perceive_every_rad` of turning
        (detection is the costly part of a fetch)."""
        if self._perceive_room is None or room_of(self.ctx.world, pose) != self._perceive_room:
            return
        if not moved_enough(self._last_perceived, pose, self.perceive_every_m, self.perceive_every_rad):
            return
        self._last_perceived = pose
        self.ctx.perception.observe(frame, pose)

    def _detect_objects(self, frame, pose: Pose2D) -> None:
        """Run the object detector on ``frame`` (taken at ``pose``); report what it sees."""
        if self.object_detector is None:
            return
        reads = getattr(self.object_detector, "reads", None)
        if reads is not None and not reads(frame):
            self._detector_blind = True  # e.g. a replayed session: not seeing means nothing
            return
        sightings = self.object_detector.detect(frame)
        if sightings:
            self.ctx.report_sightings(sightings, pose)

    def _observe_here(self) -> None:
        frame = self.ctx.robot.depth_frame()
        self._on_frame(frame, self.ctx.pose())

    def _on_frame(self, frame, pose: Pose2D) -> bool:
        self.ctx.obstacles.add_frame(frame, pose)
        self.ctx.perception.observe(frame, pose)
        self._detect_objects(frame, pose)
        return False

    # ------------------------------------------------------------------ the task
    def run(self, ctx: TaskContext, plan) -> FetchResult:
        """Carry out ``plan`` (a :class:`~assistant.grounding.GroundingPlan`) in ``ctx`` (its
        robot connected). Never raises for what happens in a home; returns a
        :class:`FetchResult`."""
        self._setup(ctx)
        plan_dict = plan.to_dict() if hasattr(plan, "to_dict") else dict(plan)
        reports: list[NodeReport] = []
        out = dict(plan=plan_dict, nodes=reports)
        try:
            result = self._run(plan, reports, out)
        except BudgetSpent:
            spent = f"the fetch used up its budget of {ctx.max_sim_seconds:.0f} s of robot time"
            result = FetchResult(ExecutionStatus.TIMEOUT, spent, **out)
        result.final_pose = ctx.pose()
        result.sim_seconds = ctx.spent()
        result.distance_m = ctx.distance_m
        if ctx.localizer is not None:
            result.details["localizer_updates"] = len(ctx.localizer.updates)
        result.details["frames_perceived"] = getattr(ctx.perception, "frames", None)
        result.seen = sorted(ctx.seen.values(), key=lambda p: p.name)
        return result

    def _target_room(self, plan, out: dict) -> str | FetchResult:
        """The room the plan is carried out in, or the result that says why there is none."""
        rooms = [r.name for r in self.ctx.world.floorplan.rooms]
        if not plan.nodes and not plan.room and not plan.object:
            return FetchResult(ExecutionStatus.PARSE, "the command could not be understood: no room, "
                               "place or object was found in it", **out)
        if not plan.room:
            # carried out from where the robot is (issue 16): the room it is in, or the one it
            # faces through the nearest opening; "on your left" is said from the start pose
            self._said_from = self.ctx.pose()
            only_moves, here = plan.nodes and all(n.dynamic for n in plan.nodes), self.ctx.pose()
            # "… next to the bed": the bedroom, whatever room the robot is in (common sense)
            room = room_of(self.ctx.world, here) if only_moves else (
                furniture_room(plan.nodes, self.ctx.world) or room_from_here(self.ctx.world, here, plan))
            if room is None:
                unused = [w for w in getattr(plan, "unused", []) or []]
                extra = f" (words not understood: {', '.join(unused)})" if unused else ""
                return FetchResult(ExecutionStatus.NO_ROOM, "the command names no room of this home and the "
                                   f"robot is in none{extra}; say which room ({', '.join(rooms)})", **out)
        else:
            room = plan.room
        if room not in rooms:
            return FetchResult(ExecutionStatus.NO_ROOM, f"this home has no room called {room!r}; "
                               f"its rooms are {', '.join(rooms)}", **out)
        return room

    def _run(self, plan, reports: list[NodeReport], out: dict) -> FetchResult:
        ctx = self.ctx
        if is_motion_plan(plan):  # "turn around", "back up a little": where the robot is, nothing else
            status, message = run_moves(ctx, plan, reports)
            return FetchResult(status, message, details={"motion": True}, **out)
        room = self._target_room(plan, out)
        if isinstance(room, FetchResult):
            return room
        # 1. enter the target room, look around
        entered = enter_room(ctx, room)
        ctx.event("entered", room=room, result=entered)
        if not entered.success:
            return FetchResult(entered.status, f"could not enter the {room}: {entered.message}", **out)
        self._perceive_room = room
        entry = ctx.pose()
        self.surveyor.look_around()
        # back to the heading it entered with: "on your right", "turn left" are said from there
        ctx.turn_to(entry.theta)
        # 2. RDT nodes
        target, failure, last_map = self._follow_nodes(plan, room, reports)
        if isinstance(failure, FetchResult):
            failure.nodes, failure.plan = reports, out["plan"]
            return failure
        # 3. face the target furniture (or search the likely surfaces)
        return self._face_target(plan, room, target, failure, dict(out, score_map=last_map))

    def _follow_nodes(self, plan, room: str, reports: list[NodeReport]):
        """Run each node; ``(target furniture or None, failure, last score map)``, where a
        failure is a :class:`FetchResult` when the fetch must end (a collision, the budget),
        else the last node's ``(status, message)`` or None."""
        target: Entity | None = None
        node_failure: tuple[ExecutionStatus, str] | None = None
        last_map = None
        for node in plan.nodes:
            report, chosen, score_map = self._run_node(node, room)
            reports.append(report)
            last_map = score_map or last_map
            self.ctx.event("node", report=report)
            if report.status == ExecutionStatus.SUCCESS.value:
                if chosen is not None:
                    target = chosen
            elif report.status in (ExecutionStatus.COLLISION.value, ExecutionStatus.TIMEOUT.value):
                return target, FetchResult(ExecutionStatus(report.status), f"node {report.rdt}: {report.message}",
                                           score_map=last_map), last_map
            else:
                node_failure = (ExecutionStatus(report.status), f"node {report.rdt}: {report.message}")
        return target, node_failure, last_map

    def _face_target(self, plan, room: str, target: Entity | None, node_failure, out: dict) -> FetchResult:
        recovered = False
        wanted = self._target_word(plan)
        if plan.nodes:
            self._said = Said.of(plan.nodes[-1])
        if target is None or not self._in_view(target):
            if target is None:
                candidates = self.chooser.likely_surfaces(room, wanted, self.ctx.pose(), self._said)
                if not candidates:
                    self.surveyor.better_view(room)
                    candidates = self.chooser.likely_surfaces(room, wanted, self.ctx.pose(), self._said)
                if not candidates and not plan.nodes and not getattr(plan, "object", None):
                    # "go to the hallway": there, with nothing to face
                    return FetchResult(ExecutionStatus.SUCCESS, f"in the {room}", details={"arrived": room}, **out)
                if not candidates:
                    status, message = node_failure or (
                        ExecutionStatus.REFERENCE_NOT_FOUND, f"no {wanted} was seen in the {room}")
                    return FetchResult(status, message, **out)
                target = candidates[0]
                recovered = True
        faced = self._face(target)
        info = {"id": target.id, "name": target.name, "centre": [round(v, 3) for v in entity_centre(target)]}
        if not faced.success:
            return FetchResult(faced.status, f"could not reach a view of the {target.name}: {faced.message}",
                               target_furniture=info, recovered=recovered, **out)
        if not self._in_view(target):
            return FetchResult(ExecutionStatus.NOT_VISIBLE, f"the {target.name} is not in view at the end",
                               target_furniture=info, recovered=recovered, **out)
        other = self._look_at_other_surfaces(plan, room, target, wanted)
        if other is not None:  # the object was not on the target but on another surface the plan allows
            target, recovered = other, True
            info = {"id": target.id, "name": target.name, "centre": [round(v, 3) for v in entity_centre(target)]}
        message = f"facing the {target.name} in the {room}"
        if recovered:
            message += " (found by searching the likely surfaces)"
        return FetchResult(ExecutionStatus.SUCCESS, message, target_furniture=info, recovered=recovered, **out)

    def _look_at_other_surfaces(self, plan, room: str, target: Entity, wanted: str) -> Entity | None:
        """When the object detector does not see the plan's object from the target, face the
        other surfaces the plan allows in the room, nearest first, until it does; the surface it
        is seen on, or None (the target stays)."""
        name = getattr(plan, "object", None)
        if self.object_detector is None or not name or self._detector_blind:
            return None
        before = self.ctx.seen.get(name)
        self._observe_here()
        now = self.ctx.seen.get(name)
        seen_on = self._seen_on(name, room, target)
        if (now is not before or before is not None and before.furniture_id == target.id) and (
                now.furniture_id in (None, target.id) or not seen_on):
            return None  # seen from here on the target (or on nothing the robot has mapped)
        if now is not before and self._by_target(now, target):
            # seen from here by the target, though put on the furniture beside it (the monitor on
            # the table by the bed, placed on the bed by the detector's cells): it is in view
            return None
        pose = self.ctx.pose()
        others = [e for e in self.chooser.likely_surfaces(room, wanted, pose, self._said) if e.id != target.id]
        if (found := self._look_where_seen(name, room, target)) is not None:
            return found
        for other in seen_on + nearest_first(others, pose)[:self.max_other_surfaces]:
            before = self.ctx.seen.get(name)
            if not self._face(other).success:
                continue
            self._observe_here()
            if self.ctx.seen.get(name) is not before and self._in_view(other):
                return other
        self._face(target)
        return None

    def _by_target(self, sighting, target: Entity) -> bool:
        """Whether a sighting lies by ``target``: within :attr:`by_target_m` of its cells."""
        cells = np.asarray(target.points_m(), dtype=float).reshape(-1, 2)
        if not len(cells):
            return False
        gap = np.hypot(cells[:, 0] - sighting.x_m, cells[:, 1] - sighting.y_m).min()
        return bool(gap <= self.by_target_m)

    def _look_where_seen(self, name: str, room: str, target: Entity) -> Entity | None:
        """When the object was seen in ``room`` (on the way, or in an earlier task) on no
        furniture the robot has mapped — seen from afar, the surface under it not yet
        perceived — go and look at that spot (:func:`~assistant.executor.viewing.point_viewing_spot`).
        Seen again there: the furniture it is seen on, or ``target`` when it lies on nothing
        found (the robot stays facing it); else None."""
        seen = self.ctx.seen.get(name)
        if seen is None or seen.furniture_id is not None or room_of(self.ctx.world, (seen.x_m, seen.y_m)) != room:
            return None
        spot = point_viewing_spot(self.ctx.obstacles.occupancy(), self.ctx.pose(), (seen.x_m, seen.y_m),
                                  self.spot_clearance_m)
        if spot is None or not self.ctx.go_to(spot, math.atan2(seen.y_m - spot[1], seen.x_m - spot[0])).success:
            return None
        self.ctx.face_point(seen.x_m, seen.y_m)
        self._observe_here()
        now = self.ctx.seen.get(name)
        if now is seen or now.furniture_id == target.id:
            return None
        # seen again from here: on the furniture found under it, or (none found) the robot stays
        # facing it with the plan's target as the furniture it reports
        return next((e for e in self.ctx.perception.furniture() if e.id == now.furniture_id), target)

    def _seen_on(self, name: str, room: str, target: Entity) -> list[Entity]:
        """The perceived furniture in ``room`` the object was last seen on, on the way here,
        when that is not ``target``: looked at first, before the other likely surfaces (any
        kind of furniture — it was seen there — not only the plan's)."""
        seen = self.ctx.seen.get(name)
        if seen is None or seen.furniture_id in (None, target.id):
            return []
        return [e for e in self.ctx.perception.furniture()
                if e.id == seen.furniture_id and entity_room(self.ctx.world, e) == room]

    # ------------------------------------------------------------------ nodes
    def _run_node(self, node, room: str):
        rdts = node.rdts
        if node.dynamic or (node.target == NO_TARGET and rdts[0].reference_kind == "furniture"):
            return spoken_node(self.ctx, self.chooser, node, room) or self._dynamic_node(rdts[0], room)
        report = NodeReport(str(node), "static", ExecutionStatus.REFERENCE_NOT_FOUND.value)
        # furniture references first: "between the two chairs" singles a table out better than
        # "across the room"; the other pairs still weigh in (PlaceChooser.agreement)
        rdts = sorted(rdts, key=lambda r: r.reference in PLACE_REFERENCES)
        # "on your right" keeps meaning this pose's right after a look elsewhere; with no room
        # named, the start pose's
        said_from = self._said_from or self.ctx.pose()
        self._said = Said.of(node)
        if not self._surveyed:  # a room too large to see from its door: look from further in first
            self._surveyed = True
            toward = next((t for t in (self._toward(r, said_from) for r in rdts) if t is not None), None)
            self.surveyor.survey(room, toward)
        self._look_for(room, [r.reference for r in rdts if r.reference not in PLACE_REFERENCES] + [node.target])
        looked_again = False
        for attempt in range(2):
            for rdt in rdts:
                report.tried.append([rdt.reference, rdt.direction])
                pair, looked_again = self._pair_for(rdt, rdts, room, said_from, looked_again)
                if pair is None:
                    continue
                moved, score_map = self._go_by_pair(rdt, pair, report)
                return report, pair[1] if moved.success else None, score_map
            if looked_again:
                break
            self.surveyor.better_view(room)
            looked_again = True
        wanted = " or ".join(sorted({r.reference for r in rdts if r.reference not in ("robot", "room")}))
        report.message = (f"no {wanted} with a {node.target} " if wanted else f"no {node.target} ") + f"seen in the {room}"
        return report, None, None

    def _pair_for(self, rdt, rdts, room: str, said_from: Pose2D, looked_again: bool):
        """The chosen (reference, target, fit) for ``rdt`` (or None) and whether the robot has
        now looked again: when nothing fits well, or not what was said ("the desk"), it moves
        for a better view once before it commits; when perception is unsure of the reference or
        target (attribute ``unsure``), it first looks at that item again from another pose."""
        others = [r for r in rdts if r is not rdt]
        pair = self.chooser.choose_pair(rdt, room, said_from, others, self._said)
        if pair is None:
            return None, looked_again
        doubtful = [e for e in pair[:2] if e is not None and e.attributes.get("unsure")]
        unsure = pair[2] < self.weak_fit or self._said.fit(pair[1]) < self.weak_description
        if (unsure or doubtful) and not looked_again:
            if not (doubtful and self.surveyor.look_again_at(doubtful[0], self.standoff_m)):
                self.surveyor.better_view(room, self._toward(rdt, said_from))
            looked_again = True
            pair = self.chooser.choose_pair(rdt, room, said_from, others, self._said) or pair
        return pair, looked_again

    def _go_by_pair(self, rdt, pair, report: NodeReport):
        """Drive to the policy's move-to pose for the chosen pair; near the target instead when
        that pose is unreachable or the robot bumped on the way."""
        reference, target, _ = pair
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
        return moved, score_map

    def _look_for(self, room: str, words) -> None:
        """While some furniture the node names (``words``: reference and target words) is not
        seen in ``room``, look again from further in (:meth:`_survey` with
        :attr:`reference_range_m`), at most :attr:`max_looks_for_reference` times."""
        words = sorted({w for w in words if w and w != NO_TARGET})
        for _ in range(self.max_looks_for_reference):
            if all(self.chooser.in_room(room, w) for w in words):
                return
            if not self.surveyor.survey(room, max_unseen_share=0.05, range_m=self.reference_range_m):
                return

    def _dynamic_node(self, rdt, room: str):
        report = NodeReport(str(rdt), "dynamic", ExecutionStatus.SUCCESS.value)
        report.tried.append([rdt.reference, rdt.direction])
        reference = None
        here = room_of(self.ctx.world, self.ctx.pose()) or room
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
        pose = self.ctx.pose()
        landmark = [reference] if is_landmark(reference) else []  # an object seen: "next to the keys"
        env = environment_items(self.ctx.world, self.ctx.perception.furniture() + landmark)
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
            except (UnknownNameError, NotFittedError) as error:  # no model, unknown entity: geometry
                report.model = f"none ({type(error).__name__}: {error})"
        if goal is None:
            goal = self._geometric_goal(rdt, pose, target)
            report.model = report.model or "geometric"
        report.move_to = [round(goal.x, 3), round(goal.y, 3), round(goal.theta, 4)]
        self.ctx.event("move_to", rdt=rdt, goal=goal, score_map=score_map)
        return self.ctx.go_to((goal.x, goal.y), goal.theta), score_map

    @staticmethod
    def _geometric_goal(rdt: str, pose: Pose2D, target) -> Pose2D:
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
        pose = self.ctx.pose()
        env = [e for e in environment_items(self.ctx.world, ()) if e.id.startswith("wall:") and e.room == room]
        for step in np.arange(0.1, 12.0, 0.1):
            p = np.array([[pose.x + step * math.cos(pose.theta), pose.y + step * math.sin(pose.theta)]])
            for item in env:
                if point_in_polygon(p, item.polygon_array())[0]:
                    return item.id
        return None

    @staticmethod
    def _target_word(plan) -> str:
        if plan.nodes:
            return plan.nodes[-1].target if plan.nodes[-1].target != NO_TARGET else "table"
        return "table"

    @staticmethod
    def _toward(rdt, said_from: Pose2D) -> tuple[float, float] | None:
        """Where to look from when the robot itself is the reference ("on your right", or an
        unreferenced target after some steps): a few metres that way from where it was said."""
        if rdt.reference_kind == "furniture":
            return None
        angles = WALL_ANGLES if rdt.reference == "wall" else DIRECTION_ANGLES
        turn = angles.get(rdt.direction, 0.0) / 2  # that side and ahead: the room lies ahead
        heading = said_from.theta + turn
        return (said_from.x + 4.0 * math.cos(heading), said_from.y + 4.0 * math.sin(heading))

    # ------------------------------------------------------------------ facing the target
    def _in_view(self, target: Entity) -> bool:
        return in_view(target, self.ctx.pose(), self.ctx.perception.furniture(), self.view_distance_m)

    def _face(self, target: Entity) -> ExecutionResult:
        """Drive to a viewing pose of ``target`` (if not already there) and turn to it."""
        ctx = self.ctx
        cx, cy = entity_centre(target)
        if not self._in_view(target):
            last = None
            goals = viewing_poses(ctx.world, target, ctx.pose(), ctx.obstacles.occupancy(),
                                  ctx.perception.furniture(), self.standoff_m)
            for goal in goals[:4]:
                last = ctx.go_to(goal[:2], goal[2])
                if last.success:
                    break
                if not self._recover_from_bump(last):
                    break
                if self._in_view(target):  # backed off with the target in view: close enough
                    last = ExecutionResult.ok("backed off after a bump, the target in view", final_pose=ctx.pose())
                    break
            if last is not None and not last.success:
                return last
        turned = ctx.face_point(cx, cy)
        self._observe_here()
        return turned

    def _recover_from_bump(self, result: ExecutionResult) -> bool:
        """After a bump (``result`` a collision with ``bumped``): back off a little and say
        True so the caller tries another way; False for any other result, or when backing
        off bumped too (boxed in: the collision stands)."""
        if result.status is not ExecutionStatus.COLLISION or not result.details.get("bumped"):
            return False
        backed = self.ctx.back_off()
        self._observe_here()  # what it touched may now be in view
        return backed.success


__all__ = ["FETCH_BUDGET_S", "FetchResult", "FetchTask", "NodeReport"]

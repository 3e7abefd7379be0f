"""Carrying out commands as people say them (issue 16): no room named, counted steps, turns by
angle, "stop", passing furniture.

* :func:`room_from_here` — a command that names no room is carried out from where the robot is:
  the room it stands in, unless that is a passage (a hallway, :data:`PASSAGE_WORDS`, or narrower
  than :data:`PASSAGE_WIDTH_M`: no furniture of a plan stands there), else the room it faces through
  the nearest opening — on the side the command says ("the mug is on the table to your left"),
  or the most nearly ahead.
* :func:`amount_goal` — a move with a distance ("take two steps forward": 1.2 m, a step being
  :data:`~assistant.grounding.amounts.STEP_M`) or a turn with an angle ("turn left 90 degrees")
  as a pose to drive to, from the robot's pose.
* :func:`passing_goal` — "pass the couch": a pose on the couch's far side, seen from the robot.
* :func:`run_moves` — a command of moves alone ("turn around", "back up a little";
  :func:`~assistant.grounding.motion.is_motion_plan`), carried out where the robot is.
"""

from __future__ import annotations

import math

import numpy as np

from assistant.executor.outcome import ExecutionStatus
from assistant.executor.reports import NodeReport
from assistant.executor.sensing import entity_centre
from assistant.geometry import Pose2D, wrap_angle
from assistant.grounding.motion import describe_motion, reverses
from assistant.rdt import NO_TARGET

__all__ = ["PASSAGE_WIDTH_M", "amount_goal", "nearest_first", "passing_goal", "room_from_here", "run_moves",
           "said_side", "spoken_node"]

#: a room narrower than this (metres, its bounding box's short side) is a passage
PASSAGE_WIDTH_M = 1.6
#: words of a room's name that make it a passage (a hallway, an inner hall, a corridor)
PASSAGE_WORDS = ("hall", "corridor", "entry", "landing", "passage", "foyer")
#: sides of a move, radians counter-clockwise from the robot's heading
SIDE_ANGLES = {"front": 0.0, "left": math.pi / 2, "right": -math.pi / 2, "back": math.pi}
#: how far past a passed piece of furniture the robot stops (metres beyond its far edge)
PAST_MARGIN_M = 0.6


def said_side(plan) -> str | None:
    """The listener's side the plan says first ("to your left": a ``robot`` pair, or a first
    move "turn left"), or None."""
    for node in plan.nodes:
        for reference, direction in node.pairs:
            if reference in ("robot", "move") and direction in ("left", "right"):
                return direction
    return None


def _is_passage(room) -> bool:
    if any(word in room.name.lower() for word in PASSAGE_WORDS):
        return True
    xs = [p[0] for p in room.polygon]
    ys = [p[1] for p in room.polygon]
    return min(max(xs) - min(xs), max(ys) - min(ys)) < PASSAGE_WIDTH_M


def room_from_here(world, pose: Pose2D, plan) -> str | None:
    """The room a command that names none is carried out in (module doc); None when the robot
    stands in no room and none is joined to where it is."""
    floor = world.floorplan
    here = floor.room_at(pose.x, pose.y)
    side = said_side(plan)
    if here is not None and not _is_passage(here):
        return here.name
    if here is None:
        return None
    return floor.room_faced(pose, side) or floor.room_faced(pose) or here.name


def amount_goal(pose: Pose2D, direction: str, distance_m: float | None, degrees: float | None) -> Pose2D:
    """Where a counted move or a turn by an angle ends (heading in radians): a turn turns on the
    spot to the side said (``degrees``, default 90), a distance goes that far to the side said
    keeping the heading for a side step, turning to face a move ahead or back."""
    if degrees is not None and distance_m is None:
        sign = -1.0 if direction == "right" else 1.0 if direction == "left" else 0.0
        return Pose2D(pose.x, pose.y, wrap_angle(pose.theta + sign * math.radians(degrees)))
    angle = wrap_angle(pose.theta + SIDE_ANGLES.get(direction, 0.0))
    d = distance_m or 0.0
    heading = pose.theta if direction in ("left", "right") else angle
    if degrees is not None:  # "a 45 degree angle to the right for 2 steps"
        sign = -1.0 if direction == "right" else 1.0
        angle = heading = wrap_angle(pose.theta + sign * math.radians(degrees))
    return Pose2D(pose.x + d * math.cos(angle), pose.y + d * math.sin(angle), heading)


#: how near a counted move's end may come to a wall or furniture (metres, besides the robot's own
#: clearance), and the least way worth driving when the full way is blocked
STOP_SHORT_M = 0.15
LEAST_MOVE_M = 0.2


def free_part(occupancy, pose: Pose2D, goal: Pose2D, step_m: float = 0.05) -> tuple[Pose2D, float | None]:
    """The goal of a counted move, or — when the straight way to it leaves the free floor of the
    map (a wall, known furniture, the map's edge) — the farthest free point on that way, kept
    ``STOP_SHORT_M`` back, with the metres it goes (None when the whole way is free). A way
    blocked at once gives the goal itself (the move then fails and says why)."""
    length = math.hypot(goal.x - pose.x, goal.y - pose.y)
    if length < step_m:
        return goal, None
    ux, uy = (goal.x - pose.x) / length, (goal.y - pose.y) / length
    along = np.arange(step_m, length + step_m / 2, step_m)
    points = np.column_stack([pose.x + ux * along, pose.y + uy * along])
    need = occupancy.robot_radius_m + occupancy.margin_m
    free = occupancy.clearance_at(points) >= need
    if free.all():
        return goal, None
    reach = float(along[np.argmin(free)] - step_m - STOP_SHORT_M) if free[0] else 0.0
    if reach < LEAST_MOVE_M:
        return goal, None
    return Pose2D(pose.x + ux * reach, pose.y + uy * reach, goal.theta), reach


def passing_goal(pose: Pose2D, centre: tuple[float, float], extent_m: float) -> Pose2D:
    """A pose just past furniture centred at ``centre`` (its largest extent ``extent_m``), on
    the far side from ``pose``, facing on in the same direction."""
    dx, dy = centre[0] - pose.x, centre[1] - pose.y
    dist = math.hypot(dx, dy) or 1.0
    ux, uy = dx / dist, dy / dist
    reach = extent_m / 2 + PAST_MARGIN_M
    return Pose2D(centre[0] + ux * reach, centre[1] + uy * reach, math.atan2(uy, ux))


def spoken_node(ctx, chooser, node, room: str):
    """Carry out a node said the way people move a robot: stop, a counted move or a turn by an
    angle, passing furniture. ``(report, None, None)`` as the fetch task's nodes give, or None
    for any other node."""
    rdt = node.rdts[0]
    if rdt.reference == "stop":
        return NodeReport(str(rdt), "dynamic", ExecutionStatus.SUCCESS.value, message="stopped here"), None, None
    pose = ctx.pose()
    report = NodeReport(str(rdt), "dynamic", ExecutionStatus.SUCCESS.value)
    if rdt.reference == "move" and (node.distance_m is not None or node.degrees is not None):
        goal = amount_goal(pose, rdt.direction, node.distance_m, node.degrees)
        turn_only = node.distance_m is None
    elif node.target == NO_TARGET and rdt.reference_kind == "furniture":  # "pass the couch"
        seen = sorted(chooser.in_room(room, rdt.reference), key=lambda e: math.dist(entity_centre(e), (pose.x, pose.y)))
        if not seen:
            report.message = f"skipped (no {rdt.reference} seen to pass)"
            return report, None, None
        extent = float(np.ptp(seen[0].points_m(), axis=0).max())
        goal, turn_only = passing_goal(pose, entity_centre(seen[0]), extent), False
    else:
        return None
    report.move_to = [round(goal.x, 3), round(goal.y, 3), round(goal.theta, 4)]
    moved = ctx.turn_to(goal.theta) if turn_only else ctx.go_to((goal.x, goal.y), goal.theta)
    report.status, report.message = moved.status.value, moved.message
    if moved.status is ExecutionStatus.NO_PATH:  # those steps cannot be taken here: stay, go on
        report.status, report.message = ExecutionStatus.SUCCESS.value, f"skipped ({moved.message})"
    return report, None, None


def nearest_first(entities, pose: Pose2D) -> list:
    """``entities`` ordered by the distance of their centres from ``pose``."""
    return sorted(entities, key=lambda e: math.dist(entity_centre(e), (pose.x, pose.y)))


def run_moves(ctx, plan, reports: list[NodeReport]) -> tuple[ExecutionStatus, str]:
    """Carry out a plan of moves alone from where the robot is, node by node (a short move back
    reverses, :func:`~assistant.grounding.motion.reverses`; the rest as :func:`amount_goal`
    says); ``(status, message)`` — the first node that could not be carried out ends it."""
    shortfalls: list[str] = []  # moves cut short by a wall or furniture ("only 2.1 m of the 3.0 m")
    for node in plan.nodes:
        rdt = node.rdts[0]
        short_m = None
        report = NodeReport(str(rdt), "dynamic", ExecutionStatus.SUCCESS.value)
        reports.append(report)
        if reverses(node):
            moved = ctx.back_off(node.distance_m)
        else:
            pose = ctx.pose()
            goal = amount_goal(pose, rdt.direction, node.distance_m, node.degrees)
            if node.distance_m is not None:  # "go forward three meters" towards a wall 2 m away: as far as it can
                goal, short_m = free_part(ctx.obstacles.occupancy(), pose, goal)
            report.move_to = [round(goal.x, 3), round(goal.y, 3), round(goal.theta, 4)]
            moved = ctx.turn_to(goal.theta) if node.distance_m is None else ctx.go_to((goal.x, goal.y), goal.theta)
            if short_m is not None and moved.status is ExecutionStatus.SUCCESS:
                shortfalls.append(f"only {short_m:.1f} m of the {node.distance_m:.1f} m")
        report.status, report.message = moved.status.value, moved.message
        if short_m is not None and moved.status is ExecutionStatus.SUCCESS:  # this node's own shortfall
            report.message = f"{shortfalls[-1]}: a wall or furniture is in the way"
        ctx.event("node", report=report)
        if moved.status is not ExecutionStatus.SUCCESS:
            said = describe_motion([node])
            return moved.status, f"could not finish {said}: {moved.message}"
    done = describe_motion(plan.nodes, done=True)
    if shortfalls:
        return ExecutionStatus.SUCCESS, f"{done} ({'; '.join(shortfalls)}: a wall or furniture was in the way)"
    return ExecutionStatus.SUCCESS, done

"""The teacher's rules: where a person would drive the robot for each RDT of Table 5-1.

The dissertation's teacher drove the robot by keyboard to where the command meant (5.5.2).
These rules write down the choices our scripted teacher makes, from the environment model
(furniture footprints with their fronts, rooms, walls) and the robot's pose when the node
begins. The same rules give the *expected pose* of ``assistant eval policy`` in a test layout.

* Standing at a table ("approach"): the robot's centre 0.5 m out from the table's edge (its
  body 0.25 m from it), facing the table's centre, on a chosen side; when that spot is not free
  the teacher walks round the table in 15° steps, nearer side first.
* ``move-front-non``: 1.0 m straight ahead (less if a wall or furniture is closer; ≥ 0.3 m).
* ``move-left-non`` / ``move-right-non``: turn 90° left / right, then advance 0.5 m.
* ``robot-left-table`` / ``robot-right-table``: the table (in the robot's room) whose bearing
  from the robot is nearest 90° to the left / right (within 30°–150°); stand at it on the side
  facing the robot's start.
* ``<furniture>-left-table`` / ``-right-table`` (bed, couch): the nearest table on the
  reference's own left / right (its intrinsic frame: left = front + 90°) beside it, and stand at
  it on the reference's front side (the side one faces when sitting or lying on it).
* ``<furniture>-front-table`` (couch): the nearest table in front of the reference (within its
  width, 0.3–2.5 m out); stand at it on the side away from the reference, facing it (so the
  robot faces the table and the couch).
* ``<furniture>-beside-table`` (chair): the table nearest the chair (within 1.2 m, edge to
  edge); stand at the table as near the chair as is free, on the chair's left-hand side (as
  one sits on it) when both sides are free — our teacher's habit, so that the choice between
  the two sides is one the robot can see.
* ``room-center-non``: the centre of the robot's room (if it is a hallway, the nearest other
  room), facing the way the robot drove there.
* ``wall-front-non``: the wall straight ahead of the robot, in its room; stand 0.7 m from the
  wall's face where the robot's line of sight meets it, facing it squarely (no instance when
  furniture stands there: the teacher would not give the command).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from assistant.errors import AssistantError
from assistant.geometry import Pose2D, angle_difference, point_in_polygon, wrap_angle
from assistant.policy.demonstration import EnvironmentEntity
from assistant.policy.freespace import FreeSpace
from assistant.policy.rdt import RDT, parse_rdt
from assistant.world import load_catalogue

STANDOFF_M = 0.5      # robot centre to a table's edge when standing at it
WALL_STANDOFF_M = 0.7  # robot centre to a wall's face
CLEARANCE_M = 0.3     # a teacher's goal keeps the robot's centre this far from obstacles
HALLWAY_WORDS = ("hallway", "corridor", "hall")


class NoInstanceError(AssistantError):
    """The layout has no instance of an RDT for this start pose."""


@dataclass(frozen=True)
class TeacherGoal:
    """What the teacher chose: the reference and target entity ids (None when none) and the
    pose to drive to."""

    rdt: str
    reference_id: str | None
    target_id: str | None
    goal: Pose2D


def _centre(item: EnvironmentEntity) -> np.ndarray:
    return item.polygon_array().mean(axis=0)


def _of_word(environment, word: str) -> list[EnvironmentEntity]:
    cats = load_catalogue().categories_of(word) or (word,)
    return [e for e in environment if e.kind == "short_term" and (e.category in cats or e.name == word)]


def _local(origin: np.ndarray, heading: float, point: np.ndarray) -> tuple[float, float]:
    """(front, left) coordinates of ``point`` in a frame at ``origin`` facing ``heading``."""
    d = point - origin
    c, s = math.cos(heading), math.sin(heading)
    return float(c * d[0] + s * d[1]), float(-s * d[0] + c * d[1])


def _extent(poly: np.ndarray, heading: float) -> float:
    """Half-extent of a polygon along ``heading`` from its vertex mean."""
    u = np.array([math.cos(heading), math.sin(heading)])
    return float(((poly - poly.mean(axis=0)) @ u).max())


def approach(item: EnvironmentEntity, side_rad: float, free: FreeSpace,
             standoff_m: float = STANDOFF_M, prefer_xy=None) -> Pose2D:
    """Stand at ``item`` on the side ``side_rad`` (direction from its centre), facing it;
    when that spot is taken, turn round the table in 15° steps, first towards ``prefer_xy``
    (if given) at each step."""
    poly = item.polygon_array()
    c = poly.mean(axis=0)
    # first floor the robot can drive to with a margin, then with none, then any free spot
    tests = (lambda x, y: free.is_reachable(x, y, CLEARANCE_M),
             lambda x, y: free.is_reachable(x, y, 0.26),
             lambda x, y: free.is_free(x, y, 0.26))
    for test in tests:
        for k in range(0, 13):
            signs = (1,) if k == 0 or k == 12 else (1, -1)
            if prefer_xy is not None and len(signs) == 2:
                def spot(sg):
                    a = side_rad + sg * math.radians(15 * k)
                    return c + (_extent(poly, a) + standoff_m) * np.array([math.cos(a), math.sin(a)])
                signs = tuple(sorted(signs, key=lambda sg: float(np.linalg.norm(spot(sg) - prefer_xy))))
            for sign in signs:
                a = wrap_angle(side_rad + sign * math.radians(15 * k))
                r = _extent(poly, a) + standoff_m
                p = c + r * np.array([math.cos(a), math.sin(a)])
                if test(p[0], p[1]):
                    return Pose2D(float(p[0]), float(p[1]), wrap_angle(a + math.pi))
    raise NoInstanceError(f"no free floor around {item.id} to stand at")


def _advance(free: FreeSpace, pose: Pose2D, heading: float, distance: float, minimum: float) -> Pose2D:
    u = np.array([math.cos(heading), math.sin(heading)])
    d = distance
    while d >= minimum - 1e-9:
        p = np.array([pose.x, pose.y]) + d * u
        if free.segment_free((pose.x, pose.y), p, CLEARANCE_M):
            return Pose2D(float(p[0]), float(p[1]), heading)
        d -= 0.1
    raise NoInstanceError(f"less than {minimum:.1f} m of free floor in that direction")


def _room_of(free: FreeSpace, x: float, y: float) -> str | None:
    return free.room_at(x, y)


def teacher_goal(rdt: str | RDT, environment, start: Pose2D, free: FreeSpace | None = None,
                 instance: int = 0) -> TeacherGoal:
    """The teacher's reference, target and goal pose for ``rdt`` from ``start``.

    ``instance`` picks among several qualifying references (e.g. which chair), cycling."""
    rdt = parse_rdt(rdt)
    env = tuple(environment)
    free = free or FreeSpace(env)
    if rdt.reference_kind == "robot" and not rdt.has_target:
        return _robot_move_goal(rdt, start, free)
    if rdt.reference_kind == "robot":  # robot-left-table, robot-right-table
        return _robot_side_goal(rdt, env, start, free)
    if rdt.reference_kind == "room":
        return _room_centre_goal(rdt, env, start, free)
    if rdt.reference_kind == "wall":
        return _wall_goal(rdt, env, start, free)
    return _furniture_goal(rdt, env, start, free, instance)


def _robot_move_goal(rdt: RDT, start: Pose2D, free: FreeSpace) -> TeacherGoal:
    """move-front-non: a metre ahead; move-left/right/back-non: turn, then half a metre on."""
    if rdt.direction in ("front", "forward"):
        return TeacherGoal(rdt.name, None, None, _advance(free, start, start.theta, 1.0, 0.3))
    turn = {"left": math.pi / 2, "right": -math.pi / 2, "back": math.pi}.get(rdt.direction)
    if turn is None:
        raise NoInstanceError(f"no teacher rule for {rdt.name}")
    heading = wrap_angle(start.theta + turn)
    try:
        goal = _advance(free, start, heading, 0.5, 0.2)
    except NoInstanceError:
        goal = Pose2D(start.x, start.y, heading)
    return TeacherGoal(rdt.name, None, None, goal)


def _robot_side_goal(rdt: RDT, env, start: Pose2D, free: FreeSpace) -> TeacherGoal:
    """robot-left-table: the target of the word on that side of the robot in its room (within
    60°, the least off and nearest), approached from the robot's side."""
    want = {"left": math.pi / 2, "right": -math.pi / 2, "front": 0.0, "back": math.pi}[rdt.direction]
    start_xy = np.array([start.x, start.y])
    room = _room_of(free, start.x, start.y)
    best, best_cost = None, math.inf
    for item in _of_word(env, rdt.target):
        if room is not None and item.room not in (None, room):
            continue
        c = _centre(item)
        bearing = angle_difference(math.atan2(c[1] - start.y, c[0] - start.x), start.theta)
        off = abs(angle_difference(bearing, want))
        if off > math.radians(60):
            continue
        cost = off + 0.1 * float(np.linalg.norm(c - start_xy))
        if cost < best_cost:
            best, best_cost = item, cost
    if best is None:
        raise NoInstanceError(f"no {rdt.target} on the robot's {rdt.direction} in its room")
    c = _centre(best)
    side = math.atan2(start.y - c[1], start.x - c[0])
    return TeacherGoal(rdt.name, None, best.id, approach(best, side, free))


def _room_centre_goal(rdt: RDT, env, start: Pose2D, free: FreeSpace) -> TeacherGoal:
    """room-center-non: the free floor nearest the centre of the robot's room (from a hallway,
    the nearest named room)."""
    start_xy = np.array([start.x, start.y])
    room = _room_of(free, start.x, start.y)
    rooms = {e.room: e for e in env if e.id.startswith("room:")}
    if room is None or any(w in room.lower() for w in HALLWAY_WORDS):
        named = [r for r in rooms if not any(w in r.lower() for w in HALLWAY_WORDS)]
        if not named:
            raise NoInstanceError("no room to go to the centre of")
        room = min(named, key=lambda r: np.linalg.norm(_centre(rooms[r]) - start_xy))
    item = rooms[room]
    p = _nearest_free(free, _centre(item))
    heading = math.atan2(p[1] - start.y, p[0] - start.x) if np.linalg.norm(p - start_xy) > 0.3 else start.theta
    return TeacherGoal(rdt.name, item.id, None, Pose2D(float(p[0]), float(p[1]), heading))


def _wall_goal(rdt: RDT, env, start: Pose2D, free: FreeSpace) -> TeacherGoal:
    """wall-front-non: facing the wall straight ahead, ``WALL_STANDOFF_M`` from its face."""
    start_xy = np.array([start.x, start.y])
    room = _room_of(free, start.x, start.y)
    walls = [e for e in env if e.id.startswith("wall:") and (room is None or e.room == room)]
    u = np.array([math.cos(start.theta), math.sin(start.theta)])
    hit_item, hit_d = None, math.inf
    for step in np.arange(0.05, 15.0, 0.05):
        p = start_xy + step * u
        for item in walls:
            if point_in_polygon(p[None], item.polygon_array())[0]:
                hit_item, hit_d = item, step
                break
        if hit_item is not None or (free.clearance(p[None])[0] == 0 and not walls):
            break
    if hit_item is None:
        raise NoInstanceError("no wall straight ahead of the robot in its room")
    poly = hit_item.polygon_array()
    lo, hi = poly.min(axis=0), poly.max(axis=0)
    size = hi - lo
    hit = start_xy + hit_d * u
    if size[0] >= size[1]:  # wall along x: face it along ±y
        normal = np.array([0.0, 1.0 if u[1] > 0 else -1.0])
        face = lo[1] if normal[1] > 0 else hi[1]
        p = np.array([hit[0], face - normal[1] * WALL_STANDOFF_M])
    else:
        normal = np.array([1.0 if u[0] > 0 else -1.0, 0.0])
        face = lo[0] if normal[0] > 0 else hi[0]
        p = np.array([face - normal[0] * WALL_STANDOFF_M, hit[1]])
    q = _nearest_free(free, p)
    if np.linalg.norm(q - p) > 0.3:
        raise NoInstanceError("furniture stands between the robot and the wall ahead")
    return TeacherGoal(rdt.name, hit_item.id, None, Pose2D(float(q[0]), float(q[1]),
                                                           math.atan2(normal[1], normal[0])))


def _furniture_goal(rdt: RDT, env, start: Pose2D, free: FreeSpace, instance: int) -> TeacherGoal:
    """couch-front-table and the like: the ``instance``-th (reference, target) pair, the target
    approached from the reference's side named by the direction."""
    choices = []
    for ref in _of_word(env, rdt.reference):
        tar = _furniture_target(rdt, ref, env)
        if tar is not None:
            choices.append((ref, tar))
    if not choices:
        raise NoInstanceError(f"no {rdt.target} {rdt.direction} of a {rdt.reference} in this layout")
    ref, tar = choices[instance % len(choices)]
    rc, tc = _centre(ref), _centre(tar)
    if rdt.direction == "front":
        side = ref.orientation if ref.orientation is not None else math.atan2(tc[1] - rc[1], tc[0] - rc[0])
    elif rdt.direction in ("left", "right"):
        side = ref.orientation if ref.orientation is not None else math.atan2(start.y - tc[1], start.x - tc[0])
    else:  # beside: at the table next to the chair, on the chair's left-hand side
        side = math.atan2(rc[1] - tc[1], rc[0] - tc[0])
        facing = ref.orientation if ref.orientation is not None else side + math.pi
        left = rc + np.array([math.cos(facing + math.pi / 2), math.sin(facing + math.pi / 2)])
        return TeacherGoal(rdt.name, ref.id, tar.id, approach(tar, side, free, prefer_xy=left))
    return TeacherGoal(rdt.name, ref.id, tar.id, approach(tar, side, free))


def _furniture_target(rdt: RDT, ref: EnvironmentEntity, env) -> EnvironmentEntity | None:
    rpoly = ref.polygon_array()
    rc = rpoly.mean(axis=0)
    facing = ref.orientation
    best, best_d = None, math.inf
    for item in _of_word(env, rdt.target):
        if item.id == ref.id or (ref.room and item.room and item.room != ref.room):
            continue
        c = _centre(item)
        d = float(np.linalg.norm(c - rc))
        if rdt.direction == "beside":
            gap = _polygon_gap(rpoly, item.polygon_array())
            if gap > 1.2:
                continue
            d = gap
        else:
            if facing is None:
                continue
            front, left = _local(rc, facing, c)
            half_len = _extent(rpoly, facing + math.pi / 2)  # half the reference's width across its front
            half_depth = _extent(rpoly, facing)
            if rdt.direction == "front":
                if not (half_depth + 0.3 <= front <= half_depth + 2.5 and abs(left) <= half_len):
                    continue
            elif rdt.direction in ("left", "right"):
                side = left if rdt.direction == "left" else -left
                if not (side > half_len and abs(front) <= half_depth + 0.6 and side < half_len + 2.0):
                    continue
            else:
                continue
        if d < best_d:
            best, best_d = item, d
    return best


def _polygon_gap(a: np.ndarray, b: np.ndarray) -> float:
    """Approximate edge-to-edge distance of two polygons (metres), from densely sampled edges."""
    def sample(p):
        q = np.roll(p, -1, axis=0)
        t = np.linspace(0, 1, 20, endpoint=False)
        return (p[:, None, :] + t[None, :, None] * (q - p)[:, None, :]).reshape(-1, 2)
    sa, sb = sample(a), sample(b)
    if point_in_polygon(sa, b).any() or point_in_polygon(sb, a).any():
        return 0.0
    return float(np.sqrt(((sa[:, None, :] - sb[None, :, :]) ** 2).sum(-1)).min())


def _nearest_free(free: FreeSpace, p: np.ndarray, clearance: float = CLEARANCE_M) -> np.ndarray:
    if free.is_reachable(p[0], p[1], clearance):
        return np.asarray(p, float)
    for r in np.arange(0.05, 2.0, 0.05):
        for a in np.linspace(0, 2 * math.pi, 24, endpoint=False):
            q = p + r * np.array([math.cos(a), math.sin(a)])
            if free.is_reachable(q[0], q[1], clearance):
                return q
    raise NoInstanceError(f"no free floor near ({p[0]:.2f}, {p[1]:.2f})")


def sample_start(rdt: str | RDT, environment, free: FreeSpace, rng: np.random.Generator,
                 instance: int = 0, min_distance_m: float = 1.5, max_tries: int = 2000,
                 heading_rad: float | None = None) -> tuple[Pose2D, TeacherGoal]:
    """A random start pose for ``rdt`` (free floor, random heading) whose teacher goal exists
    and lies at least ``min_distance_m`` away (for the robot-relative moves: any free pose
    with room to move). Rooms and walls: starts inside a room, not a hallway. ``heading_rad``
    fixes the start heading (a teacher spreading the starts over all directions)."""
    rdt = parse_rdt(rdt)
    rooms = {e.room: e.polygon_array() for e in environment if e.id.startswith("room:")}
    names = sorted(rooms)
    if rdt.reference_kind in ("room", "wall") or rdt.reference_kind == "robot":
        names = [n for n in names if not any(w in n.lower() for w in HALLWAY_WORDS)] or names
    for _ in range(max_tries):
        room = names[int(rng.integers(len(names)))]
        poly = rooms[room]
        lo, hi = poly.min(axis=0), poly.max(axis=0)
        p = lo + rng.random(2) * (hi - lo)
        if not point_in_polygon(p[None], poly)[0] or not free.is_free(p[0], p[1], 0.4):
            continue
        heading = float(rng.uniform(-math.pi, math.pi)) if heading_rad is None else float(heading_rad)
        start = Pose2D(float(p[0]), float(p[1]), heading)
        try:
            goal = teacher_goal(rdt, environment, start, free, instance)
        except NoInstanceError:
            continue
        dist = math.hypot(goal.goal.x - start.x, goal.goal.y - start.y)
        if rdt.reference_kind == "robot" and not rdt.has_target:
            if rdt.direction == "front" and dist < 0.95:
                continue
            if rdt.direction in ("left", "right") and dist < 0.45:
                continue
            return start, goal
        if dist >= min_distance_m:
            return start, goal
    raise NoInstanceError(f"found no start pose for {rdt.name} in {max_tries} tries")

"""What "the table in front of the couch" means here: the one place that reads an RDT.

:func:`resolve` ranks the perceived furniture that could be the target of an RDT (and the
reference it is read from), for the executor choosing where to go; :func:`relation_fit` scores
one (reference, target) pair, for the executor and for the describer checking what it says.
Both read furniture relations through the spatial relation variables of dissertation 5.4.2:

* **direction** — the DIR-SRV weight of the RDT's direction (:func:`direction_weight`): the
  histogram of forces of the target around the reference, read in the reference's frame (its
  front when it has one, the viewer's otherwise: "in front of the table" is the side towards
  the person speaking). The robot as a reference ("the table on your left") is a disc at the
  viewer pose facing its heading (:meth:`~assistant.world.Entity.robot`).
* **distance** — the DIST-SRV (:func:`nearness`): the expected ``exp(-d / 2.5 m)`` over its four
  distance words, so a target next to the reference beats one across the room.
* **beside / between** — the DIST-SRV's ``superposition`` and ``near`` (:func:`closeness`),
  for ``between`` also a second item of the reference's kind close to the target.

A reference is read as the item it is (:func:`~assistant.world.entity.as_item`): where perception fused two items into
one track, the cells beyond what the catalogue's largest model of that category can reach from
the detected centre are left out, so "in front of the couch" is not read from the other couch of
an L.

Relations to the floor plan are geometry, not SRVs: a room's side ("at the back of the room":
how far along the room's extent, :func:`room_side_fit`), a wall ("against the left wall",
:func:`wall_fit`), and a target named with no reference (the one most in view,
:func:`view_fit`). Every fit is in (0, 1]; ties go to what the viewer sees best.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from assistant.geometry import Pose2D, wrap_angle
from assistant.rdt import RDT
from assistant.spatial.srv import DIST_CENTRES_M, DistSRV, dir_srv, dist_srv
from assistant.world.entity import Entity, as_item

__all__ = [
    "DIRECTION_ANGLES", "Resolution", "closeness", "direction_weight", "nearness",
    "relation_fit", "resolve", "room_side_fit", "strongest_direction", "view_fit", "wall_fit",
]

#: a direction word → its angle from the viewer's heading (radians, counter-clockwise)
DIRECTION_ANGLES = {"front": 0.0, "left": math.pi / 2, "back": math.pi, "right": -math.pi / 2}
#: for a wall: "the front wall" is the one ahead, as is "the back wall" as one walks in
WALL_ANGLES = {"front": 0.0, "back": 0.0, "left": math.pi / 2, "right": -math.pi / 2}
#: the floor of every fit, so that one weak relation cannot veto a target outright
FLOOR = 0.05
#: metres: the scale of nearness (exp(-d / NEAR_SCALE_M))
NEAR_SCALE_M = 2.5
#: metres: how far from a wall a target still stands "against" it (exp(-gap / WALL_SCALE_M))
WALL_SCALE_M = 0.3
#: the share of the node's other relations a target must also fit (0.3 + 0.7 · share)
AGREEMENT_FLOOR = 0.3

_NEAR_WEIGHTS = np.exp(-np.asarray(DIST_CENTRES_M) / NEAR_SCALE_M)


@dataclass(frozen=True)
class Resolution:
    """One reading of an RDT: the ``reference`` it is read from (None for the robot, the room or
    a wall), the ``target`` entity, and how well they fit it (``fit`` in (0, 1])."""

    reference: Entity | None
    target: Entity
    fit: float


# ----------------------------------------------------------------------------- SRV readings

def nearness(dist: DistSRV) -> float:
    """In (0, 1]: the expected ``exp(-d / 2.5 m)`` of a DIST-SRV (1 when touching)."""
    return float(np.asarray(dist.values) @ _NEAR_WEIGHTS)


def closeness(dist: DistSRV) -> float:
    """In [0, 1]: the DIST-SRV's ``superposition`` + ``near`` ("beside", "by", "next to")."""
    d = dist.as_dict()
    return d["superposition"] + d["near"]


def direction_weight(reference: Entity, target: Entity, direction: str,
                     viewer_heading_rad: float | None) -> float:
    """The DIR-SRV weight of ``direction`` (front/left/back/right) of ``target`` around
    ``reference`` — its outer part plus its inner part (a target on the reference counts) —
    or 0 when the reference has no front and there is no viewer."""
    srv = dir_srv(reference, target, viewer_heading_rad)
    if srv is None or direction not in DIRECTION_ANGLES:
        return 0.0
    return srv[direction] + srv[f"inner-{direction}"]


def strongest_direction(reference: Entity, target: Entity, viewer_heading_rad: float | None = None
                        ) -> tuple[str, float] | None:
    """The direction word (front/left/back/right) with the most DIR-SRV weight of ``target``
    around ``reference`` (outer part: what a person would say of it), and that weight; None
    when the reference has no front and there is no viewer."""
    srv = dir_srv(reference, target, viewer_heading_rad)
    if srv is None:
        return None
    weights = {w: srv[w] for w in DIRECTION_ANGLES}
    word = max(weights, key=weights.get)
    return word, weights[word]


# ----------------------------------------------------------------------------- floor-plan fits

def view_fit(target: Entity, viewer: Pose2D) -> float:
    """In (0, 1]: how much ``target`` is in the viewer's view and near: the one meant by "the
    table there" when nothing else is said."""
    ahead, distance_m = _bearing_share(target, viewer)
    return (FLOOR + ahead) * math.exp(-distance_m / 3.0)


def _seen(target: Entity, viewer: Pose2D) -> float:
    """In [0, 1]: how well the viewer sees ``target`` (ahead and not far): breaks ties between
    look-alikes (several chairs, each with a table) in favour of the one in view."""
    ahead, distance_m = _bearing_share(target, viewer)
    return ahead * math.exp(-distance_m / 6.0)


def _bearing_share(target: Entity, viewer: Pose2D) -> tuple[float, float]:
    """``((1 + cos bearing) / 2, distance m)`` of the target's centre from the viewer."""
    tx, ty = target.centre_m
    bearing = wrap_angle(math.atan2(ty - viewer.y, tx - viewer.x) - viewer.theta)
    return (1.0 + math.cos(bearing)) / 2, math.hypot(tx - viewer.x, ty - viewer.y)


def room_side_fit(target: Entity, viewer: Pose2D, direction: str, floorplan) -> float:
    """In [0, 1]: how far toward ``direction`` of its room ``target`` stands, as seen from
    ``viewer`` ("at the back" = the far end along the heading, "on the left" = the left part):
    its centre's position across the room's extent in the viewer's frame (0.5 outside rooms)."""
    centre = target.centre_m
    room = floorplan.room_at(*centre)
    if room is None:
        return 0.5
    corners = viewer.to_local(room.polygon_array)
    lo, hi = corners.min(axis=0), corners.max(axis=0)
    fwd, lat = viewer.to_local(np.array([centre]))[0]
    u = float(np.clip((fwd - lo[0]) / max(hi[0] - lo[0], 1e-6), 0.0, 1.0))  # 1 = far end
    v = float(np.clip((lat - lo[1]) / max(hi[1] - lo[1], 1e-6), 0.0, 1.0))  # 1 = left side
    return {"back": u, "front": 1.0 - u, "left": v, "right": 1.0 - v}.get(direction, 0.5)


def wall_fit(target: Entity, viewer: Pose2D, direction: str | None, floorplan) -> float:
    """In [0, 1]: how closely ``target`` stands against a floor-plan wall on ``direction``'s
    side of the viewer (None: any wall): per wall, the agreement of the perpendicular from the
    viewer to the wall with that side, times ``exp(-gap / 0.3 m)``; the best wall counts."""
    pts = target.points_m()
    if len(pts) == 0:
        return 0.0
    angle = WALL_ANGLES.get(direction) if direction is not None else None
    best = 0.0
    half = target.grid.resolution_m / 2
    for wall in floorplan.walls:
        lo, hi = wall.polygon_array.min(axis=0), wall.polygon_array.max(axis=0)
        gap = float(np.hypot(np.maximum(np.maximum(lo[0] - pts[:, 0], pts[:, 0] - hi[0]), 0.0),
                             np.maximum(np.maximum(lo[1] - pts[:, 1], pts[:, 1] - hi[1]), 0.0)).min())
        near = math.exp(-max(0.0, gap - half) / WALL_SCALE_M)
        if near < FLOOR:
            continue
        agree = 1.0
        if angle is not None:
            cx, cy = (lo + hi) / 2
            if hi[0] - lo[0] < hi[1] - lo[1]:  # a wall along y: east or west of the viewer
                side = 0.0 if cx > viewer.x else math.pi
            else:
                side = math.pi / 2 if cy > viewer.y else -math.pi / 2
            agree = max(math.cos(wrap_angle(side - viewer.theta - angle)), 0.0) ** 2
        best = max(best, agree * near)
    return best


# ----------------------------------------------------------------------------- one pair

def relation_fit(rdt: RDT, reference: Entity | None, target: Entity, viewer: Pose2D,
                 floorplan=None, perceived: Sequence[Entity] = (), *,
                 items: Mapping[str, Entity] | None = None) -> float:
    """In (0, 1]: how well ``target`` stands in ``rdt``'s relation to ``reference``, as said by
    a person at ``viewer`` (the robot's pose when the command was given).

    ``reference`` is None for the robot (``robot``/``move``), the room and a wall; a furniture
    RDT without its reference entity is read from the viewer. ``floorplan`` is needed for the
    room and wall references; ``perceived`` (the other furniture) for ``between``. References
    are read as the items they are (:func:`~assistant.world.entity.as_item`); ``items`` (id →
    entity) holds those already read so (:func:`resolve` reads each reference once).
    """
    kind = rdt.reference_kind
    if kind == "room" and rdt.direction in DIRECTION_ANGLES and floorplan is not None:
        return FLOOR + room_side_fit(target, viewer, rdt.direction, floorplan)
    if kind == "room" or (reference is None and rdt.direction == "center"):
        return view_fit(target, viewer)
    if kind == "wall" and floorplan is not None:
        return FLOOR + wall_fit(target, viewer, rdt.direction, floorplan)
    origin = _item(reference, items) if reference is not None else Entity.robot(viewer, target.grid)
    dist = dist_srv(origin, target)
    seen = _seen(target, viewer)
    if rdt.direction in ("beside", "between") and reference is not None:
        fit = (0.3 + 0.7 * seen) * max(closeness(dist), FLOOR)
        if rdt.direction == "between":  # a second item of the reference's kind close by
            others = [closeness(dist_srv(_item(r, items), target)) for r in perceived
                      if r.name == reference.name and r.id not in (reference.id, target.id)]
            fit *= 0.5 + 0.5 * max(others, default=0.0)
        return fit
    near = nearness(dist)
    if rdt.direction not in DIRECTION_ANGLES:  # center of a piece, or a word with no side
        return near
    agree = direction_weight(origin, target, rdt.direction, viewer.theta)
    return (FLOOR + agree) * near * (0.7 + 0.3 * seen)


def _item(entity: Entity, items: Mapping[str, Entity] | None) -> Entity:
    """``entity`` as the item it is: from ``items`` when read already, else :func:`as_item`."""
    found = items.get(entity.id) if items is not None else None
    return found if found is not None else as_item(entity)


# ----------------------------------------------------------------------------- ranking

def resolve(rdt: RDT, perceived: Sequence[Entity], viewer_pose: Pose2D, *, floorplan=None,
            also: Sequence[RDT] = (), prior: Callable[[Entity], float] | None = None
            ) -> list[Resolution]:
    """Every reading of ``rdt`` among the ``perceived`` furniture, best first.

    Targets are the entities named ``rdt.target``; references those named ``rdt.reference``
    (or None for the robot, room and wall references). ``also``: the node's other RDTs, which
    the target should fit too ("the table by the chairs at the far end": a target's fit is
    multiplied by ``0.3 + 0.7 · its share of the best fit`` for each, so none can veto);
    ``prior``: a factor per target from what else was said (size, shape: the executor's
    description fit). Empty when no target, or no reference, of those names is perceived.
    """
    targets = [e for e in perceived if e.name == rdt.target]
    if not targets:
        return []
    refs: list[Entity | None]
    if rdt.reference_kind == "furniture":
        refs = [e for e in perceived if e.name == rdt.reference]
        if not refs:
            return []
    else:
        refs = [None]
    # every entity that is some relation's reference, read as the item it is once
    names = {rdt.reference} | {r.reference for r in also}
    items = {e.id: as_item(e) for e in perceived if e.name in names}
    agreement = _agreement(also, perceived, targets, viewer_pose, floorplan, items)
    out = []
    for ref in refs:
        for tar in targets:
            if ref is not None and tar.id == ref.id:
                continue
            fit = relation_fit(rdt, ref, tar, viewer_pose, floorplan, perceived, items=items)
            fit *= agreement.get(tar.id, 1.0) * (prior(tar) if prior is not None else 1.0)
            out.append(Resolution(ref, tar, fit))
    out.sort(key=lambda r: -r.fit)
    return out


def _agreement(also: Sequence[RDT], perceived: Sequence[Entity], targets: list[Entity],
               viewer: Pose2D, floorplan, items: Mapping[str, Entity]) -> dict[str, float]:
    """Per target id, a factor in [0.3, 1] for how well it also fits each of ``also``
    (relative to the best target); a relation whose reference is not perceived counts for
    nothing."""
    out = {t.id: 1.0 for t in targets}
    for rdt in also:
        if rdt.reference_kind == "furniture":
            refs = [e for e in perceived if e.name == rdt.reference]
            if not refs:
                continue
        else:
            refs = [None]
        fits = {t.id: max((relation_fit(rdt, r, t, viewer, floorplan, perceived, items=items)
                           for r in refs if r is None or r.id != t.id), default=0.0)
                for t in targets}
        top = max(fits.values(), default=0.0)
        if top <= 0:
            continue
        for tid, f in fits.items():
            out[tid] *= AGREEMENT_FLOOR + (1 - AGREEMENT_FLOOR) * f / top
    return out

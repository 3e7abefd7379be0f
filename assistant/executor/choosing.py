"""Choosing furniture for an RDT node among what the robot has perceived.

A static node ("the table in front of the couch") names a reference and a direction; the
robot picks, among the furniture its perception has reported in the room, the (reference,
target) pair that fits best (:meth:`PlaceChooser.choose_pair`): direction agreement times
nearness (:meth:`PlaceChooser.fit`), times how well the target fits the words said about it
(:class:`Said`: "the desk", "the round table"), times how well it fits the node's other pairs
(:meth:`PlaceChooser.agreement`). When no pair can be chosen the fetch searches the likely
surfaces (:meth:`PlaceChooser.likely_surfaces`).

The chooser reads only the floor plan, the perceived furniture and the pose the command was
said from — no robot — so it is tested directly.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.spatial import cKDTree

from assistant.executor.describe import description_fit
from assistant.executor.sensing import FurnitureSource, entity_centre, entity_room
from assistant.geometry import Pose2D, wrap_angle
from assistant.world import Entity, World

__all__ = ["DIRECTION_ANGLES", "NOTHING_SAID", "PLACE_REFERENCES", "WALL_ANGLES", "PlaceChooser", "Said", "gap"]

#: directions of the RDT model as angles in the reference's frame (0 = its front)
DIRECTION_ANGLES = {"front": 0.0, "left": math.pi / 2, "back": math.pi, "right": -math.pi / 2}
#: a room's walls as a person entering names them (radians from the entry heading): "the back
#: wall" is the far one, like "the back of the room" (the generator says it so too), and "the
#: front wall" is the one ahead
WALL_ANGLES = {"front": 0.0, "back": 0.0, "left": math.pi / 2, "right": -math.pi / 2}
#: references that are not furniture (no perceived item to look for)
PLACE_REFERENCES = ("robot", "room", "move", "wall", "door")


@dataclass(frozen=True)
class Said:
    """The words said about a node's target: ``support`` ("desk") and ``descriptors``
    (size/shape words, "round", "big")."""

    support: str | None = None
    descriptors: tuple[str, ...] = ()

    @classmethod
    def of(cls, node) -> "Said":
        """The words an RDT node carries about its target."""
        return cls(getattr(node, "support", None), tuple(getattr(node, "descriptors", ()) or ()))

    def fit(self, entity: Entity) -> float:
        """How well ``entity`` fits these words, in (0, 1] (1 when nothing was said)."""
        return description_fit(self.support, self.descriptors, entity)


#: no words said about the target
NOTHING_SAID = Said()


@dataclass
class PlaceChooser:
    """Scores and picks perceived furniture for RDT nodes in ``world`` (module docstring)."""

    world: World
    perception: FurnitureSource

    def in_room(self, room: str, word: str | None = None) -> list[Entity]:
        """The perceived furniture in ``room`` (named ``word`` if given)."""
        out = []
        for e in self.perception.furniture():
            if word is not None and e.name != word:
                continue
            if entity_room(self.world, e) == room:
                out.append(e)
        return out

    def choose_pair(self, rdt, room: str, pose: Pose2D, others=(), said: Said = NOTHING_SAID):
        """The (reference, target, fit) instances that best fit ``rdt`` among the furniture
        seen in ``room``; None when the reference or target is not seen. ``pose``: the robot's
        pose the command's "your left" is said from; ``others``: the node's other RDTs, which
        the target should fit too (:meth:`agreement`); ``said``: the words said about the
        target (:class:`Said`)."""
        targets = self.in_room(room, rdt.target)
        if not targets:
            return None
        if rdt.reference in ("robot", "room", "move", "wall"):
            refs = [None]
        else:
            refs = self.in_room(room, rdt.reference)
            if not refs:
                return None
        agreement = self.agreement(others, room, targets, pose)
        best = None
        for ref in refs:
            for tar in targets:
                if ref is not None and tar.id == ref.id:
                    continue
                fit = self.fit(rdt, ref, tar, pose) * said.fit(tar) * agreement.get(tar.id, 1.0)
                if best is None or fit > best[2]:
                    best = (ref, tar, fit)
        return best

    def agreement(self, others, room: str, targets: list[Entity], pose: Pose2D) -> dict[str, float]:
        """Per target id, a factor in [0.3, 1] for how well it also fits the node's other
        pairs ("next to the chair" and "at the back on the left" both hold for the one meant):
        per pair, its best fit over that pair's references relative to the best target's, mixed
        0.3 + 0.7 · share so that a pair cannot veto; pairs whose reference is not seen count
        for nothing."""
        out = {t.id: 1.0 for t in targets}
        for rdt in others or ():
            if rdt.reference in ("robot", "room", "move", "wall"):
                refs = [None]
            else:
                refs = self.in_room(room, rdt.reference)
                if not refs:
                    continue
            fits = {t.id: max((self.fit(rdt, r, t, pose) for r in refs if r is None or r.id != t.id), default=0.0)
                    for t in targets}
            top = max(fits.values(), default=0.0)
            if top <= 0:
                continue
            for tid, f in fits.items():
                out[tid] *= 0.3 + 0.7 * f / top
        return out

    def fit(self, rdt, ref: Entity | None, tar: Entity, pose: Pose2D) -> float:
        """How well ``tar`` stands in ``rdt.direction`` of ``ref`` (the robot when None), in
        (0, 1]: direction agreement times nearness."""
        tx, ty = entity_centre(tar)
        if rdt.reference == "room" and rdt.direction in DIRECTION_ANGLES:
            return 0.05 + self.room_side_fit(tar, pose, rdt.direction)
        if rdt.reference == "room" or (ref is None and rdt.direction == "center"):
            # a target named with no reference ("the mug is on the table there"): the one most
            # in the robot's view now — where the steps so far have turned it
            d = math.hypot(tx - pose.x, ty - pose.y)
            bearing = wrap_angle(math.atan2(ty - pose.y, tx - pose.x) - pose.theta)
            return (0.05 + (1.0 + math.cos(bearing)) / 2) * math.exp(-d / 3.0)
        if rdt.reference == "wall":
            # "the desk against the left wall": close to a wall that lies on that side of the
            # robot (as it stood when told), wherever along the wall
            return 0.05 + self.wall_fit(tar, pose, WALL_ANGLES.get(rdt.direction))
        if ref is None:
            ox, oy, front = pose.x, pose.y, pose.theta
            # the robot's left/right: things to its side, ahead or level, not behind it
        else:
            # from the reference's nearest part, not its centre: a table at the head of a long
            # bed is beside it even though the bed's centre is far along
            cells = ref.points_m()
            if len(cells):
                ox, oy = cells[int(np.argmin(np.hypot(cells[:, 0] - tx, cells[:, 1] - ty)))]
            else:
                ox, oy = entity_centre(ref)
            if ref.orientation_rad is not None:
                front = ref.orientation_rad
            else:  # a reference without a front: the viewer's frame (the robot looking at it)
                cx, cy = entity_centre(ref)
                front = math.atan2(pose.y - cy, pose.x - cx)
                if rdt.direction in ("left", "right"):
                    front = front  # facing the viewer: its left is the viewer's right
        dx, dy = tx - ox, ty - oy
        dist = math.hypot(dx, dy)
        near = math.exp(-dist / 2.5)
        # ties (several chairs each with a table) go to the one most in view
        bearing = wrap_angle(math.atan2(ty - pose.y, tx - pose.x) - pose.theta)
        seen = (1.0 + math.cos(bearing)) / 2 * math.exp(-math.hypot(tx - pose.x, ty - pose.y) / 6.0)
        view = 0.7 + 0.3 * seen
        if rdt.direction in ("beside", "between") and ref is not None:
            fit = (0.3 + 0.7 * seen) * math.exp(-gap(ref, tar) / 1.0)
            if rdt.direction == "between":  # two of the reference's kind close to the target
                others = sorted(gap(r, tar) for r in self.in_room(entity_room(self.world, tar) or "", ref.name)
                                if r.id != ref.id)
                fit *= 0.5 + 0.5 * (math.exp(-others[0] / 0.4) if others else 0.0)
            return fit
        if rdt.direction in ("beside", "between", "center") or rdt.direction not in DIRECTION_ANGLES:
            return near
        angle = DIRECTION_ANGLES[rdt.direction]
        if ref is not None and ref.orientation_rad is None and rdt.direction in ("left", "right"):
            angle = -angle  # the viewer's left of a front-less item
        want = front + angle
        agree = max(math.cos(wrap_angle(math.atan2(dy, dx) - want)), 0.0) ** 2
        if ref is not None:
            # and from its centre: where perception merged two pieces (an L of two couches
            # reported as one), the nearest part alone points anywhere
            cx, cy = entity_centre(ref)
            from_centre = max(math.cos(wrap_angle(math.atan2(ty - cy, tx - cx) - want)), 0.0) ** 2
            agree = 0.5 * (agree + from_centre)
        return (0.05 + agree) * near * view

    def room_side_fit(self, entity: Entity, pose: Pose2D, direction: str) -> float:
        """In [0, 1]: how far toward ``direction`` of its room ``entity`` stands, seen from
        ``pose`` ("at the back" = the far end along the heading, "on the left" = the left
        part): its centre's position across the room's extent in the robot's frame."""
        room = self.world.floorplan.room_at(*entity_centre(entity))
        if room is None:
            return 0.5
        corners = pose.to_local(room.polygon_array)
        lo, hi = corners.min(axis=0), corners.max(axis=0)
        fwd, lat = pose.to_local(np.array([entity_centre(entity)]))[0]
        u = float(np.clip((fwd - lo[0]) / max(hi[0] - lo[0], 1e-6), 0.0, 1.0))  # 1 = far end
        v = float(np.clip((lat - lo[1]) / max(hi[1] - lo[1], 1e-6), 0.0, 1.0))  # 1 = left side
        return {"back": u, "front": 1.0 - u, "left": v, "right": 1.0 - v}[direction]

    def wall_fit(self, entity: Entity, pose: Pose2D, angle: float | None) -> float:
        """In [0, 1]: how closely ``entity`` stands against a floor-plan wall that faces the
        robot from ``angle`` (radians from its heading; None = any wall): per wall, the
        agreement of the perpendicular from the robot to the wall with that side, times
        exp(-gap / 0.3 m); the best wall counts."""
        pts = entity.points_m()
        if len(pts) == 0:
            return 0.0
        best = 0.0
        half = entity.grid.resolution_m / 2
        for wall in self.world.floorplan.walls:
            lo, hi = wall.polygon_array.min(axis=0), wall.polygon_array.max(axis=0)
            gap = float(np.hypot(np.maximum(np.maximum(lo[0] - pts[:, 0], pts[:, 0] - hi[0]), 0.0),
                                 np.maximum(np.maximum(lo[1] - pts[:, 1], pts[:, 1] - hi[1]), 0.0)).min())
            near = math.exp(-max(0.0, gap - half) / 0.3)
            if near < 0.05:
                continue
            agree = 1.0
            if angle is not None:
                cx, cy = (lo + hi) / 2
                if hi[0] - lo[0] < hi[1] - lo[1]:  # a wall along y: it lies east or west of the robot
                    side = 0.0 if cx > pose.x else math.pi
                else:
                    side = math.pi / 2 if cy > pose.y else -math.pi / 2
                agree = max(math.cos(wrap_angle(side - pose.theta - angle)), 0.0) ** 2
            best = max(best, agree * near)
        return best

    def likely_surfaces(self, room: str, word: str, pose: Pose2D, said: Said = NOTHING_SAID) -> list[Entity]:
        """Furniture of the target's kind (``word``; any table when none is seen) in the room,
        the one most in view from ``pose`` and fitting ``said`` first."""
        items = self.in_room(room, word) or self.in_room(room, "table")

        def rank(e):
            x, y = entity_centre(e)
            d = math.hypot(x - pose.x, y - pose.y)
            bearing = abs(wrap_angle(math.atan2(y - pose.y, x - pose.x) - pose.theta))
            return -(math.exp(-d / 3.0) * (1.0 + math.cos(bearing)) * said.fit(e))

        return sorted(items, key=rank)


def gap(a: Entity, b: Entity) -> float:
    """Least distance (metres) between two entities' cells (0 when they touch)."""
    pa, pb = a.points_m(), b.points_m()
    if len(pa) == 0 or len(pb) == 0:
        return math.inf
    d, _ = cKDTree(pb).query(pa, k=1)
    return max(0.0, float(d.min()) - (a.grid.resolution_m + b.grid.resolution_m) / 2)



"""Choosing furniture for an RDT node among what the robot has perceived.

A static node ("the table in front of the couch") names a reference and a direction; the
robot picks, among the furniture its perception has reported in the room, the (reference,
target) pair that fits best (:meth:`PlaceChooser.choose_pair`): the spatial layer's reading of
the RDT (:func:`assistant.spatial.resolve`: DIR-SRV direction weight times DIST-SRV nearness,
times how well it fits the node's other pairs), times how well the target fits the words said
about it (:class:`Said`: "the desk", "the round table"). When no pair can be chosen the fetch searches the likely
surfaces (:meth:`PlaceChooser.likely_surfaces`).

Objects are landmarks too ("the table next to the lamp", "by the keys"): an object the robot's
object detector has seen in the room (``seen``, the task's latest sightings) stands among the
furniture as a small disc where it was seen (:func:`landmark_entity`), named as the object is, so
``resolve`` reads "beside the keys" from it as from any chair. An object not seen is no
reference: the node's furniture pairs decide, or the likely surfaces.

The chooser reads only the floor plan, the perceived furniture and the pose the command was
said from — no robot — so it is tested directly.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

from assistant.executor.describe import description_fit
from assistant.executor.sensing import FurnitureSource, entity_centre, entity_room
from assistant.geometry import Pose2D, ellipse, wrap_angle
from assistant.perception.objects import Sighting
from assistant.spatial.resolve import resolve
from assistant.world import Entity, World
from assistant.world.entity import EntityKind

__all__ = ["LANDMARK_PREFIX", "NOTHING_SAID", "PlaceChooser", "Said", "is_landmark", "landmark_entity"]

#: metres: the radius of the disc an object seen stands for as a landmark
LANDMARK_RADIUS_M = 0.1
#: the id prefix of an object seen, standing as a landmark (``object:keys``)
LANDMARK_PREFIX = "object:"


def landmark_entity(sighting: Sighting, grid) -> Entity:
    """An object the object detector saw, as an entity of ``grid`` a relation can be read from:
    a disc of :data:`LANDMARK_RADIUS_M` where it was seen, named as the object, without a front
    (so "to the left of the lamp" is the viewer's left)."""
    centre = Pose2D(sighting.x_m, sighting.y_m, 0.0)
    disc = ellipse(centre, 2 * LANDMARK_RADIUS_M, 2 * LANDMARK_RADIUS_M, segments=12)
    return Entity.from_polygon(LANDMARK_PREFIX + sighting.name, sighting.name, EntityKind.SHORT_TERM, disc,
                               grid, None, room=sighting.room,
                               attributes={"x": sighting.x_m, "y": sighting.y_m})


def is_landmark(entity) -> bool:
    """Whether ``entity`` is an object seen standing as a landmark (:func:`landmark_entity`)."""
    return isinstance(entity, Entity) and entity.id.startswith(LANDMARK_PREFIX)



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
    #: object name → the latest placed sighting of the robot's object detector (the task's ``seen``)
    seen: Mapping[str, Sighting] = field(default_factory=dict)

    def in_room(self, room: str, word: str | None = None) -> list[Entity]:
        """The perceived furniture in ``room`` and the objects seen there as landmarks (named
        ``word`` if given)."""
        out = []
        for e in self.perception.furniture():
            if word is not None and e.name != word:
                continue
            if entity_room(self.world, e) == room:
                out.append(e)
        return out + self.landmarks(room, word)

    def landmarks(self, room: str, word: str | None = None) -> list[Entity]:
        """The objects the object detector has seen in ``room`` (named ``word`` if given), as
        :func:`landmark_entity`; none before any furniture is perceived (nothing to place them on)."""
        found = [s for s in self.seen.values() if s.room == room and (word is None or s.name == word)]
        if not found:
            return []
        furniture = self.perception.furniture()
        if not furniture:
            return []
        return [landmark_entity(s, furniture[0].grid) for s in sorted(found, key=lambda s: s.name)]

    def choose_pair(self, rdt, room: str, pose: Pose2D, others=(), said: Said = NOTHING_SAID):
        """The (reference, target, fit) that best fit ``rdt`` among the furniture seen in
        ``room`` — the spatial layer's reading, :func:`assistant.spatial.resolve` — or None when
        the reference or target is not seen. ``pose``: the robot's pose the command's "your
        left" is said from; ``others``: the node's other RDTs, which the target should fit too;
        ``said``: the words said about the target (:class:`Said`)."""
        readings = resolve(rdt, self.in_room(room), pose, floorplan=self.world.floorplan,
                           also=others, prior=said.fit)
        if not readings:
            return None
        best = readings[0]
        return best.reference, best.target, best.fit

    def likely_surfaces(self, room: str, word: str, pose: Pose2D, said: Said = NOTHING_SAID) -> list[Entity]:
        """Furniture of the target's kind (``word``; any table when none is seen) in the room,
        the one most in view from ``pose`` and fitting ``said`` first."""
        items = [e for e in self.in_room(room, word) or self.in_room(room, "table") if not is_landmark(e)]

        def rank(e):
            x, y = entity_centre(e)
            d = math.hypot(x - pose.x, y - pose.y)
            bearing = abs(wrap_angle(math.atan2(y - pose.y, x - pose.x) - pose.theta))
            return -(math.exp(-d / 3.0) * (1.0 + math.cos(bearing)) * said.fit(e))

        return sorted(items, key=rank)

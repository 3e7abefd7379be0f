"""The Reference-Direction-Target triple and its reference kinds: a core term of every layer.

An RDT reads ``reference-direction-target`` (dissertation 4.3 II.B and Table 5-1):
``couch-front-table`` is "the table in front of the couch"; ``move-left-non`` is "turn left".

* the *reference* is ``move`` or ``robot`` (the robot itself, its pose when the node began),
  ``stop`` (``stop-center-non``: stay where the robot is; "stop there"),
  ``room``, ``wall`` or ``door`` (floor-plan structures), or a furniture word;
* the *direction* is one of :data:`DIRECTIONS`;
* the *target* is a furniture word, or :data:`NO_TARGET` (``non``: the robot goes to a place,
  not to a thing).

Grounding produces RDTs, the policies are trained per RDT, the executor and the spatial layer
carry them out, generation describes with them: they all use this one type.
"""

from __future__ import annotations

from dataclasses import dataclass

from assistant.errors import AssistantError

__all__ = [
    "DIRECTIONS", "DYNAMIC_REFERENCES", "NO_TARGET", "PLACE_REFERENCES", "RDT", "RDTNameError",
    "ROBOT_REFERENCES", "STRUCTURE_REFERENCES", "parse_rdt", "reference_kind",
]

#: the target word of a node that has no target furniture
NO_TARGET = "non"
#: the directions of the RDT model
DIRECTIONS = ("front", "back", "left", "right", "center", "beside", "between")
#: reference words that mean the robot itself (its pose when the node began)
ROBOT_REFERENCES = frozenset({"move", "robot", "stop"})
#: reference words that are floor-plan structures rather than furniture
FLOORPLAN_REFERENCES = frozenset({"room", "wall", "door"})
#: reference words that are not furniture (dissertation 4.3 II.B, Fig. 1)
STRUCTURE_REFERENCES = ("move", "room", "wall", "door", "robot", "stop")
#: references that name a place rather than a thing to perceive (robot, floor plan)
PLACE_REFERENCES = ROBOT_REFERENCES | FLOORPLAN_REFERENCES
#: references whose node needs no furniture perception (a dynamic description)
DYNAMIC_REFERENCES = frozenset({"move", "room", "wall", "door", "stop"})


class RDTNameError(AssistantError, ValueError):
    """A string that is not ``reference-direction-target``."""


def reference_kind(reference: str) -> str:
    """``robot`` (move/robot), ``room``, ``wall`` or ``furniture``.

    A door is an entity with a position and a facing, like a piece of furniture, so the policy
    models treat it as one (its kind is ``furniture``).
    """
    if reference in ROBOT_REFERENCES:
        return "robot"
    if reference in ("room", "wall"):
        return reference
    return "furniture"


@dataclass(frozen=True)
class RDT:
    """One reference-direction-target triple, e.g. ``couch-front-table`` or ``move-left-non``."""

    reference: str
    direction: str
    target: str = NO_TARGET

    @classmethod
    def parse(cls, text: str) -> "RDT":
        """``"Couch-front-table"`` → ``RDT("couch", "front", "table")`` (lower-cased)."""
        parts = str(text).strip().lower().split("-")
        if len(parts) != 3 or not all(parts):
            raise RDTNameError(f"{text!r} is not an RDT name: write reference-direction-target, "
                               "e.g. couch-front-table or move-left-non")
        return cls(*parts)

    @property
    def name(self) -> str:
        return f"{self.reference}-{self.direction}-{self.target}"

    def __str__(self) -> str:
        return self.name

    @property
    def has_target(self) -> bool:
        return self.target != NO_TARGET

    @property
    def reference_kind(self) -> str:
        """``robot`` (move/robot), ``room``, ``wall`` or ``furniture`` (see :func:`reference_kind`)."""
        return reference_kind(self.reference)

    @property
    def has_reference_entity(self) -> bool:
        """Whether the WSF has a ``ref`` entity (the robot reference is the OR entity itself)."""
        return self.reference_kind != "robot"

    @property
    def names_a_place(self) -> bool:
        """True when the reference is the robot or a floor-plan structure, not furniture."""
        return self.reference in PLACE_REFERENCES

    @property
    def dynamic(self) -> bool:
        """True when following it needs no furniture perception (move/room/wall/door, no target)."""
        return self.reference in DYNAMIC_REFERENCES and self.target == NO_TARGET


def parse_rdt(name: "str | RDT") -> RDT:
    """An :class:`RDT` from its name, or the RDT itself."""
    return name if isinstance(name, RDT) else RDT.parse(name)

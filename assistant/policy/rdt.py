"""The RDT nodes a policy model is trained for (dissertation Table 5-1).

An RDT name is ``reference-direction-target``: ``couch-front-table`` is "the table in front of
the couch"; ``move`` and ``robot`` references mean the robot itself (its pose when the node
began), ``non`` means no target (the robot goes to a place, not to a thing).
"""

from __future__ import annotations

from dataclasses import dataclass

from assistant.errors import AssistantError

#: reference words that mean the robot itself
ROBOT_REFERENCES = ("move", "robot")
#: reference words that are floor-plan structures rather than furniture
STRUCTURE_REFERENCES = ("room", "wall")


@dataclass(frozen=True)
class RDT:
    """One RDT node: ``reference`` word, ``direction`` word, ``target`` word (``non``: none)."""

    reference: str
    direction: str
    target: str

    @classmethod
    def parse(cls, name: str) -> "RDT":
        parts = str(name).strip().lower().split("-")
        if len(parts) != 3 or not all(parts):
            raise AssistantError(f"{name!r} is not an RDT name: write reference-direction-target, "
                                 f"e.g. couch-front-table or move-left-non")
        return cls(*parts)

    @property
    def name(self) -> str:
        return f"{self.reference}-{self.direction}-{self.target}"

    @property
    def has_target(self) -> bool:
        return self.target != "non"

    @property
    def reference_kind(self) -> str:
        """``robot`` (move/robot), ``room``, ``wall`` or ``furniture``."""
        if self.reference in ROBOT_REFERENCES:
            return "robot"
        if self.reference in STRUCTURE_REFERENCES:
            return self.reference
        return "furniture"

    @property
    def has_reference_entity(self) -> bool:
        """Whether the WSF has a ``ref`` entity (the robot reference is the OR entity itself)."""
        return self.reference_kind != "robot"

    def __str__(self) -> str:
        return self.name


#: (number, natural-language description, RDT) — dissertation Table 5-1
TABLE_5_1: tuple[tuple[int, str, str], ...] = (
    (1, "go/walk/move forward", "move-front-non"),
    (2, "turn left", "move-left-non"),
    (3, "turn right", "move-right-non"),
    (4, "table on the/your left", "robot-left-table"),
    (5, "the table is on/to the/your right", "robot-right-table"),
    (6, "table on/to the left of the bed", "bed-left-table"),
    (7, "table on/to the right of the bed", "bed-right-table"),
    (8, "table in front of the couch", "couch-front-table"),
    (9, "table to/on the left of the couch", "couch-left-table"),
    (10, "table to/on the right of the couch", "couch-right-table"),
    (11, "table beside a chair", "chair-beside-table"),
    (12, "go to the center of the room", "room-center-non"),
    (13, "move to the front wall", "wall-front-non"),
)

TABLE_RDTS: tuple[str, ...] = tuple(name for _, _, name in TABLE_5_1)


def parse_rdt(name: str | RDT) -> RDT:
    return name if isinstance(name, RDT) else RDT.parse(name)

"""The RDT nodes a policy model is trained for (dissertation Table 5-1).

The :class:`~assistant.rdt.RDT` type itself is a core term (:mod:`assistant.rdt`).

An RDT name is ``reference-direction-target``: ``couch-front-table`` is "the table in front of
the couch"; ``move`` and ``robot`` references mean the robot itself (its pose when the node
began), ``non`` means no target (the robot goes to a place, not to a thing).
"""

from __future__ import annotations

from assistant.rdt import RDT, parse_rdt

__all__ = ["RDT", "TABLE_5_1", "TABLE_RDTS", "parse_rdt"]


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


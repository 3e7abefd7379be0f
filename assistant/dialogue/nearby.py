"""What stands by a piece of furniture: "what's next to the bed?", "what's on the table next to
the bed?", "is there anything behind the couch?".

The furniture near another is read from the spatial layer's relations between the home's
furniture (:func:`assistant.spatial.relations.relations`: a DIST-SRV whose strongest value is
"superposition" or "near", and the DIR-SRV's strongest side — the bed's own left and right, a
table's from the robot's start). The chat's other answers about furniture read the same world
file; the robot's own sightings add the things lying there.
"""

from __future__ import annotations

import re

#: the relation words of a question → the side they ask about (None: any side)
RELATION_SIDES = {
    "next to": None, "by": None, "beside": None, "near": None, "close to": None, "around": None,
    "to the left of": "left", "left of": "left", "on the left of": "left",
    "to the right of": "right", "right of": "right", "on the right of": "right",
    "in front of": "front", "behind": "back", "at the back of": "back",
}
RELATION = "|".join(sorted(map(re.escape, RELATION_SIDES), key=len, reverse=True))
#: how a side is said after the furniture's name
SIDE_WORDS = {"front": "in front of it", "back": "behind it", "left": "to its left", "right": "to its right"}

#: "what's next to the bed?", "anything behind the couch in the living room?" (groups ``rel``,
#: ``reference``, ``room``)
NEAR_QUESTION = re.compile(
    r"^(?:(?:and|so|ok|okay|um|uh|then|now|tell me|robot|hey robot|please) )*(?:what|whats|what is|what else is|whats else is|"
    r"what stands|what furniture is|is there anything|is there something|anything|is anything)(?: right| just| else)?"
    r" (?P<rel>" + RELATION + r") (?:the|my|that|this) (?P<reference>[a-z]+(?: (?!now\b|at\b|in\b)[a-z]+)?)"
    r"(?: (?:in|inside) (?:the|my|our) (?P<room>[a-z]+(?: [a-z]+)?))?(?: now| at the moment)?$")


def near_question(norm: str) -> tuple[str, str, str | None] | None:
    """(relation words, the furniture said, the room said or None) of a normalised question about
    what stands by a piece of furniture, or None."""
    m = NEAR_QUESTION.match(norm)
    return None if m is None else (m.group("rel"), m.group("reference"), m.group("room"))


def furniture_by(world, scene: str, reference_id: str, side: str | None = None) -> list[tuple[object, str]]:
    """(furniture item, its side of the reference: "front", "back", "left" or "right") of every
    piece of the reference's room that stands near it, nearest first; ``side`` keeps that side's."""
    from assistant.spatial.relations import relations

    items = {f.id: f for f in world.scene(scene).furniture}
    out = []
    for r in relations(world, scene, reference=reference_id):
        if r["reference"] != reference_id or r["distance"] not in ("superposition", "near"):
            continue
        where = r["direction"].replace("inner-", "")
        if side is None or where == side:
            out.append((items[r["described"]], where, r["dist"]["far"]))
    return [(item, where) for item, where, _ in sorted(out, key=lambda x: x[2])]

"""A piece of furniture said as the place to go: "go to the couch", "walk over to the desk in the
office", "take me to the coffee table".

The corpus descriptions say where a thing is; a person also just sends the robot to a piece of
furniture, and the chunker reads "go to the couch" as a room phrase that grounds to nothing.
:func:`said_destination` reads such a command — a verb of going, "to"/"towards"/"up to"/"next to",
the furniture (its size, shape and kind words kept as descriptors), and at most the room it is in
— into the node the fetch task faces ("room-center-couch"). The furniture may be told by another
piece or a wall ("go to the couch by the table", "the chair to the left of the bed", "the couch
against the right wall": ``table-beside-couch``, ``bed-left-chair``, ``wall-right-couch``), as the
chat's own questions offer them ("the one by the table?"): the grounders, trained on where things
lie, read the first as the table. Anything else in the words and it gives None: the grounders'
reading stands.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistant.grounding.types import RDTNode
from assistant.grounding.vocabulary import DESCRIPTORS, canonical_word, furniture_category, said_descriptors

__all__ = ["said_destination"]

_GO = r"(?:go|walk|drive|head|move|come|get|roll|navigate|take me|bring me|lead me|show me the way)"
_TO = r"(?:back |over |right |straight )*(?:to|towards|toward|up to|next to|near|over to|in front of|close to)"
_DET = r"(?:the|my|your|our|that|this)"
#: how a person tells one piece of furniture by another → the RDT direction
_RELATIONS = {"by": "beside", "beside": "beside", "next to": "beside", "near": "beside", "close to": "beside",
              "nearest": "beside", "nearest to": "beside", "closest to": "beside", "near to": "beside",
              "in front of": "front", "facing": "front", "behind": "back", "in back of": "back",
              "to the left of": "left", "left of": "left", "on the left of": "left",
              "to the right of": "right", "right of": "right", "on the right of": "right",
              "against": "beside", "along": "beside", "at": "beside", "on": "beside"}
_RELATION = "|".join(sorted((re.escape(r) for r in _RELATIONS), key=len, reverse=True))
_PATTERN = re.compile(r"^(?:(?:please|robot|okay|ok|now|just|um|uh|can you|could you|would you|will you) )*"
                      + _GO + r" " + _TO + r" " + _DET + r" (?P<thing>[a-z ]+?)"
                      r"(?: (?:that is |that's |which is |thats )?(?P<relation>" + _RELATION + r") (?:the|my|your|our)"
                      r" (?P<landmark>[a-z ]+?))?"
                      r"(?: (?:in|inside) (?:the|my|our) [a-z ]+)?(?: please| now| for me)*$")
#: walls said by side ("against the left wall"): the side is the RDT direction
_WALL_SIDES = {"left": "left", "right": "right", "back": "back", "far": "back", "front": "front", "near": "front"}


#: colour and material words said of furniture ("the blue chair", "the wooden table"): a depth
#: camera cannot see them, so they are no descriptor of the node; the words stay in the text,
#: where the dialogue reads them against the furniture's model names
LOOKS = frozenset({"blue", "red", "green", "white", "black", "brown", "grey", "gray", "yellow", "pink", "orange",
                   "purple", "beige", "cream", "wood", "wooden", "leather", "glass", "metal", "plastic", "old",
                   "new", "comfy", "soft"})


def said_destination(words: Sequence[str], rooms: Sequence[str] = ()) -> RDTNode | None:
    """The furniture node of a "go to the couch" command (see the module), or None. ``rooms``:
    the home's room names, so a room said after the furniture is not read as part of it."""
    text = " ".join(str(w).strip().lower() for w in words if str(w).strip() and str(w) not in ",.!?")
    m = _PATTERN.match(text)
    if m is None:
        return None
    thing = m.group("thing").split()
    if not thing:
        return None
    head = canonical_word(thing[-1])
    category = furniture_category(head)
    if category is None or any(w not in DESCRIPTORS and w not in LOOKS and canonical_word(w) != head
                               for w in thing[:-1]):
        return None
    if any(r in " ".join(thing) for r in rooms):
        return None
    pairs: tuple[tuple[str, str], ...] = ()
    if m.group("relation"):
        landmark = m.group("landmark").split()
        if any(r in " ".join(landmark) for r in rooms):
            return None
        if landmark[-1] == "wall" and len(landmark) == 2 and landmark[0] in _WALL_SIDES:
            pairs = (("wall", _WALL_SIDES[landmark[0]]),)  # "against the left wall"
        else:
            reference = furniture_category(canonical_word(landmark[-1]))
            if reference is None or reference == category or any(
                    w not in DESCRIPTORS and w not in LOOKS for w in landmark[:-1]):
                return None
            pairs = ((reference, _RELATIONS[m.group("relation")]),)
    return RDTNode(category, pairs=pairs, support=head if head != category else category,
                   descriptors=said_descriptors(thing[:-1]))

"""What the words plainly say, over a learned guess: the families of real spoken commands.

The grounders learn from labelled chunks; real speakers use words the labels never pair with
their fields. These rules read a chunk's own words and correct the grounding where the words
decide it (each rule is one family of real phrasing, not one sentence):

* **objects** — an object phrase (OBTP) names its object by its noun phrase, any noun phrase
  (:mod:`assistant.grounding.objects`); an object reference phrase (OBRP, or a furniture
  reference phrase that names no furniture) makes the object a landmark ("with the lamp",
  "next to the computer"), beside it unless a side is said; an object reference to "it" names
  nothing;
* **the listener** — a PERS phrase ("on your right", "to your left") is the robot's side,
  never a room;
* **rooms** — a room phrase that names no room and no side ("walk straight into", "as soon as
  you get into") after a room was already named repeats nothing;
* **furniture** — a target phrase that names no furniture ("on it") keeps the learned target
  (our corpus labels it ``table``, as the templates do; one real file labels it N/A);
* **whose side** — a side said of the room ("the right end of the room") is the room's, a side
  said of the listener ("on your right", "ahead to your left") the robot's;
* **motion** — "stop" is a ``stop`` node; "halfway" is the centre of the room; "the other /
  far side (end) of the room" is its back; a turn or a side step said with a side ("turn
  right again", "side step left") moves to that side; "until you hit the wall", "go to the
  wall" is left to the grounder (the CSISL templates label it ``wall``/``beside``); passing furniture ("pass the couch") is its far side.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from assistant.grounding.objects import is_object_word, object_phrase
from assistant.grounding.types import ChunkGrounding, ChunkRecord
from assistant.grounding.vocabulary import FURNITURE_WORDS, canonical_tokens

__all__ = ["spoken_groundings", "STOP"]

#: the reference of a chunk that tells the robot to stop where it is
STOP = "stop"
#: chunk labels whose words can name the target room
ROOM_LABELS = frozenset({"ORMTP", "ORMRP", "IRMTP"})
#: labels of phrases that give a reference
REFERENCE_LABELS = frozenset({"OBRP", "FURRP"})
SIDES = {"left": "left", "right": "right"}
LISTENER = frozenset({"you", "your", "yourself", "brian", "his", "him"})
ROOM_WORDS = frozenset({"room", "rooms", "bedroom", "kitchen", "office", "hallway", "hall", "bathroom",
                        "studio", "alcove", "lounge", "living", "dining", "den", "study", "closet"})
POINTERS = frozenset({"it", "its", "that", "this", "them", "those", "these", "there", "here"})
#: words that ask to stop; a chunk of only these (and fillers) is a stop
STOP_WORDS = frozenset({"stop", "halt", "freeze", "there", "here", "and", "then", "now", "um", "uh",
                        "er", "okay", "ok", "right", "just", "please", "robot", "brian"})
TURN_VERBS = frozenset({"turn", "make", "take", "hang", "step", "veer", "bear", "swing", "pivot",
                        "rotate", "sidestep", "shuffle", "scoot", "slide", "strafe"})
#: words that say "beside" (the landmark is next to the place)
BESIDE_WORDS = frozenset({"with", "by", "next", "beside", "near", "nearby", "along", "against", "alongside",
                          "close", "besides"})
PASSING_WORDS = frozenset({"pass", "past", "passing", "beyond", "passed"})
FAR_WORDS = frozenset({"other", "far", "opposite", "farthest", "furthest"})
END_WORDS = frozenset({"side", "end", "wall"})
#: words after "right" that make it an intensifier ("right next to", "right there")
INTENSIFIED = frozenset({"next", "there", "here", "by", "beside", "in", "on", "behind", "at", "near"})
#: sides said in a landmark reference ("to the left of the lamp")
LANDMARK_SIDES = {"left": "left", "right": "right", "behind": "back", "front": "front",
                  "between": "between", "beside": "beside"}


def _words(record: ChunkRecord) -> list[str]:
    return [w.strip().lower() for w in record.words if w.strip()]


def spoken_groundings(records: Sequence[ChunkRecord], groundings: Sequence[ChunkGrounding],
                      known: Sequence[bool] | None = None) -> list[ChunkGrounding]:
    """``groundings`` corrected by what each chunk's own words plainly say (module doc).
    ``known[i]``: whether chunk i has a word the grounder was trained on; a chunk of only
    unknown words ("asdf qwerty") names an object only when the catalogue knows it ("keys")."""
    out: list[ChunkGrounding] = []
    room_said = False
    for i, (record, g) in enumerate(zip(records, groundings)):
        label = record.label.upper()
        words = _words(record)
        g = _object_rules(record, label, words, g)
        if known is not None and not known[i] and not (g.object and is_object_word(g.object)):
            g = ChunkGrounding()
        g = _listener_rules(label, words, g)
        if g.room is not None and label in ROOM_LABELS and room_said and not _names_room_or_side(record):
            g = replace(g, room=None)
        g = _motion_rules(label, words, _passing(record, label, words, g))
        room_said = room_said or g.room is not None
        out.append(g)
    return out


def _names_room_or_side(record: ChunkRecord) -> bool:
    words = set(_words(record))
    return bool(words & ROOM_WORDS or words & set(SIDES)
                or any(str(t).upper() == "RM" for t in record.pos))


def _object_rules(record: ChunkRecord, label: str, words: list[str], g: ChunkGrounding) -> ChunkGrounding:
    if label == "OBTP":
        found = object_phrase(record.words, record.pos)
        return replace(g, object=found.kind if found else None)
    if label in REFERENCE_LABELS and not _names_furniture_only(record):
        found = object_phrase(record.words, record.pos)
        if found is None:
            return ChunkGrounding() if label == "OBRP" else g
        direction = next((LANDMARK_SIDES[w] for i, w in enumerate(words) if w in LANDMARK_SIDES
                          and not (w in SIDES and i + 1 < len(words) and words[i + 1] in INTENSIFIED)), None)
        if direction is None and (set(words) & BESIDE_WORDS or g.direction is None):
            direction = "beside"
        return ChunkGrounding(reference=found.kind, direction=direction or g.direction)
    return g


def _names_furniture_only(record: ChunkRecord) -> bool:
    canon, _ = canonical_tokens(record.words, record.pos)
    return any(w in FURNITURE_WORDS for w in canon)


def _listener_rules(label: str, words: list[str], g: ChunkGrounding) -> ChunkGrounding:
    if label != "PERS":
        return g
    side = next((SIDES[w] for w in words if w in SIDES), None)
    if side is None:
        return replace(g, room=None)
    return ChunkGrounding(reference="robot", direction=side)


def _motion_rules(label: str, words: list[str], g: ChunkGrounding) -> ChunkGrounding:
    said = set(words)
    if words and said <= STOP_WORDS and said & {"stop", "halt", "freeze"}:
        return ChunkGrounding(reference=STOP)
    if g.reference in ("move", "room", "wall", "door") and "halfway" in said and not said & set(SIDES):
        return replace(g, reference="room", direction="center")
    if g.reference in ("move", "room") and said & FAR_WORDS and said & END_WORDS and "room" in said:
        return replace(g, reference="room", direction="back")
    if g.reference == "move":
        side = _turned_side(words)
        if side is not None:
            return replace(g, direction=side)
    if label == "FURRP" and g.reference in FURNITURE_WORDS.values() and said & PASSING_WORDS:
        return replace(g, direction="back")
    # whose side: "the right end of the room" is the room's, "on your right" the listener's
    if g.reference == "robot" and said & {"room"} and not said & LISTENER:
        return replace(g, reference="room")
    if g.reference == "room" and said & LISTENER and not said & ROOM_WORDS and g.direction in SIDES:
        return replace(g, reference="robot")
    return g


def _passing(record: ChunkRecord, label: str, words: list[str], g: ChunkGrounding) -> ChunkGrounding:
    """"pass the couch" chunked as a room phrase that names no room: the far side of the couch
    (the passing rule of :func:`_motion_rules` reads it from a reference phrase)."""
    said = set(words)
    if label not in ROOM_LABELS or g.room is not None or not said & PASSING_WORDS or said & ROOM_WORDS:
        return g
    canon, _ = canonical_tokens(record.words, record.pos)
    furniture = [FURNITURE_WORDS[w] for w in canon if w in FURNITURE_WORDS]
    return ChunkGrounding(reference=furniture[-1], direction="back") if furniture else g


def _turned_side(words: list[str]) -> str | None:
    """The side of a turn or side step ("turn right again", "side step left", "make a left")."""
    for i, w in enumerate(words):
        if w in TURN_VERBS or (w == "side" and i + 1 < len(words) and words[i + 1] in ("step", "steps")):
            for later in words[i + 1:i + 5]:
                if later in SIDES:
                    return SIDES[later]
    return None

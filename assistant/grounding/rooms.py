"""Rooms named in so many words: the home's own room names override a learned room guess.

The grounders learn the *target room* field from labelled commands, so they only know the room
names the corpus labels (the CSISL homes have a living room and a bedroom). A home the robot
is told about has more — a hallway, an office, an alcove — and a learned guess for a room
chunk can only pick among the trained values ("go to the office" → living room). When the
chunk's own words name one of the home's rooms, that name is what the person meant;
:func:`named_room_groundings` puts it into the chunk's grounding.

Which chunks: a chunk grounded to a room (its room is replaced by the one named), or a chunk
that grounds to nothing else — no reference, direction or target — whose words name a room:
a room target phrase the grounder left empty, or a short command whose room the chunker read
as the object phrase ("go to [OBTP the bedroom]"); there the object is kept only when its own
word is said in the chunk too. Chunks of other kinds ("past the bedroom door", a reference to
a room on the way) are left alone.
"""

from __future__ import annotations

import re

from collections.abc import Iterable, Sequence
from dataclasses import replace

from assistant.grounding.types import ChunkGrounding, ChunkRecord
from assistant.grounding.vocabulary import canonical_word

__all__ = ["COMMON_ROOMS", "side_room_groundings", "first_named_room", "named_room", "named_room_groundings", "room_names_of",
           "unknown_room_named"]

#: rooms people name in homes (lower case); one a home does not have is answered, not guessed
COMMON_ROOMS = ("kitchen", "bathroom", "bedroom", "living room", "dining room", "office", "hallway",
                "garage", "laundry room", "basement", "attic", "den", "study", "guest room",
                "nursery", "playroom", "pantry", "porch", "studio", "meeting room", "family room",
                "sitting room", "lounge", "toilet", "utility room", "spare room", "cellar")

#: other names people give a room → the room name a home's floor plan uses: a home without a room
#: of the other name ("the sitting room" in a home with a living room) takes it as its own
ROOM_ALIASES = {
    "living room": ("sitting room", "lounge", "front room", "family room", "living area", "lounge room", "tv room",
                    "sitting area", "drawing room", "parlour", "parlor"),
    # not "hall" or "corridor": said of the way far more often ("to the end of the hall")
    "hallway": ("entrance hall", "entryway", "foyer"),
    "office": ("study", "home office", "workroom", "work room"),
    "bedroom": ("master bedroom", "main bedroom", "bed room", "sleeping room"),
    "bathroom": ("loo", "toilet", "washroom", "restroom", "wc"),
    "meeting room": ("conference room", "boardroom"),
    "small room": ("little room", "box room", "spare room"),
}


def room_aliases(rooms: Iterable[str]) -> dict[str, str]:
    """Other name → the home's room (:data:`ROOM_ALIASES`), for the ``rooms`` a home has, leaving
    out any name that is itself one of its rooms (an office and a study are two rooms there)."""
    own = set(rooms)
    return {alias: room for room, aliases in ROOM_ALIASES.items() if room in own
            for alias in aliases if alias not in own and not any(alias in r.split() for r in own)}


#: chunk labels that can say where to go (a room *target* phrase, outside or inside a room, the
#: object phrase and its "in the hallway");
#: a room named in a reference phrase (ORMRP "past the kitchen") is a landmark, not the target
ROOM_TARGET_LABELS = frozenset({"ORMTP", "IRMTP", "OBTP", "OBRP"})
#: words that say a room without naming it ("the room on the left", "the next doorway")
ROOM_WORDS = frozenset({"room", "rooms", "door", "doorway", "doors", "entrance", "hall", "hallway", "corridor",
                        "opening"})


def room_names_of(world) -> list[str]:
    """The room names of a :class:`~assistant.world.World` (lower case), longest first."""
    if world is None:
        return []
    names = {r.name.strip().lower() for r in world.floorplan.rooms}
    return sorted(names, key=lambda n: (-len(n.split()), n))


#: words before a room name that make it the way, not the goal ("down the hallway", "the end of
#: the hallway", "out of the kitchen", "past the office")
PATH_WORDS = frozenset({"down", "up", "along", "through", "across", "past", "of", "from", "out",
                        "via", "leave", "exit", "around", "by"})
#: words passed over when looking for the word before a room name
SKIPPED_BEFORE = frozenset({"the", "a", "an", "this", "that", "my", "your", "our", "uh", "um", "er", "erm"})
#: words after a room name that make it a landmark on the way ("past the bedroom door")
LANDMARK_WORDS = frozenset({"door", "doors", "doorway", "entrance", "opening", "wall", "walls"})


def named_room(words: Sequence[str], rooms: Iterable[str], path_words: frozenset[str] = PATH_WORDS) -> str | None:
    """The room of ``rooms`` said first in ``words`` (case-insensitive, multi-word names as
    given; "bed room" also matches "bedroom"); a name followed by a landmark word ("the
    bedroom door") or said as the way ("down the hallway") does not count. None when no room
    is named as a goal."""
    said = [w.strip().lower() for w in words if w.strip()]
    found: list[tuple[int, int, str, int]] = []  # (start, -length, room, end)
    rooms = list(rooms)
    names = [(room, room) for room in rooms] + [(alias, room) for alias, room in room_aliases(rooms).items()]
    for name, room in names:
        parts = name.split()
        n = len(parts)
        for i in range(len(said) - n + 1):
            if said[i:i + n] == parts:
                found.append((i, -n, room, i + n))
        if n == 1:  # said as two or three words ("bed room")
            for i in range(len(said)):
                for j in range(i + 2, min(len(said), i + 3) + 1):
                    if "".join(said[i:j]) == room:
                        found.append((i, -(j - i), room, j))
    found = [f for f in found if (f[3] >= len(said) or said[f[3]] not in LANDMARK_WORDS)
             and _word_before(said, f[0]) not in path_words]
    return min(found)[2] if found else None


def _word_before(said: Sequence[str], start: int) -> str | None:
    """The word before position ``start``, skipping determiners, possessives and fillers."""
    i = start - 1
    while i >= 0 and said[i] in SKIPPED_BEFORE:
        i -= 1
    return said[i] if i >= 0 else None


def _says_object(words: Sequence[str], obj: str) -> bool:
    said = {canonical_word(w) for w in words}
    return all(canonical_word(part) in said for part in obj.split())


def named_room_groundings(records: Sequence[ChunkRecord], groundings: Sequence[ChunkGrounding],
                          world) -> list[ChunkGrounding]:
    """``groundings`` with the rooms the chunks name in so many words (see the module doc);
    unchanged when ``world`` is None. When a chunk names a room, a chunk grounded to a room
    that says no room at all — not even "room" ("turn left" guessed as the bedroom before "go
    into the living room") — loses its guess: the room said is the one meant."""
    rooms = room_names_of(world)
    if not rooms:
        return list(groundings)
    said = [named_room(record.words, rooms) for record in records]
    out = []
    for record, g, room in zip(records, groundings, said):
        if room is None and g.room is not None and any(said) and not (
                {w.strip().lower() for w in record.words} & ROOM_WORDS):
            out.append(replace(g, room=None))  # a guess where another chunk names the room
        elif room is None or g.room == room:
            out.append(g)
        elif g.room is not None:
            out.append(replace(g, room=room))
        elif record.label in ROOM_TARGET_LABELS and g.reference is None and g.direction is None \
                and g.target is None:
            obj = g.object if g.object is not None and _says_object(record.words, g.object) else None
            out.append(replace(g, room=room, object=obj))
        else:
            out.append(g)
    return out


def identified_room(text: str, world) -> str | None:
    """The room a route says it ends in by naming it ("… take the first door on your left,
    that's the office, …", "the door on the right, which is the bedroom"), or None: the goal,
    whatever rooms the way passed through before."""
    rooms = room_names_of(world)
    if not rooms:
        return None
    said = re.findall(r"\b(?:that'?s|that is|which is|this is|it'?s|its|thats) (?:the|your|my|our) ("
                      + "|".join(re.escape(r) for r in rooms) + r")\b", (text or "").lower())
    return said[-1] if said else None


def first_named_room(records: Sequence[ChunkRecord], world) -> str | None:
    """The first of the home's rooms named in any chunk (landmarks excepted) — the target room
    of a command that names its room only inside a place phrase ("the laptop is on the table in
    the middle of the meeting room"); None without a world or a named room."""
    rooms = room_names_of(world)
    for record in records:
        # "the middle of the meeting room" names its goal with "of"
        room = named_room(record.words, rooms, PATH_WORDS - {"of"}) if rooms else None
        if room is not None:
            return room
    return None


#: furniture that says its room by the room's name in any home (common sense, not the map: the
#: robot knows the rooms, not where the furniture is) — a couch or a desk stands in many rooms
FURNITURE_ROOM_WORDS = {"bed": "bedroom"}


def furniture_room(nodes, world) -> str | None:
    """The room a plan's furniture says when the plan names no room ("the statue is on the round
    table next to the bed": the bedroom), when the home has one room of that name; else None.
    The executor goes there (the plan's room stays what the words said)."""
    rooms = room_names_of(world)
    for node in nodes:
        for word in (node.target, *(reference for reference, _ in node.pairs)):
            kind = FURNITURE_ROOM_WORDS.get(str(word or ""))
            homes = [r for r in rooms if kind and kind in r.split()]
            if len(homes) == 1:
                return homes[0]
    return None


def unknown_room_named(words: Sequence[str], world) -> str | None:
    """The first room of :data:`COMMON_ROOMS` the words name as a goal that the home does not
    have ("go to the kitchen" in a home without one), or None."""
    rooms = set(room_names_of(world))
    if not rooms:
        return None
    aliases = room_aliases(rooms)
    other = [r for r in COMMON_ROOMS if r not in rooms and r not in aliases
             and not any(r in mine.split() for mine in rooms)]
    return named_room(words, other, PATH_WORDS - {"from", "of"})


#: words of a room phrase that say the robot goes in ("the room on your right", "the door on the left")
ENTERING = frozenset({"room", "door", "doorway", "entrance", "opening", "into", "enter", "entryway",
                      "doors", "openings", "in"})
#: words said before that take the robot elsewhere first ("the end of the hallway", "the second room")
ELSEWHERE = frozenset({"end", "down", "through", "past", "second", "third", "last", "far", "beyond", "across"})
#: listener sides
SIDES = ("left", "right")


def side_room_groundings(records: Sequence[ChunkRecord], groundings: Sequence[ChunkGrounding],
                         world) -> list[ChunkGrounding]:
    """``groundings`` with the first room phrase that names no room but a side from the start
    ("the room on your right", "take a left into the room") grounded by the floor plan: the room
    joined to the start's through the passage on that side
    (:meth:`~assistant.world.model.Floorplan.room_faced`). Left alone when something said
    before takes the robot elsewhere first ("the end of the hallway"), when the words name a
    room of the home anywhere ("go out the door, turn left, then go into the living room": the
    living room, not the room on the left), or without a world."""
    out = list(groundings)
    if world is None:
        return out
    rooms = room_names_of(world)
    if any(named_room([w.strip().lower() for w in r.words], rooms) is not None for r in records):
        return out
    generic: list[int] = []  # earlier room phrases that name no room ("the room")
    for i, (record, g) in enumerate(zip(records, groundings)):
        words = [w.strip().lower() for w in record.words]
        if set(words) & ELSEWHERE or named_room(words, rooms) is not None:
            return out
        if record.label not in ("ORMTP", "ORMRP"):
            continue
        sides = [w for w in words if w in SIDES]
        if not sides or (record.label == "ORMTP" and not set(words) & ENTERING):
            generic.append(i)
            continue
        room = world.floorplan.room_faced(world.start, sides[-1])
        if room is not None:
            out[i] = replace(g, room=room)
            for j in generic:
                out[j] = replace(out[j], room=None)
        return out
    return out

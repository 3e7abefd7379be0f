"""What the words say beats a grounder's guess: a furniture reference nobody named.

A learned grounder can ground a chunk to a furniture reference whose word the chunk does not
contain ("just ahead of you" → couch-front, because "ahead of" mostly comes with a couch in
the corpus). A furniture reference needs its furniture said (or pointed back to with "it",
"that", "one"); a chunk that names none but speaks of the listener ("you", "your") places
something from the robot. :func:`said_reference_groundings` makes those chunks ``robot``
references. Likewise a reference to a thing the chunk does not name while it names one kind of
furniture ("the table near the bed" → ``keys-beside-table``: "near the …" in an object chunk
mostly comes with a thing in the corpus) becomes that furniture. Every other grounding is left
as it is.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from assistant.grounding.objects import plural, singular
from assistant.grounding.types import ChunkGrounding, ChunkRecord
from assistant.grounding.vocabulary import FURNITURE_WORDS, canonical_tokens

__all__ = ["said_reference_groundings"]

#: words that point back to furniture said before ("to the left of it")
BACK_POINTERS = frozenset({"it", "its", "that", "this", "one", "them", "those", "these"})
#: words that make the listener (the robot) the reference
LISTENER_WORDS = frozenset({"you", "your", "yourself", "you're", "youre"})


def said_reference_groundings(records: Sequence[ChunkRecord],
                              groundings: Sequence[ChunkGrounding]) -> list[ChunkGrounding]:
    """``groundings`` with unnamed furniture references of listener chunks made ``robot``, and
    unnamed thing references of chunks that name one kind of furniture made that furniture."""
    out = []
    for record, g in zip(records, groundings):
        if g.reference is not None and g.reference not in NOT_THINGS:
            words, _ = canonical_tokens(record.words, record.pos)
            lowered = {w.lower() for w in words}
            furniture = {FURNITURE_WORDS[w] for w in lowered if w in FURNITURE_WORDS}
            if g.reference in FURNITURE_WORDS.values():
                named = bool(furniture) or lowered & BACK_POINTERS
                if not named and lowered & LISTENER_WORDS:
                    g = replace(g, reference="robot")
            elif len(furniture) == 1 and not _names(lowered, g.reference):
                g = replace(g, reference=next(iter(furniture)))
        out.append(g)
    return out


#: references that are not a thing said in the chunk (the robot, a room, the structure)
NOT_THINGS = frozenset({"robot", "room", "wall", "door", "doorway", "corner", "entrance", "window"})


def _names(words: set[str], reference: str) -> bool:
    """Whether the chunk's words name the thing ``reference`` (each of its words, singular or plural)."""
    return all(w in words or singular(w) in words or plural(w) in words for w in reference.split())

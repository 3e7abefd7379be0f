"""What the words say beats a grounder's guess: a furniture reference nobody named.

A learned grounder can ground a chunk to a furniture reference whose word the chunk does not
contain ("just ahead of you" → couch-front, because "ahead of" mostly comes with a couch in
the corpus). A furniture reference needs its furniture said (or pointed back to with "it",
"that", "one"); a chunk that names none but speaks of the listener ("you", "your") places
something from the robot. :func:`said_reference_groundings` makes those chunks ``robot``
references and leaves every other grounding as it is.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from assistant.grounding.types import ChunkGrounding, ChunkRecord
from assistant.grounding.vocabulary import FURNITURE_WORDS, canonical_tokens

__all__ = ["said_reference_groundings"]

#: words that point back to furniture said before ("to the left of it")
BACK_POINTERS = frozenset({"it", "its", "that", "this", "one", "them", "those", "these"})
#: words that make the listener (the robot) the reference
LISTENER_WORDS = frozenset({"you", "your", "yourself", "you're", "youre"})


def said_reference_groundings(records: Sequence[ChunkRecord],
                              groundings: Sequence[ChunkGrounding]) -> list[ChunkGrounding]:
    """``groundings`` with unnamed furniture references of listener chunks made ``robot``."""
    out = []
    for record, g in zip(records, groundings):
        if g.reference in FURNITURE_WORDS.values() and g.reference is not None:
            words, _ = canonical_tokens(record.words, record.pos)
            lowered = {w.lower() for w in words}
            named = any(w in FURNITURE_WORDS for w in lowered) or lowered & BACK_POINTERS
            if not named and lowered & LISTENER_WORDS:
                g = replace(g, reference="robot")
        out.append(g)
    return out

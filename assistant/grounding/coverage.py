"""Real descriptions to plans: does the plan hold what the person said?

For annotated descriptions (the real CSISL file, or any corpus XML) each description's text is
parsed as the product parses a command, and the plan is *covered* when

* it names the object the description names — the object phrase of the description's own
  annotated object chunks (OBTP), read with :func:`~assistant.grounding.objects.object_phrase`
  and compared by the catalogue's name; a description that names no object must give a plan
  with none — and
* no spatial word is left unused: no word of the plan's ``unused`` list is tagged (in the
  annotation) as furniture, room, structure, direction or spatial preposition (FUR, RM, STR,
  DIR, ON), nor is a motion or place word of :data:`SPATIAL_WORDS` ("forward", "steps",
  "halfway", "stop" …).

``assistant eval grounding --descriptions PATH`` reports the share covered and the first
misses, grouped by why.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence

from assistant.grounding.objects import object_phrase

__all__ = ["SPATIAL_TAGS", "SPATIAL_WORDS", "described_object", "plan_coverage"]

SPATIAL_TAGS = frozenset({"FUR", "RM", "STR", "DIR", "ON"})
SPATIAL_WORDS = frozenset({
    "left", "right", "forward", "forwards", "straight", "ahead", "behind", "front", "back", "next",
    "beside", "between", "across", "past", "pass", "around", "towards", "toward", "through",
    "halfway", "steps", "step", "paces", "pace", "feet", "degrees", "degree", "turn", "stop",
    "corner", "middle", "center", "centre", "end", "side", "far", "near", "opposite", "wall", "door",
    "room", "table", "couch", "bed", "chair", "desk", "nightstand",
})


def described_object(tree) -> str | None:
    """The object an annotated description names: the first object phrase found in its object
    chunks' own words (OBTP), as the catalogue names it; None when it names none."""
    for chunk, _, _ in tree.chunks():
        if chunk.label.upper() != "OBTP":
            continue
        own = chunk.own_tokens
        found = object_phrase([t.text for t in own], [t.pos for t in own])
        if found is not None:
            return found.kind
    return None


def _spatial_unused(unused: Sequence[str], tree) -> list[str]:
    tags: dict[str, set[str]] = {}
    for t in tree.tokens():
        tags.setdefault(t.text.lower(), set()).add(str(t.pos).upper())
    return [w for w in unused
            if w.lower() in SPATIAL_WORDS or tags.get(w.lower(), set()) & SPATIAL_TAGS]


def plan_coverage(parser, descriptions, limit: int = 20) -> dict:
    """Parse each description's text; the share whose plan names its object and leaves no
    spatial word unused (module doc), with counts of each way of missing and the first
    ``limit`` misses."""
    total = covered = 0
    why: Counter = Counter()
    words: Counter = Counter()
    misses = []
    for description in descriptions:
        text = description.text
        if not text.strip():
            continue
        total += 1
        want = described_object(description.tree)
        plan = parser.parse(text).plan
        reasons = []
        if plan.object != want:
            reasons.append("object" if want is not None else "object where none was named")
        spatial = _spatial_unused(plan.unused, description.tree)
        if spatial:
            reasons.append("spatial words unused")
            words.update(w.lower() for w in spatial)
        if not reasons:
            covered += 1
            continue
        why.update(reasons)
        if len(misses) < limit:
            misses.append({"number": description.number, "text": text, "object": [want, plan.object],
                           "unused": spatial})
    return {"descriptions": total, "covered": covered, "share": covered / total if total else 0.0,
            "why": dict(why.most_common()), "unused_words": dict(words.most_common(20)), "misses": misses}

"""Words taken back: "go into the bedroom, no wait, the living room" is "go into the living room".

People correct themselves in the middle of a description, out loud or typing as they think:
"go to the living room no sorry i mean the office", "turn left, no, turn right", "the mug is on
the table — wait no, it's on the desk". The grounders would read both the retracted words and
the correction, and the first room said wins. :func:`without_retractions` rewrites the text
before it is parsed: the clause before a retraction marker (:data:`MARKERS`) has its last
phrase replaced by the phrase said after the marker —

* a side, an end, an order or a size after the marker ("on the left I mean right") replaces
  the clause's last word of that kind (:data:`SWAPPED`) and what follows it;
* a noun phrase after the marker ("the living room") replaces the clause's last noun phrase
  (from its last article or possessive on);
* a place after it ("on the desk at the back") replaces the clause's place (from its first
  preposition on);
* anything else ("turn right") replaces the whole clause.

"it's", "they're" after the marker and a "sorry" at its end are dropped. The rest of the text
stays as said. Markers are only phrases that say a correction ("no wait", "sorry I mean", "or
rather", ", no,"), not "actually" or "I mean" alone at the start, which people say as fillers.
"""

from __future__ import annotations

import re

__all__ = ["MARKERS", "without_retractions"]

#: phrases that take back what was just said (longest first where one starts another)
MARKERS = (
    r"no\s+sorry\s+i\s+mean", r"sorry\s+no\s+i\s+mean", r"no\s+wait\s+i\s+mean", r"no\s+no", r"no\s+wait", r"wait\s+no",
    r"wait\s+wait", r"no\s+sorry", r"sorry\s+no", r"sorry\s+i\s+mean", r"no\s+i\s+mean", r"i\s+mean", r"no\s+actually",
    r"actually\s+no", r"oops", r"scratch\s+that", r"or\s+rather", r"correction", r"my\s+mistake", r"my\s+bad",
    r"i\s+meant", r"(?<=,)\s*no(?=\s*,)",
)
_MARKER = re.compile(r"(?:^|(?<=[\s,.;:!-]))(?:" + "|".join(MARKERS) + r")(?=$|[\s,.;:!-])", re.IGNORECASE)
#: where a clause ends
_CLAUSE_END = re.compile(r"\s*(?:[,.;:!]|\s-+\s|\s—\s|\bthen\b|\band\b)\s*", re.IGNORECASE)
_DETERMINERS = r"(?:the|a|an|my|your|our|his|her|their|this|that)"
_PREPOSITIONS = r"(?:on|in|at|by|near|next|under|behind|beside|besides|inside|into|onto|to|towards|toward|between|" \
                r"across|against|outside|over|opposite)"
_LEAD = re.compile(r"^(?:(?:it|they)\s*(?:'?s|'re|\s+is|\s+are|\s+was|\s+were)|its|theyre|it\s+s|they\s+re)\s+",
                   re.IGNORECASE)
_LEADING_FILLERS = re.compile(r"^(?:(?:sorry|oh|um|uh|er|well|ah|hmm|actually|wait|no|oops)[\s,.!-]+)+", re.IGNORECASE)
_TRAILING_SORRY = re.compile(r"[\s,]+sorry\s*[.!]*$", re.IGNORECASE)


def without_retractions(text: str, leading: bool = True) -> str:
    """The text with each retracted phrase replaced by its correction (see the module); the
    text as it is when nothing would be left ("no wait" alone is for the dialogue). With
    ``leading`` False, a text that starts with a marker is left as it is: in a conversation "no
    wait, the living room" takes back what the robot is doing, not words of the same sentence."""
    said_first = text
    first = _MARKER.search(text)
    if not leading and first is not None and not _LEADING_FILLERS.sub("", text[:first.start()].strip() + " ").strip(
            " ,.!-"):
        return text  # "no wait, the living room", "sorry, I meant the bedroom": the dialogue's to read
    for _ in range(8):  # a few corrections in one breath at most
        m = _MARKER.search(text)
        if m is None:
            break
        before, after = text[:m.start()], text[m.end():]
        after = _TRAILING_SORRY.sub("", after.lstrip(" ,.;:!-—"))
        after = _LEAD.sub("", after)
        head = before.rstrip(" ,.;:!-—")
        if not head.strip() or not after.strip():  # "I mean, …" at the start; a marker at the end
            text = (head + " " + after).strip() if head.strip() else after
            continue
        end = _CLAUSE_END.search(after)
        said, rest = (after[:end.start()], after[end.start():]) if end else (after, "")
        if said.strip().lower() in ("it", "that", "this", "them", "so", "well", "like"):
            text = head + rest  # "go to the couch, I mean it": emphasis, nothing taken back
            continue
        cut = [c.end() for c in _CLAUSE_END.finditer(head)]
        start = cut[-1] if cut else 0
        kept = head[:start]
        text = kept + (" " if kept and not kept[-1].isspace() else "") + _replaced(head[start:], said.strip()) + rest
    return text if text.strip() else said_first


#: words said in place of one another: "on the left I mean right" corrects the side only
SWAPPED = (frozenset({"left", "right"}), frozenset({"front", "back", "behind", "ahead"}), frozenset({"near", "far"}),
           frozenset({"first", "second", "third", "fourth", "last", "next"}),
           frozenset({"big", "small", "large", "little", "low", "high", "tall", "bigger", "smaller"}))


def _replaced(clause: str, said: str) -> str:
    """``clause`` with the part ``said`` corrects replaced by it."""
    first = said.split()[0].lower() if said.split() else ""
    swapped = next((kind for kind in SWAPPED if first in kind), None)
    if swapped is not None:  # "in the room on the left i mean right …": the side, and what follows
        last = [m for m in re.finditer(r"[A-Za-z]+", clause) if m.group(0).lower() in swapped]
        if last:
            return clause[:last[-1].start()] + said
    if re.fullmatch(_DETERMINERS, first):
        phrases = list(re.finditer(rf"\b{_DETERMINERS}\b", clause, re.IGNORECASE))
        if phrases:
            return clause[:phrases[-1].start()] + said
    if re.fullmatch(_PREPOSITIONS, first):
        place = re.search(rf"\b{_PREPOSITIONS}\b", clause, re.IGNORECASE)
        if place is not None:
            return clause[:place.start()] + said
    return said

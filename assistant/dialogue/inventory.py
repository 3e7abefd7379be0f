"""Questions about the home's furniture: "what's in the bedroom?", "is there a couch in the living
room?", "how many chairs are in the living room?".

The patterns are :data:`~assistant.dialogue.intents.FURNITURE_QUESTIONS` (the intent
``furniture``); :func:`furniture_asked` reads what a question asks about and
:func:`furniture_answer` answers it from the home's furniture as the robot knows it (the same
list the chat's "which table?" questions come from), grouping pieces by their model name ("two
round tables and a hexagon table"). A thing that is not furniture ("is there a mug in the
bedroom?") is a where-question, not this one: the manager sends it there.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

from assistant.grounding.objects import article
from assistant.dialogue.turns import NUMBER_WORDS, join_words
from assistant.grounding.objects import plural, singular
from assistant.grounding.vocabulary import canonical_word, furniture_category

__all__ = ["ANYTHING", "furniture_answer", "furniture_asked", "matching"]

#: what a question asks about when it asks about everything ("is there anything in the hallway?")
ANYTHING = frozenset({"", "anything", "something", "furniture", "things", "stuff", "any furniture", "pieces",
                      "pieces of furniture", "furniture pieces"})
#: the three shapes of question (intents.FURNITURE_QUESTIONS' groups)
KINDS = ("list", "yes_no", "count")


def furniture_asked(norm: str) -> tuple[str, str] | None:
    """``(kind, what)`` of a normalised furniture question — kind ``list``, ``yes_no`` or
    ``count``; ``what`` the words asked about ("" for everything) — or None."""
    from assistant.dialogue.intents import FURNITURE_QUESTIONS

    for kind, pattern in zip(KINDS, FURNITURE_QUESTIONS):
        m = re.search(pattern, norm)
        if m:
            what = (m.groupdict().get("what") or "").strip()
            what = re.sub(r"^(a|an|any|some|the) ", "", what)
            return ("list" if what in ANYTHING and kind != "count" else kind), what
    return None


def matching(items: Sequence, what: str) -> list:
    """The pieces ``what`` names: by model name ("coffee table", "desk") if any piece has it,
    else by category ("tables", "sofa", "nightstand" → table)."""
    one = singular(what)
    by_model = [f for f in items if f.model == one]
    if by_model:
        return by_model
    return [f for f in items if f.word == (furniture_category(one) or canonical_word(one))]


def _count(n: int, name: str) -> str:
    return f"{article(name)} {name}" if n == 1 else f"{NUMBER_WORDS.get(n, str(n))} {plural(name)}"


def _listing(items: Sequence) -> str:
    """"a bed, two round tables and a blue chair" (by model, in the order first met)."""
    counts: dict[str, int] = {}
    for f in items:
        counts[f.model] = counts.get(f.model, 0) + 1
    return join_words([_count(n, model) for model, n in counts.items()])


def _there(items: Sequence) -> str:
    return ("there is " if len(items) == 1 else "there are ") + _listing(items)


def furniture_answer(furniture: Sequence, rooms: Sequence[str], kind: str, what: str,
                     room: str | None) -> str:
    """The reply to a furniture question (see the module) about ``room`` (None: the whole home),
    from ``furniture`` (items with ``model``, ``word`` and ``room``)."""
    here = [f for f in furniture if room is None or f.room == room]
    where = f" in the {room}" if room else " here"
    if kind == "list" or not what:
        if room is None:
            parts = [(r, _listing(fs)) for r in rooms if (fs := [f for f in furniture if f.room == r])]
            if not parts:
                return "I don't know of any furniture here."
            return "; ".join([f"In the {parts[0][0]} I know of {parts[0][1]}"]
                             + [f"in the {r}, {said}" for r, said in parts[1:]]) + "."
        if not here:
            return f"I don't know of any furniture in the {room}."
        return f"In the {room} I know of {_listing(here)}."
    name = singular(what)
    found = matching(here, what)
    # a kind of piece no piece here is called ("a desk" where the tables are round, coffee, …)
    named = None if canonical_word(name) in {f.word for f in furniture} or any(f.model == name for f in furniture) \
        else name
    if not found:
        elsewhere = [r for r in rooms if matching([f for f in furniture if f.room == r], what)]
        other = (f" There {'is one' if len(matching(furniture, what)) == 1 else 'are some'} in "
                 + join_words([f"the {r}" for r in elsewhere]) + ".") if elsewhere and room is not None else ""
        return f"No — I don't know of any {plural(name) if kind == 'count' else name}{where}.{other}"
    category = found[0].word
    total = _count(len(found), category if named else name)
    said = _listing(found)
    if named is not None:  # "is there a desk?": not by that name, but these
        return f"I don't know of {article(name)} {name}{where}, but there {'is' if len(found) == 1 else 'are'} " \
               f"{said if said != total else total}."
    lead = "Yes — " if kind == "yes_no" else ""
    if kind == "count" and len(found) == 1:
        return f"There is just one {found[0].model}{where}."
    if kind == "count" and said != total and len({f.model for f in found}) > 1:
        text = f"there {'is' if len(found) == 1 else 'are'} {total}{where}: {said}"
    else:  # "two blue chairs in the living room"
        text = f"{_there(found)}{where}"
    return (lead + text if lead else text[0].upper() + text[1:]) + "."

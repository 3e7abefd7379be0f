"""The grounding vocabulary: canonical words for references, directions, targets and synonyms.

The RDT model (dissertation 4.3 II.B) names a *reference* (``move``, ``room``, ``wall``,
``door``, ``robot`` or a furniture word), a *direction* (``front``, ``back``, ``left``,
``right``, ``center``, ``beside``, ``between``) and a *target* (``non`` or a furniture word).
People say more words than that: *sofa* for couch, *night stand* for nightstand, *head* for go.
:func:`canonical_tokens` rewrites a chunk's words to canonical ones before any grounder sees
them, so a paraphrase meets the same templates and features as the corpus wording.

Furniture targets are grounded to the everyday category word the world uses for its entities
(``table`` for every table-like item: a nightstand, a desk, a coffee table), because that is
what the robot can recognise; the word the person actually said is kept as the plan's
``support`` (dissertation 4.3 II.B: "usually, a table … people usually put small objects on
table-like furniture").
"""

from __future__ import annotations

from collections.abc import Sequence

from assistant.rdt import DIRECTIONS, DYNAMIC_REFERENCES, NO_TARGET, STRUCTURE_REFERENCES  # noqa: F401 (re-exported)
from assistant.world.catalogue import category_word, load_catalogue

#: furniture category words the robot recognises (the catalogue's ``word`` values)
FURNITURE_CATEGORIES = ("table", "chair", "couch", "bed")

_WORDS = load_catalogue().words
#: single words → canonical word (lower case); the catalogue's ``words.synonyms``
SYNONYMS: dict[str, str] = _WORDS.synonyms
#: two-word phrases → one canonical word; the catalogue's ``words.phrases``
PHRASES: dict[tuple[str, str], str] = _WORDS.phrases
#: every one-word furniture word the grounders understand, with the category word it grounds to
#: (``nightstand`` → ``table``); from the catalogue's ``words.furniture``
FURNITURE_WORDS: dict[str, str] = {word: category_word(categories[0])
                                   for word, categories in _WORDS.furniture.items() if " " not in word}
#: furniture words that ground to the ``table`` category (table-like supports)
TABLE_LIKE = frozenset(w for w, c in FURNITURE_WORDS.items() if c == "table")
#: words said with a furniture word that describe which one ("the round table", "the big
#: table", "the coffee table") → a canonical descriptor (the catalogue's ``words.descriptors``);
#: the executor compares them with what it perceives (size class, footprint) to choose among
#: several of a kind
DESCRIPTORS: dict[str, str] = _WORDS.descriptors

#: words a person may say that carry no grounding on their own (for the ``unused`` list)
FILLERS = frozenset({
    "um", "uh", "er", "erm", "hmm", "well", "so", "okay", "ok", "please", "like", "just",
    "and", "then", "now", "the", "a", "an", "of", "to", "in", "on", "at", "it", "is", "you",
    "robot", "brian", "hey", "oh", "yeah", "alright", "go", ",", ".", "!", "?", ";", ":",
    "will", "can", "could", "would", "be", "there", "there's", "i", "me", "my", "your", "again",
})


def said_descriptors(words: Sequence[str]) -> tuple[str, ...]:
    """The canonical descriptors among a chunk's words, in order, without repeats
    (``["on", "the", "little", "round", "table"]`` → ``("small", "round")``)."""
    out: list[str] = []
    for w in words:
        d = DESCRIPTORS.get(w.strip().lower())
        if d is not None and d not in out:
            out.append(d)
    return tuple(out)


def canonical_word(word: str) -> str:
    """The canonical lower-case form of one word (``Sofa`` → ``couch``)."""
    w = word.strip().lower()
    return SYNONYMS.get(w, w)


def canonical_tokens(words: Sequence[str], pos: Sequence[str]) -> tuple[list[str], list[str]]:
    """Canonical words (and their tags) for one chunk: synonyms mapped, phrases merged.

    ``night stand`` becomes one token ``nightstand`` (tag ``FUR``); ``sofa`` becomes ``couch``.
    Empty tokens are dropped.
    """
    out_w: list[str] = []
    out_p: list[str] = []
    lowered = [w.strip().lower() for w in words]
    i = 0
    while i < len(lowered):
        if not lowered[i]:
            i += 1
            continue
        if i + 1 < len(lowered) and (lowered[i], lowered[i + 1]) in PHRASES:
            merged = PHRASES[(lowered[i], lowered[i + 1])]
            out_w.append(merged)
            out_p.append("FUR" if merged in FURNITURE_WORDS else "NN")
            i += 2
            continue
        out_w.append(SYNONYMS.get(lowered[i], lowered[i]))
        out_p.append(pos[i] if i < len(pos) else "NN")
        i += 1
    return out_w, out_p


def furniture_category(word: str | None) -> str | None:
    """The category word a furniture word grounds to (``nightstand`` → ``table``), or None."""
    if word is None:
        return None
    return FURNITURE_WORDS.get(canonical_word(word))


def match_token(word: str) -> str:
    """The token used for matching: furniture words collapse to their category word."""
    return FURNITURE_WORDS.get(word, word)


def canonical_value(field_name: str, value: str | None) -> str | None:
    """A label value in canonical form: furniture references and targets as category words
    (``nightstand`` → ``table``, ``sofa`` → ``couch``), directions canonical (``centre`` →
    ``center``), everything lower case."""
    if value is None:
        return None
    text = " ".join(value.strip().lower().split())
    if field_name in ("reference", "target"):
        return furniture_category(text) or SYNONYMS.get(text, text)
    if field_name == "direction":
        return {"centre": "center", "middle": "center", "behind": "back", "side": "beside",
                "next": "beside"}.get(text, text)
    return text

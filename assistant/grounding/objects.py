"""Open-vocabulary objects: the thing a person names, whatever it is.

A fetch or where-is command can name any object ("the keys", "your cell phone", "a ring of
keys", "the yellow notepad"), and an object can be a landmark ("next to the lamp", "with the
purse"). The grounders learn fields from a closed set of labelled values, so the object itself
is read from the words: :func:`object_phrase` finds the noun phrase a chunk names, and
:func:`object_kind` maps it to the catalogue's name for it where the catalogue knows one (its
``words`` table, ``assistant/world/data/catalogue.yaml``: "phone" → ``cell phone``, "key" →
``keys``, "computer" → ``laptop``), else to the phrase itself with its last word in the
singular ("the tissue boxes" → ``tissue box``).

Rules of the phrase, in order: fillers are skipped; a word that is the start of a word said
just after it is a restart and dropped ("the pho and the cell phone" → ``cell phone``); a
collective ("a ring of keys", "a pair of glasses") is read with what it collects; adjectives
before the noun are kept apart as :attr:`ObjectPhrase.adjectives` ("yellow"); nouns that say a
place, a part or a count ("the front", "the end", "two steps", "the object") never name an
object; furniture, rooms and structure words are the landmarks of other fields.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache

from assistant.grounding.vocabulary import FURNITURE_WORDS, SYNONYMS

__all__ = ["ObjectPhrase", "object_kind", "object_phrase", "object_phrases", "said_object", "singular",
           "is_object_word"]

#: nouns that say a place, a part, a count, a motion or nothing in particular — never an object
NOT_OBJECTS = frozenset({
    "object", "objects", "thing", "things", "item", "items", "something", "stuff", "one", "ones", "next", "other",
    "front", "top", "side", "sides", "middle", "center", "centre", "corner", "corners", "end", "ends",
    "edge", "back", "left", "right", "way", "bit", "part", "spot", "place", "area", "location",
    "direction", "position", "time", "turn", "step", "steps", "pace", "paces", "foot", "feet",
    "meter", "meters", "metre", "metres", "inch", "inches", "yard", "yards", "degree", "degrees",
    "angle", "couple", "halfway", "beginning", "start", "entrance", "entry", "opening", "openings",
    "room", "rooms", "hallway", "hall", "wall", "walls", "door", "doors", "doorway", "floor",
    "ground", "ceiling", "robot", "brian", "stop", "pass", "take", "walk", "go", "look", "face",
    "left-hand", "right-hand", "intersection", "house", "home", "kitchen", "bedroom", "bathroom",
    "office", "living", "dining", "closet", "lot", "few", "level", "row", "line", "surface",
    "find", "see", "get", "grab", "bring", "fetch", "pick", "spot", "notice", "locate", "search",
    "check", "need", "want", "put", "leave", "left", "sit", "rest", "lie", "lay", "laying",
    "let", "lets", "do", "does", "say", "says", "got", "better", "nothing", "smack", "youll", "walk",
    "walks", "goes", "think", "guess", "believe", "know", "kind", "sort", "color", "colour", "shape",
    "le", "yo", "tot", "er", "um", "uh", "uhm", "erm", "hmm", "you", "me", "it", "there",
    "m", "cm", "mm", "ft", "km", "centimeter", "centimeters", "centimetre", "centimetres",
})
#: words for a group of things: "a ring of keys" is the keys
COLLECTIVES = frozenset({"ring", "set", "bunch", "pair", "pile", "stack", "bundle", "pack",
                         "packet", "box", "bottle", "bag", "jar", "piece", "sheet", "cup"})
#: tags of nouns (Penn) and of words the tagger could only guess at
NOUN_TAGS = frozenset({"NN", "NNS", "NNP", "NNPS"})
ADJECTIVE_TAGS = frozenset({"JJ", "JJR", "JJS", "VBN"})
#: words that make the object after them a landmark of a place
LANDMARK_BEFORE = frozenset({"with", "by", "next", "near", "beside", "behind", "has", "have", "had",
                             "between", "besides", "from", "past", "around"})
#: "-ing" words that are things ("a ring"); any other is a verb or a gerund ("sitting")
ING_NOUNS = frozenset({"ring", "thing", "ceiling", "painting", "string", "building", "clothing",
                       "earring", "earrings", "charger", "wedding", "drawing", "stocking", "pudding",
                       "knitting", "sewing", "bedding", "stuffing", "icing", "packaging", "wrapping", "wiring",
                       "washing", "shopping", "ironing"})
#: words before an "-ing" word that make it the first of a compound noun when a noun follows
#: ("my hearing aid", "the walking stick", "her reading glasses", "a frying pan")
COMPOUND_BEFORE = frozenset({"my", "the", "a", "an", "your", "his", "her", "our", "their", "this", "that",
                             "some", "any", "new", "old", "spare"})
#: "-ing" words before a noun that say a room or an action, never a compound ("the living room",
#: "the following door", "the remaining chair")
NOT_COMPOUND_ING = frozenset({"living", "dining", "sitting", "waiting", "meeting", "following", "remaining",
                              "adjoining", "opposing", "coming", "ceiling", "landing", "building"})
#: words between a collective and what it holds
OF = "of"
FILLER_WORDS = frozenset({"um", "uh", "er", "erm", "uhm", "hmm", "like"})


@dataclass(frozen=True)
class ObjectPhrase:
    """An object as said: its noun words ("cell phone"), the adjectives before them ("yellow")
    and the catalogue's name for it (or the phrase in the singular)."""

    nouns: tuple[str, ...]
    adjectives: tuple[str, ...]
    kind: str

    @property
    def said(self) -> str:
        return " ".join((*self.adjectives, *self.nouns))


@lru_cache(maxsize=1)
def _catalogue_words() -> dict[str, str]:
    from assistant.world.catalogue import load_catalogue

    words = load_catalogue().object_words()
    indexed = dict(words)
    for word, name in words.items():  # the singular and plural of each name find it too
        indexed.setdefault(singular(word), name)
        indexed.setdefault(plural(word), name)
    return indexed


def singular(phrase: str) -> str:
    """The phrase with its last word in the singular ("car keys" → "car key", "boxes" → "box",
    "glasses" → "glass"); words that only look plural ("glass", "bus") stay."""
    parts = phrase.split()
    if not parts:
        return phrase
    w = parts[-1]
    if len(w) > 3 and w.endswith("ies"):
        w = w[:-3] + "y"
    elif len(w) > 3 and w.endswith(("ches", "shes", "sses", "xes", "zes")):
        w = w[:-2]
    elif len(w) > 2 and w.endswith("s") and not w.endswith(("ss", "us", "is")):
        w = w[:-1]
    return " ".join((*parts[:-1], w))


def plural(phrase: str) -> str:
    """The phrase with its last word in the plural ("key" → "keys", "box" → "boxes")."""
    parts = phrase.split()
    if not parts:
        return phrase
    w = parts[-1]
    if w.endswith("s") and not w.endswith("ss"):
        return phrase
    if w.endswith(("ch", "sh", "ss", "x", "z")):
        w += "es"
    elif w.endswith("y") and len(w) > 1 and w[-2] not in "aeiou":
        w = w[:-1] + "ies"
    else:
        w += "s"
    return " ".join((*parts[:-1], w))


#: word beginnings where the spelling misleads the sound: a vowel letter said with a consonant
#: ("a unicorn", "a one-cup kettle") or a silent h ("an hour")
_CONSONANT_SOUND = ("uni", "use", "usu", "usb", "ufo", "uk", "eu", "ewe", "one", "once", "ura", "ure", "uro")
_VOWEL_SOUND = ("hour", "honest", "honour", "honor", "heir", "herb")


def article(word: str) -> str:
    """The indefinite article a word takes: "a" or "an" ("an envelope", "a unicorn", "an hour")."""
    w = word.lower()
    if w.startswith(_VOWEL_SOUND):
        return "an"
    return "an" if w[:1] in "aeiou" and not w.startswith(_CONSONANT_SOUND) else "a"


def object_kind(phrase: str) -> str:
    """The catalogue's name of the object a phrase names ("ring of keys" → ``keys``, "phone" →
    ``cell phone``, "coffee cup" → ``mug``), trying the whole phrase, then without its first
    words; a phrase the catalogue does not know is returned in the singular."""
    words = _catalogue_words()
    text = " ".join(phrase.lower().split())
    parts = text.split()
    for i in range(len(parts)):
        tail = " ".join(parts[i:])
        for form in (tail, singular(tail)):
            if form in words:
                return words[form]
    if len(parts) >= 3 and parts[1] == OF and parts[0] in COLLECTIVES:
        return object_kind(" ".join(parts[2:]))
    return singular(text)


def is_object_word(word: str) -> bool:
    """Whether the catalogue knows the word (or phrase) as an object's name or other word."""
    return " ".join(word.lower().split()) in _catalogue_words()


def _nounish(word: str, tag: str) -> bool:
    if word in NOT_OBJECTS or word in FURNITURE_WORDS or SYNONYMS.get(word) in FURNITURE_WORDS:
        return False
    if is_object_word(word):  # whatever the tagger made of it ("glassescase")
        return True
    if tag in ("RM", "STR", "DIR", "WHO", "ON", "IGN", "POS", "CD", "PRP", "PRP$"):
        return False
    if not any(ch.isalpha() for ch in word):
        return False
    if word.endswith("ing") and len(word) > 4 and word not in ING_NOUNS and not is_object_word(word):
        return False
    # a tagger's FUR that is no furniture the robot knows ("lamp", "box") is a thing like any other
    return tag in NOUN_TAGS or tag == "FUR"


def _restarts(words: Sequence[str]) -> set[int]:
    """Positions of words cut off and said again: "the pho and the cell phone" (pho)."""
    out = set()
    for i, w in enumerate(words):
        if len(w) < 2:
            continue
        for later in words[i + 1:i + 6]:
            if later != w and later.startswith(w) and len(later) > len(w):
                out.add(i)
                break
    return out


def object_phrase(words: Sequence[str], pos: Sequence[str]) -> ObjectPhrase | None:
    """The first object a chunk's words name (see the module doc), or None."""
    found = object_phrases(words, pos)
    return found[0][0] if found else None


def object_phrases(words: Sequence[str], pos: Sequence[str]) -> list[tuple[ObjectPhrase, bool]]:
    """Every object a chunk's words name, in order, each with whether it is said as a landmark
    (after "with", "by", "next to", "has" …: "the table with the computer")."""
    lowered = [w.strip().lower() for w in words]
    tags = [str(p).upper() for p in pos] + ["NN"] * (len(lowered) - len(pos))
    cut = _restarts(lowered)
    keep = [(w, t) for i, (w, t) in enumerate(zip(lowered, tags)) if i not in cut and w and w not in FILLER_WORDS]
    out: list[tuple[ObjectPhrase, bool]] = []
    i = 0
    while i < len(keep):
        w, t = keep[i]
        compound = _ing_compound(keep, i)
        if not compound and not _nounish(w, t) and not (w in COLLECTIVES and i + 1 < len(keep) and keep[i + 1][0] == OF):
            i += 1
            continue
        j = i + 1 if compound else i
        while j < len(keep) and _nounish(*keep[j]):
            j += 1
        nouns = [x for x, _ in keep[i:j]] or [w]
        if nouns[-1] in COLLECTIVES and j + 1 < len(keep) and keep[j][0] == OF:
            k = j + 1
            while k < len(keep) and keep[k][1] in ("DT", "PRP$"):
                k += 1
            m = k
            while m < len(keep) and _nounish(*keep[m]):
                m += 1
            if m > k:
                nouns = [*nouns, OF, *[x for x, _ in keep[k:m]]]
                j = m
        if nouns == [w] and not _nounish(w, t):  # a collective with nothing after "of"
            i += 1
            continue
        if _describes_furniture(keep, j):  # "a light wood table", "the sand colored table"
            i = j
            continue
        adjectives = []
        a = i - 1
        while a >= 0 and keep[a][1] in ADJECTIVE_TAGS and keep[a][0] not in NOT_OBJECTS:
            adjectives.insert(0, keep[a][0])
            a -= 1
        landmark = any(w in LANDMARK_BEFORE for w, _ in keep[max(0, a - 2):a + 1])
        out.append((ObjectPhrase(tuple(nouns), tuple(adjectives), object_kind(" ".join(nouns))), landmark))
        i = j
    return out


def _ing_compound(keep, i: int) -> bool:
    """Whether the "-ing" word at ``i`` starts a compound noun: after a determiner or possessive
    and before a noun ("my hearing aid", "the walking stick"; not "the living room")."""
    w = keep[i][0]
    return (w.endswith("ing") and len(w) > 4 and w not in NOT_COMPOUND_ING and w not in ING_NOUNS
            and i > 0 and keep[i - 1][0] in COMPOUND_BEFORE
            and i + 1 < len(keep) and _nounish(*keep[i + 1]))


def _describes_furniture(keep, j: int) -> bool:
    """Whether the nouns ending before position ``j`` are followed (past adjectives) by a
    furniture word, so that they say what the furniture is made of or looks like."""
    while j < len(keep) and keep[j][1] in ADJECTIVE_TAGS:
        j += 1
    return j < len(keep) and (keep[j][0] in FURNITURE_WORDS or SYNONYMS.get(keep[j][0]) in FURNITURE_WORDS)


def said_object(chunks) -> str | None:
    """The object a command names outside its object phrases: the first the catalogue knows
    among the chunks' own words, not said as a landmark ("on the desk you will see the keys";
    "the table with the computer" is no laptop to fetch). ``chunks``: (words, tags) pairs."""
    for words, tags in chunks:
        for found, landmark in object_phrases(words, tags):
            if not landmark and is_object_word(found.kind):
                return found.kind
    return None

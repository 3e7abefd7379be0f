"""How far and how much: step and pace counts, distances and turn angles in a chunk's words.

People move the robot in their own units: "take two steps forward", "about four paces", "side
step left a couple of steps", "turn left 90 degrees", "a 45 degree angle", "a few feet". A
**step** (or pace) is :data:`STEP_M` = 0.6 m, an adult's ordinary walking step; a foot is
0.3048 m, a metre 1 m, and the short forms count after a number ("2 m", "50 cm", "1.5m"). "A couple" is 2, "a few" 3, "a step" 1; two numbers said together ("about
4 er 5 steps", "1 or 2 steps") average. :func:`said_amount` reads them; the words it reads are
:data:`AMOUNT_WORDS` (and numbers), which the plan then counts as used.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

__all__ = ["STEP_M", "Amount", "AMOUNT_WORDS", "said_amount", "is_amount_word", "split_units"]

#: one step or pace of a person, in metres
STEP_M = 0.6
#: length units → metres
UNITS_M = {"step": STEP_M, "steps": STEP_M, "pace": STEP_M, "paces": STEP_M, "stride": STEP_M,
           "strides": STEP_M, "foot": 0.3048, "feet": 0.3048, "meter": 1.0, "meters": 1.0,
           "metre": 1.0, "metres": 1.0, "yard": 0.9144, "yards": 0.9144,
           # written short ("2 m", "50 cm", "3 ft"): a unit only after a number
           "m": 1.0, "cm": 0.01, "centimeter": 0.01, "centimeters": 0.01, "centimetre": 0.01,
           "centimetres": 0.01, "ft": 0.3048, "mm": 0.001, "millimeters": 0.001, "millimetres": 0.001}
#: a number with its unit written on ("1.5m", "50cm", "3ft")
_NUMBER_WITH_UNIT = re.compile(r"^(\d+(?:\.\d+)?)(m|cm|mm|ft)$")
ANGLE_WORDS = frozenset({"degree", "degrees", "angle"})
NUMBER_WORDS = {"one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
                "nine": 9, "ten": 10, "eleven": 11, "twelve": 12, "fifteen": 15, "twenty": 20,
                "thirty": 30, "forty": 40, "forty-five": 45, "fortyfive": 45, "sixty": 60, "ninety": 90,
                "hundred": 100, "a": 1, "an": 1, "couple": 2, "few": 3, "half": 0.5}
#: words an amount is made of (besides numbers), which the plan uses
AMOUNT_WORDS = frozenset({*UNITS_M, *ANGLE_WORDS, "couple", "few", "half", "about", "around",
                          "roughly", "approximately", "or", "er", "uh"})
_NUMBER = re.compile(r"^\d+(\.\d+)?$")


@dataclass(frozen=True)
class Amount:
    """A distance (metres) and/or a turn angle (degrees) said in a chunk; None where not said."""

    distance_m: float | None = None
    degrees: float | None = None

    def __bool__(self) -> bool:
        return self.distance_m is not None or self.degrees is not None


def _number(word: str) -> float | None:
    if _NUMBER.match(word):
        return float(word)
    if "-" in word and all(p in NUMBER_WORDS for p in word.split("-")):
        return float(sum(NUMBER_WORDS[p] for p in word.split("-")))
    return None if word not in NUMBER_WORDS else float(NUMBER_WORDS[word])


def is_amount_word(word: str) -> bool:
    w = word.lower()
    return w in AMOUNT_WORDS or (_number(w) is not None and w not in ("a", "an")) or bool(_NUMBER_WITH_UNIT.match(w))


def split_units(words: Sequence[str]) -> list[str]:
    """The words with a unit written on its number said apart ("1.5m" → "1.5", "m") and a
    number "and a half" made one ("two and a half" → "2.5": its "and" joins no clauses)."""
    out: list[str] = []
    for w in words:
        m = _NUMBER_WITH_UNIT.match(w.strip().lower())
        out.extend(m.groups() if m else [w])
    i = 0
    while i + 3 < len(out):
        n = _number(out[i].lower())
        if n is not None and [x.lower() for x in out[i + 1:i + 4]] == ["and", "a", "half"]:
            out[i:i + 4] = [f"{n + 0.5:g}"]
        i += 1
    return out


def said_amount(words: Sequence[str]) -> Amount:
    """The distance and angle a chunk's words say ("take 2 steps forward" → 1.2 m; "turn left
    90 degrees" → 90°; "a 45 degree angle" → 45°); an empty :class:`Amount` when none."""
    lowered = split_units([w.strip().lower() for w in words if w.strip()])
    distance = degrees = None
    numbers: list[float] = []
    article = False  # the numbers so far are only "a"/"an"
    previous = ""
    for w in lowered:
        n = _number(w)
        if w in ("a", "an") and previous == "half":
            pass  # "half a meter": the half stands
        elif w in ("a", "an"):
            numbers, article = [1.0], True
        elif w in ("couple", "few", "half"):
            numbers, article = [float(NUMBER_WORDS[w])], False
        elif n is not None:
            numbers, article = ([n] if article else [*numbers, n]), False
        elif w in UNITS_M:
            if numbers and distance is None:  # "step forward" with no count is the verb
                count = sum(numbers[-2:]) / len(numbers[-2:])
                distance = count * UNITS_M[w]
            numbers = []
        elif w in ANGLE_WORDS:
            said = [x for x in numbers if x >= 5]
            if said and degrees is None:
                degrees = said[-1]
            numbers = []
        elif w not in AMOUNT_WORDS and w != "of":
            numbers, article = [], False
        previous = w
    return Amount(distance, degrees)

"""Moves said outside every chunk: "go forward and …", "ok left left", "stop".

Real speakers start with a move the chunker leaves outside every chunk ("go forward and the
laptop is on the table", "come forward brian and turn left …"), and say bare turns and stops
between phrases. :func:`loose_moves` reads one run of words outside the chunks and returns the
moves it says — ``(move, front)``, ``(move, left)``, ``(stop, center)`` — with the positions of
the words each one uses, so that the plan takes them as steps in the order said and does not
list their words as unused.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistant.grounding.amounts import is_amount_word

__all__ = ["loose_moves", "MOTION_VERBS"]

MOTION_VERBS = frozenset({"go", "come", "move", "walk", "head", "drive", "continue", "keep", "proceed",
                          "step", "roll", "turn", "make", "take", "hang", "veer", "bear", "goes",
                          "moving", "going", "walking", "coming", "turning", "went"})
#: words that say which way → the RDT direction of a move
MOVE_SIDES = {"forward": "front", "forwards": "front", "straight": "front", "ahead": "front",
              "onward": "front", "left": "left", "right": "right", "backward": "back",
              "backwards": "back", "back": "back"}
#: words after "right" that make it an adverb ("right there", "right next to")
NOT_A_SIDE_AFTER = frozenset({"there", "here", "next", "in", "on", "by", "at", "away", "now", "behind",
                              "beside", "up", "down", "into", "where", "of", "side", "hand", "corner"})
#: words before a side that make it a place
PLACE_BEFORE = frozenset({"the", "your", "on", "to", "at", "his", "her", "my", "its", "their"})
STOP_WORDS = frozenset({"stop", "halt"})
#: words that may stand between a verb and its side ("go straight", "turn to your left")
BETWEEN = frozenset({"to", "your", "the", "a", "an", "his", "her", "uh", "um", "er", "just", "then",
                     "on", "over", "towards", "toward", "off", "slightly"})


def loose_moves(words: Sequence[str]) -> list[tuple[tuple[str, str], list[int]]]:
    """The moves a run of words outside the chunks says, in order, each with the positions of
    its words; repeated forward moves in a row ("go straight go ahead") are one."""
    lowered = [w.strip().lower() for w in words]
    out: list[tuple[tuple[str, str], list[int]]] = []
    for i, w in enumerate(lowered):
        if w in STOP_WORDS:
            out.append((("stop", "center"), [i]))
            continue
        side = MOVE_SIDES.get(w)
        if side is None:
            continue
        after = lowered[i + 1] if i + 1 < len(lowered) else None
        verb = _verb_before(lowered, i)
        if w in ("left", "right") and after in NOT_A_SIDE_AFTER:
            continue
        if verb is None and (w == "back" or (i > 0 and lowered[i - 1] in PLACE_BEFORE)):
            continue  # "on the left", "to your right": a place, not a move
        if verb is None and w in ("straight", "ahead", "forward", "forwards") and i > 0 \
                and lowered[i - 1] not in ("and", "then", "so", "ok", "okay"):
            continue
        used = [i] + ([verb] if verb is not None else [])
        used += [j for j in range(i + 1, min(len(lowered), i + 6)) if is_amount_word(lowered[j])]
        if out and out[-1][0] == ("move", side) and side == "front" and max(out[-1][1]) >= i - 3:
            out[-1][1].extend(used)
            continue
        out.append((("move", side), sorted(set(used))))
    return out


def _verb_before(words: Sequence[str], i: int) -> int | None:
    """The position of the motion verb a side word belongs to ("go … straight"), or None."""
    j = i - 1
    while j >= 0 and i - j <= 4:
        if words[j] in MOTION_VERBS:
            return j
        if words[j] not in BETWEEN and not is_amount_word(words[j]):
            return None
        j -= 1
    return None

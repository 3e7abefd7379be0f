"""Moves said to the robot itself: "turn left", "turn around", "back up a little", "go forward
two meters and then turn right".

The corpus grounders read *descriptions of where something is*, in which "take a left" at the
doors picks the room on that side. A person standing by the robot also just moves it, with
nothing else in the sentence; those words name no room, furniture or object, and the learned
grounders have nothing to go on ("turn around" grounded to nothing, "turn left" to the room on
the left). :func:`read_motion` reads a command made only of such moves, clause by clause, into
``move-<direction>-non`` nodes that carry their amount, as the executor carries out counted
moves (:func:`~assistant.executor.spoken.amount_goal`):

* a turn ("turn left", "take a right", "face left", "spin around") turns on the spot: 90°, 180°
  around, 30° "a little", or the degrees said;
* a move ahead goes the distance said, :data:`DEFAULT_MOVE_M` when none is said and
  :data:`SMALL_MOVE_M` for "a bit"; a move to a side ("move left two steps") side-steps;
* a move back ("back up", "reverse a bit", "move back one meter") reverses, up to
  :data:`MAX_REVERSE_M` (the camera looks ahead: a longer way back turns round first).

Any other word — a room, furniture, "me", "there" — and the command is not a pure move: it goes
to the grounders as before. :func:`describe_motion` says back what the robot will do.
"""

from __future__ import annotations

from collections.abc import Sequence

from assistant.grounding.amounts import AMOUNT_WORDS, is_amount_word, said_amount, split_units
from assistant.grounding.types import RDTNode
from assistant.rdt import NO_TARGET

__all__ = ["DEFAULT_MOVE_M", "DEFAULT_TURN_DEG", "MAX_REVERSE_M", "SMALL_MOVE_M", "SMALL_TURN_DEG",
           "describe_motion", "is_motion_plan", "read_motion", "reverses"]

#: how far "go forward" goes when no distance is said (metres)
DEFAULT_MOVE_M = 1.0
#: how far "a bit", "a little" goes (metres)
SMALL_MOVE_M = 0.5
#: how far "back up" reverses when no distance is said (metres)
DEFAULT_REVERSE_M = 0.5
#: the longest way the robot reverses blind (metres); longer, it turns round and drives
MAX_REVERSE_M = 1.0
#: a turn with no angle said (degrees)
DEFAULT_TURN_DEG = 90.0
#: "turn a little left" (degrees)
SMALL_TURN_DEG = 30.0

#: words that start or join clauses
SEPARATORS = frozenset({"and", "then", ",", ".", ";", "!", "next", "after", "that", "afterwards"})
#: words said around a move that change nothing
FILLERS = frozenset({"please", "robot", "ok", "okay", "now", "just", "so", "hey", "um", "uh", "er", "erm",
                     "can", "could", "would", "will", "you", "also", "alright", "again", "the", "to", "your",
                     "yourself", "a", "an", "by", "of", "about", "around", "for", "me", "us", "kindly", "quickly",
                     "slowly", "carefully", "little", "bit", "slightly", "tad", "touch", "go", "going", "way"})
#: verbs of a move
MOVE_VERBS = frozenset({"go", "move", "drive", "walk", "head", "roll", "step", "scoot", "inch", "keep",
                        "continue", "proceed", "come", "advance"})
#: verbs of a turn
TURN_VERBS = frozenset({"turn", "rotate", "spin", "face", "pivot", "swing", "take", "make", "hang"})
#: verbs that turn only when no distance is said ("take a left", but "take two steps left")
COUNTED_VERBS = frozenset({"take", "make"})
#: verbs of a move back
REVERSE_VERBS = frozenset({"reverse", "back"})
#: direction words → RDT direction ("around" is a half turn)
DIRECTION_WORDS = {"forward": "front", "forwards": "front", "ahead": "front", "straight": "front",
                   "onward": "front", "onwards": "front", "on": "front",
                   "back": "back", "backward": "back", "backwards": "back", "up": None,
                   "left": "left", "right": "right", "around": "around", "round": "around",
                   "other": "around"}
#: words that make a move small
SMALL_WORDS = frozenset({"little", "bit", "slightly", "tad", "touch", "smidge", "inch"})
#: a way the move goes along, said with a distance ("go down the hallway about 5 metres"): the
#: move ahead, as far as said (without a distance the hallway is a room for the grounders)
ALONG_WORDS = frozenset({"down", "along"})
WAY_WORDS = frozenset({"hall", "hallway", "corridor", "passage", "passageway", "landing"})
#: a last clause that only ends the move ("… then stop", "and stop there")
END_CLAUSES = (("stop",), ("stop", "there"), ("and", "stop"), ("then", "stop"), ("stop", "then"))
#: every word a pure move may use (besides numbers)
MOTION_VOCABULARY = SEPARATORS | FILLERS | MOVE_VERBS | TURN_VERBS | REVERSE_VERBS | set(DIRECTION_WORDS) \
    | SMALL_WORDS | AMOUNT_WORDS | {"more", "further", "farther"}


def _clauses(words: Sequence[str]) -> list[list[str]]:
    out: list[list[str]] = [[]]
    for w in words:
        if w in SEPARATORS and not (w == "that" and out[-1]):
            if out[-1]:
                out.append([])
        else:
            out[-1].append(w)
    return [c for c in out if c]


def _clause_node(words: list[str]) -> RDTNode | None:
    """One clause's move, or None when it says no direction."""
    amount = said_amount(words)
    small = any(w in SMALL_WORDS for w in words) and not (amount.distance_m or amount.degrees)
    turning = any(w in TURN_VERBS - COUNTED_VERBS for w in words) or (
        amount.distance_m is None and any(w in COUNTED_VERBS for w in words))
    reversing = any(w in REVERSE_VERBS for w in words) and "turn" not in words
    directions = []
    for i, w in enumerate(words):
        if w == "up":
            if i and words[i - 1] == "back":
                directions.append("back")
            continue
        if w == "around" and i + 1 < len(words) and is_amount_word(words[i + 1]):
            continue  # "around two meters": an approximate amount
        if w == "on" and not (i and words[i - 1] in MOVE_VERBS | {"going"}):
            continue
        if w == "other" and not (i + 1 < len(words) and words[i + 1] == "way"):
            continue
        if w in DIRECTION_WORDS and DIRECTION_WORDS[w] is not None:
            directions.append(DIRECTION_WORDS[w])
    if not directions and any(w in ("keep", "continue", "proceed", "advance") for w in words):
        directions = ["front"]
    if not directions and amount.distance_m is not None and any(w in MOVE_VERBS for w in words):
        directions = ["front"]  # "drive 1.5 m", "walk three meters": ahead
    if not directions and "reverse" in words:
        directions = ["back"]
    if not directions:
        return None
    direction = directions[-1]
    if direction == "back" and "come" in words:
        return None  # "come back": to the person, not a move back
    if direction == "back" and (turning and not reversing):
        direction = "around"  # "turn back": face the other way
    if direction == "around":
        return RDTNode(NO_TARGET, (("move", "left"),), degrees=amount.degrees or 180.0)
    if direction in ("left", "right"):
        if not turning and (amount.distance_m is not None or small):  # "move left a bit": a side step
            return RDTNode(NO_TARGET, (("move", direction),), distance_m=amount.distance_m or SMALL_MOVE_M)
        degrees = amount.degrees or (SMALL_TURN_DEG if small else DEFAULT_TURN_DEG)
        return RDTNode(NO_TARGET, (("move", direction),), degrees=degrees)
    if direction == "back":
        distance = amount.distance_m or (SMALL_MOVE_M if small else DEFAULT_REVERSE_M)
        return RDTNode(NO_TARGET, (("move", "back"),), distance_m=distance)
    distance = amount.distance_m or (SMALL_MOVE_M if small else DEFAULT_MOVE_M)
    return RDTNode(NO_TARGET, (("move", "front"),), distance_m=distance)


def read_motion(words: Sequence[str]) -> list[RDTNode] | None:
    """The moves of a command made only of moves and turns (see the module), in order, or None
    when any word says something else or a clause names no direction."""
    lowered = split_units([str(w).strip().lower() for w in words if str(w).strip()])
    lowered = [w for w in lowered if w not in ("'", '"', "?")]
    lowered = _along_the_way(_without_end(lowered))
    if not lowered or any(w not in MOTION_VOCABULARY and not is_amount_word(w) for w in lowered):
        return None
    if not any(w in DIRECTION_WORDS or w in ("keep", "continue", "proceed", "advance", "reverse") for w in lowered) \
            and not (any(w in MOVE_VERBS for w in lowered) and said_amount(lowered).distance_m is not None):
        return None
    nodes = []
    for clause in _clauses(lowered):
        if all(w in FILLERS or w in AMOUNT_WORDS for w in clause):
            continue  # "okay", "please" between clauses
        node = _clause_node(clause)
        if node is None:
            return None
        nodes.append(node)
    return nodes or None


def _without_end(words: list[str]) -> list[str]:
    """The words without a last clause that only stops ("go ahead two meters then stop")."""
    while words and words[-1] in (".", "!"):
        words = words[:-1]
    for end in sorted(END_CLAUSES, key=len, reverse=True):
        if len(words) > len(end) and tuple(words[-len(end):]) == end:
            return words[:-len(end)]
    return words


def _along_the_way(words: list[str]) -> list[str]:
    """"go down the hallway about 5 metres": in a clause with a distance, the way it goes along
    is dropped and "down"/"along" read as ahead; otherwise the words are left as they are."""
    out: list[list[str]] = []
    for clause in _clauses_kept(words):
        if any(w in WAY_WORDS for w in clause) and said_amount(clause).distance_m is not None:
            clause = [("ahead" if w in ALONG_WORDS else w) for w in clause if w not in WAY_WORDS]
        out.append(clause)
    return [w for clause in out for w in clause]


def _clauses_kept(words: list[str]) -> list[list[str]]:
    """The words cut into clauses, each keeping the separator that ends it."""
    out: list[list[str]] = [[]]
    for w in words:
        out[-1].append(w)
        if w in SEPARATORS and not (w == "that" and len(out[-1]) > 1):
            out.append([])
    return [c for c in out if c]


def is_motion_plan(plan) -> bool:
    """Whether a :class:`~assistant.grounding.types.GroundingPlan` only moves the robot by
    amounts — no room, no object, every node a counted move or turn of the robot itself — so it
    is carried out where the robot is, without entering a room or looking around."""
    nodes = list(getattr(plan, "nodes", []) or [])
    return bool(nodes) and plan.room is None and plan.object is None and all(
        n.pairs and all(r == "move" for r, _ in n.pairs) and n.target == NO_TARGET
        and (n.distance_m is not None or n.degrees is not None) for n in nodes)


def reverses(node: RDTNode) -> bool:
    """Whether a move node is carried out reversing (a move back of at most
    :data:`MAX_REVERSE_M`, no angle)."""
    return (node.pairs[0][1] == "back" and node.distance_m is not None and node.degrees is None
            and node.distance_m <= MAX_REVERSE_M + 1e-9)


def _metres(d: float) -> str:
    text = f"{d:.1f}".rstrip("0").rstrip(".")
    return f"{text} m"


def _one(node: RDTNode) -> str:
    direction = node.pairs[0][1]
    if node.distance_m is None:
        degrees = node.degrees or DEFAULT_TURN_DEG
        if abs(degrees - 180.0) < 1e-6:
            return "turning around"
        side = "" if direction not in ("left", "right") else f" {direction}"
        return f"turning{side}" + ("" if abs(degrees - DEFAULT_TURN_DEG) < 1e-6 else f" {degrees:.0f}°")
    if direction == "front":
        return f"moving forward {_metres(node.distance_m)}"
    if direction == "back":
        return f"backing up {_metres(node.distance_m)}" if reverses(node) else \
            f"turning around and moving {_metres(node.distance_m)}"
    return f"moving {_metres(node.distance_m)} to the {direction}"


#: the present participles of :func:`_one` → the past ("turning left" → "turned left")
PAST = {"turning": "turned", "moving": "moved", "backing": "backed"}


def describe_motion(nodes: Sequence[RDTNode], done: bool = False) -> str:
    """What the robot will do, said back: "turning left, then moving forward 2 m"; with ``done``
    what it did: "turned left, then moved forward 2 m"."""
    parts = [_one(n) for n in nodes]
    if done:
        parts = [" ".join(PAST.get(w, w) for w in p.split(" ")) for p in parts]
    return ", then ".join(parts)

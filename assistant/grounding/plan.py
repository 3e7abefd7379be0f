"""From grounded chunks to a :class:`GroundingPlan` (dissertation 4.3 II.B–C).

The chunk tree is walked forward, in the order the words were said:

* the first chunk grounded to a room gives the target room, the first grounded to an object
  the target object;
* a chunk grounded to a *target* (a FURTP: "on the table") opens one RDT node; the
  reference-direction pairs of the chunks nested in it ("to the right", "behind the couch")
  become that node's pairs, tried in order. A ``move`` pair nested in it ("walk straight until
  you are at the table") is a step of its own, taken before the node — when the chunk has a
  verb; without one ("on the table just ahead of you") it places the target from the robot
  (a ``robot`` pair); a ``room``/``robot`` chunk that says two sides ("at the back on the
  left") gives a pair for each;
* a reference chunk outside any target chunk is a node of its own: ``move``/``room``/``wall``
  /``door`` references give ``…-non`` nodes (dynamic); a ``robot`` or furniture reference
  with no target named ("the fork will be on the right") gives a node whose target is implied —
  a table, where people put small things (4.3 II.B) — and consecutive such pairs share it;
  said right after a target chunk beside it ("[on the little table] [next to the keys]") it is
  a pair of that target's node.

The plan then says what it could not use and what is missing or ambiguous (:data:`FLAG_HELP`).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

from assistant.grounding.amounts import Amount, is_amount_word, said_amount
from assistant.grounding.loose import loose_moves
from assistant.grounding.objects import is_object_word, object_phrases, said_object
from assistant.grounding.spoken import PASSING_WORDS
from assistant.grounding.types import ChunkGrounding, GroundingPlan, RDTNode
from assistant.grounding.vocabulary import (
    DESCRIPTORS,
    DYNAMIC_REFERENCES,
    FILLERS,
    FURNITURE_WORDS,
    NO_TARGET,
    canonical_tokens,
    said_descriptors,
)

#: direction used when a reference chunk names none (e.g. "go forward to" → move front)
DEFAULT_DIRECTION = {"move": "front", "room": "center", "wall": "front", "door": "front",
                     "robot": "front", "stop": "center"}
#: what each flag means (the dialogue turns them into questions)
FLAG_HELP = {
    "empty": "nothing was said",
    "not_understood": "no room, place or object could be grounded",
    "no_object": "no target object was named",
    "no_room": "no target room was named",
    "implied_target": "a place was described without naming the furniture; a table is assumed",
    "unreferenced_target": "a furniture target was named without a reference to find it by",
    "ambiguous_target": "the room has several items of the named target and no reference picks one",
    "missing_direction": "a reference was named without a direction; a default was used",
    "unused_words": "some words could not be used",
}


@dataclass
class _NodeBuilder:
    target: str
    pairs: list[tuple[str, str]] = field(default_factory=list)
    support: str | None = None
    implied: bool = False
    parent_id: int | None = None
    descriptors: tuple[str, ...] = ()
    amount: Amount = field(default_factory=Amount)

    def build(self) -> RDTNode:
        distance = None if self.amount.distance_m is None else round(self.amount.distance_m, 2)
        return RDTNode(self.target, tuple(self.pairs), self.support, self.implied, self.descriptors,
                       distance, self.amount.degrees)


def _has_verb(tokens) -> bool:
    """Whether a chunk's own tokens hold a verb (a Penn ``VB*`` tag): "walk until you reach the
    table" asks for a step, "just ahead of you" only says where."""
    return any(str(t.pos).upper().startswith("VB") for t in tokens)


#: direction words that place a thing in a room or beside the robot (canonical)
SIDE_WORDS = {"left": "left", "right": "right", "back": "back", "rear": "back", "front": "front"}


def said_directions(tokens, far_is_back: bool = False) -> list[str]:
    """The side words a chunk's own tokens say, canonical, in order ("at the back on the
    left" → back, left). With ``far_is_back`` (a room reference) "far" ("the far right
    corner") is the back of the room."""
    out = []
    for t in tokens:
        text = str(t.text).lower()
        word = "back" if far_is_back and text in ("far", "farthest", "furthest") else SIDE_WORDS.get(text)
        if word and str(t.pos).upper() in ("DIR", "NN", "JJ", "RB") and word not in out:
            out.append(word)
    return out


#: words said before a furniture word that place it in the room ("the back table", "the far desk")
ROOM_SIDE_ADJECTIVES = {"back": "back", "far": "back", "farthest": "back", "furthest": "back",
                        "rear": "back", "front": "front", "near": "front", "nearest": "front",
                        "left": "left", "right": "right", "middle": "center", "center": "center"}


def side_of_room(tokens) -> list[tuple[str, str]]:
    """``(room, side)`` pairs of side words said as adjectives of a furniture word ("the back
    table" → room back)."""
    words = [str(t.text).lower() for t in tokens]
    out = []
    for i, w in enumerate(words):
        side = ROOM_SIDE_ADJECTIVES.get(w)
        if side is None or (i > 0 and words[i - 1] in ("your", "my", "his", "her", "of", "to", "on")):
            continue
        j = i + 1
        while j < len(words) and (words[j] in DESCRIPTORS or words[j] in ROOM_SIDE_ADJECTIVES
                                  or words[j] in ("white", "brown", "wooden", "wood")):
            j += 1
        if j < len(words) and canonical_tokens([words[j]], ["FUR"])[0][0] in FURNITURE_WORDS \
                and ("room", side) not in out:
            out.append(("room", side))
    return out


def said_furniture(words: Sequence[str], pos: Sequence[str]) -> str | None:
    """The last furniture word among a chunk's own words, canonical (``nightstand``, ``couch``)."""
    canon, _ = canonical_tokens(words, pos)
    found = [w for w in canon if w in FURNITURE_WORDS]
    return found[-1] if found else None


def _support_target(target: str, support: str | None) -> str:
    """The node's target for a thing said to lie on ``support``: the grounders give ``table``
    for every place a thing lies (the study's objects lay on table-like furniture), but in a
    home keys are left on the bed and a phone on the couch — a support word of another category
    the robot recognises ("on the bed", "on the sofa", "on the chair") is the target itself."""
    category = FURNITURE_WORDS.get(support or "")
    if target == "table" and category is not None and category != "table":
        return category
    return target


def assemble_plan(tree, groundings: Sequence[ChunkGrounding]) -> GroundingPlan:
    """Build the plan of a chunk tree whose chunks (in pre-order) have ``groundings``."""
    chunks = tree.chunks()
    if len(chunks) != len(groundings):
        raise ValueError(f"{len(chunks)} chunks but {len(groundings)} groundings")
    plan = GroundingPlan()
    for g in groundings:
        if plan.room is None and g.room:
            plan.room = g.room
    # the object: the first of the object phrases the catalogue knows ("with a yellow clock on it
    # the glasses case is …" fetches the glasses case); else one it knows said elsewhere, not as a
    # landmark ("on the desk you will see the keys", chunked as a place); else the first said
    objects = [g.object for g in groundings if g.object]
    plan.object = next((o for o in objects if is_object_word(o)), None) \
        or said_object([([t.text for t in c.own_tokens], [t.pos for t in c.own_tokens]) for c, _, _ in chunks]) \
        or (objects[0] if objects else None)
    walk = _PlanWalk({id(chunk): g for (chunk, _, _), g in zip(chunks, groundings)})
    walk.visit(tree.items, None, 0)
    walk.flush_loose()
    builders = walk.builders
    if plan.room is not None:  # "go forward and turn into the room on the right": the way to the room
        builders = [b for b in builders if not any(b is r for r in walk.route)]
    for b in builders:  # "… the statue, that's the statue": the object is no landmark of itself
        if b.target != NO_TARGET:
            b.pairs = [p for p in b.pairs if p[0] != plan.object]
    plan.nodes = [b.build() for b in builders]
    dynamic = [n.dynamic for n in plan.nodes]
    plan.kind = ("dynamic" if all(dynamic) else "static" if not any(dynamic) else "mixed") if plan.nodes else "static"
    targets = [n for n in plan.nodes if n.target != NO_TARGET and not n.implied_target]
    plan.support = targets[-1].support if targets else None
    flags = walk.flags
    for n in plan.nodes:
        if n.implied_target:
            flags.append(f"implied_target:{n.target}")
        elif n.target != NO_TARGET and not n.referenced:
            flags.append(f"unreferenced_target:{n.target}")
    plan.flags = list(dict.fromkeys(flags))
    return plan


class _PlanWalk:
    """One walk over a chunk tree, in pre-order, turning grounded chunks into node builders."""

    def __init__(self, by_id: dict):
        self.by_id = by_id
        self.builders: list[_NodeBuilder] = []
        self.flags: list[str] = []
        self.loose: list = []  # the words of a run outside every chunk (top level only)
        self.room_said = False  # a room chunk has been visited (moves said before it are its route)
        self.route: list[_NodeBuilder] = []

    def pair_of(self, g: ChunkGrounding) -> tuple[str, str]:
        direction = g.direction
        if direction is None:
            direction = DEFAULT_DIRECTION.get(g.reference, "front")
            if g.reference != "stop":
                self.flags.append(f"missing_direction:{g.reference}")
        return g.reference, direction

    def flush_loose(self) -> None:
        for pair, _ in loose_moves([t.text for t in self.loose]):
            self.builders.append(_NodeBuilder(NO_TARGET, [pair]))
            if not self.room_said:
                self.route.append(self.builders[-1])
        self.loose.clear()

    def visit(self, items, enclosing: _NodeBuilder | None, parent_key: int) -> None:
        after: _NodeBuilder | None = None  # the node of the target chunk said just before
        for item in items:
            if not hasattr(item, "label"):
                if parent_key == 0:
                    self.loose.append(item)
                continue
            if parent_key == 0:
                self.flush_loose()
            g = self.by_id.get(id(item), ChunkGrounding())
            self.room_said = self.room_said or bool(g.room)
            if g.target:
                self._target_chunk(item, g)
                after = self.builders[-1]
            elif g.reference:
                self._reference_chunk(item, g, enclosing, parent_key, after)
                self.visit(item.items, enclosing, id(item))
            else:
                after = None
                self.visit(item.items, enclosing, id(item))

    def _target_chunk(self, item, g: ChunkGrounding) -> None:
        own = [t.text for t in item.own_tokens]
        support = said_furniture(own, [t.pos for t in item.own_tokens]) or g.target
        target = _support_target(g.target, support)
        node = _NodeBuilder(target, support=support, descriptors=said_descriptors(own))
        if g.reference and self.pair_of(g)[0] != target:  # "grab the remote from the sofa": no
            node.pairs.append(self.pair_of(g))           # couch in front of the couch
        node.pairs.extend(p for p in side_of_room(item.own_tokens) if p not in node.pairs)
        self.visit(item.items, node, id(item))
        # move steps nested in the target chunk were appended first; the node follows
        self.builders.append(node)

    def _reference_chunk(self, item, g: ChunkGrounding, enclosing: _NodeBuilder | None, parent_key: int,
                         after: _NodeBuilder | None = None) -> None:
        """A reference chunk: a step, a pair of the node it is nested in, a pair of the target
        chunk said just before it (``after``: "[on the table] [next to the lamp]"), or a node of
        its own with a table implied."""
        reference, direction = self.pair_of(g)
        if reference == "move" and enclosing is not None and not _has_verb(item.own_tokens):
            # "on the table just ahead of you": no step is asked for, the place is said from
            # where the robot stands
            reference = "robot"
        passing = enclosing is None and reference in FURNITURE_WORDS.values() and \
            any(str(t.text).lower() in PASSING_WORDS for t in item.own_tokens)
        if passing:  # "pass the couch": a step to its far side, no target there
            self.builders.append(_NodeBuilder(NO_TARGET, [(reference, direction)]))
        elif reference == "move" or (enclosing is None and reference in DYNAMIC_REFERENCES):
            amount = said_amount([t.text for t in item.own_tokens]) if reference == "move" else Amount()
            self.builders.append(_NodeBuilder(NO_TARGET, [(reference, direction)], amount=amount))
        elif enclosing is not None:
            enclosing.pairs.append((reference, direction))
            if reference in ("room", "robot"):  # "at the back on the left": both hold
                for extra in said_directions(item.own_tokens, far_is_back=reference == "room"):
                    if (reference, extra) not in enclosing.pairs:
                        enclosing.pairs.append((reference, extra))
        else:
            last = self.builders[-1] if self.builders else None
            if after is not None and after is last:  # the table said just before: "… next to the lamp"
                last.pairs.append((reference, direction))
            elif last is not None and last.implied and last.parent_id == parent_key:
                last.pairs.append((reference, direction))
            else:
                self.builders.append(_NodeBuilder("table", [(reference, direction)], None, True, parent_key))


def unused_words(tree, vocabulary: set[str] | frozenset[str], unknown: Sequence[str] = (),
                 corrections: dict[str, str] | None = None, plan: GroundingPlan | None = None) -> list[str]:
    """Words the plan could not use: unknown to the grounder (or the tagger) or outside every
    chunk, fillers excepted; a typo the tagger corrected counts as its correction. A descriptor
    inside a chunk ("dinner" in "the dinner table") is used: the plan's node keeps it to choose
    among several tables. Returned as said, in order."""
    unknown_set = {u.lower() for u in unknown}
    corrections = corrections or {}
    labels = tree.nested_labels()
    tokens = tree.tokens()
    used = _loose_used(tokens, labels) | (_object_words_used(tree, plan) if plan is not None else set())
    out = []
    for i, (token, label) in enumerate(zip(tokens, labels)):
        canon, _ = canonical_tokens([corrections.get(token.text, token.text)], [token.pos])
        word = canon[0] if canon else ""
        if not word or word in FILLERS or not any(ch.isalnum() for ch in word) or i in used:
            continue
        if label != "O" and (is_amount_word(word) or token.text.lower() in DESCRIPTORS):
            continue  # a count, unit or angle of a move; a descriptor the node keeps
        if label == "O" or token.text.lower() in unknown_set or (word not in vocabulary
                                                                    and word not in FURNITURE_WORDS):
            out.append(token.text)
    return out


def _object_words_used(tree, plan: GroundingPlan) -> set[int]:
    """Positions of the nouns of the objects the plan uses: its object, and objects that are
    references of its nodes ("next to the tissue box")."""
    kinds = {plan.object} | {r for n in plan.nodes for r, _ in n.pairs}
    used: set[int] = set()
    position = {id(t): i for i, t in enumerate(tree.tokens())}
    for chunk, _, _ in tree.chunks():
        own = chunk.own_tokens
        nouns = {n for found, _ in object_phrases([t.text for t in own], [t.pos for t in own])
                 if found.kind in kinds for n in found.nouns}
        used.update(position[id(t)] for t in own if t.text.lower() in nouns and id(t) in position)
    return used


def _loose_used(tokens, labels) -> set[int]:
    """Positions of words outside the chunks that a loose move uses ("go forward and …")."""
    used: set[int] = set()
    run: list[int] = []
    for i, label in enumerate([*labels, None]):
        if label == "O":
            run.append(i)
            continue
        for _, positions in loose_moves([tokens[j].text for j in run]):
            used.update(run[p] for p in positions)
        run = []
    return used


def finish_flags(plan: GroundingPlan, *, words: int, world=None) -> GroundingPlan:
    """Add the flags that need the whole picture: empty, not understood, missing, ambiguous."""
    flags = list(plan.flags)
    if words == 0:
        flags.insert(0, "empty")
    elif plan.room is None and not plan.nodes and plan.object is None:
        flags.insert(0, "not_understood")
    if words and plan.object is None:
        flags.append("no_object")
    if words and plan.room is None:
        flags.append("no_room")
    if world is not None:
        for node in plan.nodes:
            if node.target == NO_TARGET or node.referenced:
                continue
            count = count_furniture(world, node.target, plan.room)
            if count > 1:
                flags.append(f"ambiguous_target:{node.target}:{count}")
    if plan.unused:
        flags.append("unused_words")
    plan.flags = list(dict.fromkeys(flags))
    return plan


def count_furniture(world, word: str, room: str | None, scene: str = "original") -> int:
    """How many furniture items of category word ``word`` the room (or the world) holds."""
    items = world.scene(scene).furniture
    return sum(1 for item in items if item.word == word and (room is None or item.room == room))

"""Surface realization (dissertation 6.2 II.E): selected nodes → chunks → chunk tree → sentence.

1. Each node becomes a chunk ``(text, type)``: the corpus chunk text of highest
   ``P(text, type | key)`` whose words are safe to say (:func:`acceptable`), slots filled
   with the object, furniture and room words. A key the corpus never says in a usable way
   backs off to a chunk of the same reference class with its direction word swapped.
2. Every ordered pair of chunks gets its most probable relation of the six (NL, NR, PL, PR,
   CL, CR) from the corpus chunk trees of the same style; Algorithm 1 grows the tree from the
   object's chunk, taking relations most probable first; siblings are ordered by the learned
   neighbour relations.
3. The sentence is the in-order traversal, then checked (:func:`repeated_phrases`): a repeated
   phrase makes the later chunk take its next text, or leaves its node out.

Guards against what went wrong in the dissertation: no chunk says a motion ("move halfway
in") in a static description (verbs are only allowed in the object's chunk), no filler,
hedge, listener-relative word (your, his) or adjective that may be false (small, round), no
doubled word, no repeated phrase; the verb agrees with the object; "a" becomes "an" before a
vowel.
"""

from __future__ import annotations

from assistant.world.catalogue import load_catalogue

import functools
import re

from assistant.generation.model import INVERSE, SLOT_OBJECT, SLOT_REF, SLOT_ROOM, SLOT_SUPPORT
from assistant.generation.types import ChunkNode, ContentNode

__all__ = ["FUNCTION_WORDS", "acceptable", "build_tree", "chunk_options", "realize",
           "repeated_phrases", "sentence_from_tree"]

#: POS tags never said by the generator (fillers, addressee, hedges, adjectives and numbers that
#: may be false, past tense, wh-clauses)
BANNED_POS = frozenset({"IGN", "WHO", "JJ", "JJR", "JJS", "CD", "VBD", "MD", "WDT", "WRB", "WP",
                        "EX", "CONF", "PERS", "NNS", "UH"})
STATIC_BANNED_POS = BANNED_POS | {"RB", "PRP", "VB", "VBG", "VBN", "VBP", "VBR", "CC"}
ROUTE_BANNED_POS = BANNED_POS | {"VBG", "VBN", "VBP", "VBR", "CC", "PRP"}
#: words that do not make a phrase "repeated" on their own
FUNCTION_WORDS = frozenset({"the", "a", "an", "of", "to", "in", "on", "at", "is", "it", "'s",
                            "and", "by", "with", "from", "are", "into"})
ROUTE_ENDINGS_BANNED = frozenset({"TO", "IN", "CC", "DT", "ON"})
MAX_TREE_PASSES = 10


def acceptable(label: str, template, key: str, style: str) -> bool:
    """Whether a corpus chunk text may be said for ``key`` in a ``style`` description."""
    words = [w for w, _ in template]
    pos = [p for _, p in template]
    if any(a == b for a, b in zip(words, words[1:])):
        return False
    if key == "object":
        return (pos[:1] == ["DT"] and words[0] == "the" and SLOT_OBJECT in words
                and pos[-1] == "VBZ" and not (set(pos) & (BANNED_POS | {"RB", "PRP", "VBG"})))
    if key == "enter" or key.startswith("move-"):
        if set(pos) & ROUTE_BANNED_POS or pos[-1] in ROUTE_ENDINGS_BANNED:
            return False
        if key == "enter":
            return words.count(SLOT_ROOM) == 1 and pos[0] == "VB" and "STR" not in pos
        return pos[0] == "VB" and "RM" not in pos and "STR" not in pos and "FUR" not in pos
    if set(pos) & STATIC_BANNED_POS:
        return False
    if key == "room":
        return words.count(SLOT_ROOM) == 1 and pos[0] in ("IN", "ON") and "DIR" not in pos
    if key == "support":
        return words.count(SLOT_SUPPORT) == 1 and pos[0] in ("IN", "ON") and "NN" not in pos[:-1]
    if "halfway" in words:  # a distance to move ("about halfway in"), not a place
        return False
    if words[0] == "with":  # "with the couch" is company, not a place
        return False
    if key.startswith("furniture-"):
        return words.count(SLOT_REF) == 1 and pos[0] in ("IN", "ON", "DIR", "TO") and \
            pos[pos.index("FUR") - 1] == "DT"
    # structure references: wall, door, room parts
    return pos[0] in ("IN", "ON", "TO") and "FUR" not in pos


def chunk_options(model, node: ContentNode | None, style: str) -> list[tuple[float, str, tuple]]:
    """Acceptable ``(P(text, type | key), type, template)`` for a node (None: the object),
    most probable first, with the direction back-off when the key has none."""
    key = "object" if node is None else node.key
    rows = [r for r in model.texts(key) if acceptable(r[1], r[2], key, style)]
    if rows or node is None or "-" not in key:
        return rows
    ref, direction = key.split("-", 1)
    backoff = []
    for other in sorted(model.templates_):
        if other == key or not other.startswith(ref + "-"):
            continue
        other_dir = other.split("-", 1)[1]
        for p, label, t in model.texts(other):
            if (other_dir, "DIR") not in t:
                continue
            swapped = tuple((direction, "DIR") if wp == (other_dir, "DIR") else wp for wp in t)
            if acceptable(label, swapped, key, style):
                backoff.append((p * 0.5, label, swapped))
    backoff.sort(key=lambda r: (-r[0], r[1], " ".join(w for w, _ in r[2])))
    return backoff


def _fill(template, node: ContentNode | None, object_name: str) -> list[str]:
    words = node.words if node is not None else {}
    out: list[str] = []
    for w, _ in template:
        if w == SLOT_OBJECT:
            out.extend(object_name.split())
        elif w == SLOT_SUPPORT:
            out.extend(words.get("support", "table").split())
        elif w == SLOT_REF:
            out.append(words.get("ref", "table"))
        elif w == SLOT_ROOM:
            out.extend(words.get("room", "room").split())
        else:
            out.append(w)
    if node is None and load_catalogue().number(object_name) == "plural":  # "the keys are"
        out = ["are" if w in ("is", "'s") else w for w in out]
    return out


# ---------------------------------------------------------------------------------- the tree
def build_tree(model, root: ChunkNode, chunks: list[ChunkNode], style: str,
               top: list[ChunkNode] | None = None, container: dict | None = None) -> list[ChunkNode]:
    """Algorithm 1: place ``chunks`` around ``root`` by their most probable relations (pool B,
    most probable first; a relation is used when exactly one of its chunks is in the tree).
    Returns the top-level list (the root and any chunk that became its neighbour). ``top`` and
    ``container`` continue a tree built by an earlier call (the route steps of a dynamic
    description are placed around the finished static part)."""
    if top is None:
        top = [root]
        container = {id(root): top}
    placed = [c for c in _all(top)]
    everyone = placed + list(chunks)
    pool = []
    for a in everyone:
        for b in everyone:
            if a is b or (a in placed and b in placed):
                continue
            v, p = model.relation(a.label, b.label, style)
            if v is not None:
                pool.append((p, a, b, v))
    pool.sort(key=lambda r: -r[0])
    waiting = list(chunks)
    passes = 0
    while waiting and passes < MAX_TREE_PASSES:
        passes += 1
        for entry in list(pool):
            p, a, b, v = entry
            a_in, b_in = id(a) in container, id(b) in container
            if a_in == b_in:
                continue
            new, old, rel = (a, b, v) if not a_in else (b, a, INVERSE[v])
            if rel in ("PL", "PR") and old is root:
                rel = "NL" if rel == "PR" else "NR"  # the object's chunk stays the root
            _place(new, old, rel, container)
            waiting.remove(new)
            pool.remove(entry)
    for c in waiting:  # no learned relation: say it after the object's words
        root.right.append(c)
        container[id(c)] = root.right
    _order_siblings(model, top, style, moved=set(id(c) for c in chunks))
    return top


def _all(top):
    out = []
    for c in top:
        out.append(c)
        out.extend(_all(c.left))
        out.extend(_all(c.right))
    return out


def _place(new: ChunkNode, old: ChunkNode, rel: str, container: dict) -> None:
    if rel in ("NL", "NR"):
        lst = container[id(old)]
        i = lst.index(old)
        lst.insert(i if rel == "NL" else i + 1, new)
        container[id(new)] = lst
    elif rel in ("CL", "CR"):
        lst = old.left if rel == "CL" else old.right
        lst.append(new)
        container[id(new)] = lst
    else:  # new is the parent of old
        lst = container[id(old)]
        lst[lst.index(old)] = new
        container[id(new)] = lst
        side = new.left if rel == "PL" else new.right
        side.append(old)
        container[id(old)] = side


def _order_siblings(model, top: list[ChunkNode], style: str, moved: set | None = None) -> None:
    """Order each sibling list by the learned neighbour relations; only lists that received a
    chunk of this call (``moved``) are reordered."""
    def compare(a: ChunkNode, b: ChunkNode) -> int:
        fa, fb = _furniture_relation(a), _furniture_relation(b)
        if fa != fb and _relation(a) and _relation(b):
            # a furniture landmark before a wall or the room's middle: "on the table in front
            # of the couch in the middle of the room" — the listener (a person, or the fetch
            # task, which resolves a node's relations in the order said) finds the couch first
            return -1 if fa else 1
        nl = model.relation_probability(a.label, b.label, "NL", style)
        nr = model.relation_probability(a.label, b.label, "NR", style)
        if nl == nr:
            return 0
        return -1 if nl > nr else 1

    def visit(lst):
        if moved is None or any(id(c) in moved for c in lst):
            lst.sort(key=functools.cmp_to_key(compare))
        for c in lst:
            visit(c.left)
            visit(c.right)

    visit(top)


def _relation(c: ChunkNode) -> bool:
    return c.node is not None and c.node.kind == "relation"


def _furniture_relation(c: ChunkNode) -> bool:
    return _relation(c) and c.node.key.startswith("furniture-")


def sentence_from_tree(top: list[ChunkNode], style: str) -> str:
    """In-order traversal; top-level chunks of a dynamic description are joined with commas."""
    parts = [" ".join(c.in_order()) for c in top]
    text = ", ".join(parts) if style == "dynamic" else " ".join(parts)
    words = text.split()
    out: list[str] = []
    for w in words:
        if out and out[-1].rstrip(",") == w:
            continue
        out.append(w)
    for i, w in enumerate(out[:-1]):
        if w.lower() == "a" and re.match(r"[aeiou]", out[i + 1]):
            out[i] = "an" if w == "a" else "An"
    text = " ".join(out).replace(" 's", "'s")
    return text[:1].upper() + text[1:] + "."


def repeated_phrases(text: str) -> list[str]:
    """Phrases of two or more words said twice, that contain a content word."""
    words = [w.strip(",.").lower() for w in text.split()]
    found = []
    for n in range(len(words) // 2, 1, -1):
        seen = set()
        for i in range(len(words) - n + 1):
            gram = tuple(words[i:i + n])
            if gram in seen and any(w not in FUNCTION_WORDS for w in gram):
                phrase = " ".join(gram)
                if not any(phrase in f for f in found):
                    found.append(phrase)
            seen.add(gram)
    return found


# ---------------------------------------------------------------------------------- whole step
def realize(model, nodes: list[ContentNode], object_name: str, style: str = "static"
            ) -> tuple[str, list[ChunkNode], list[ContentNode]]:
    """Sentence, top-level chunk list and the nodes actually said (a node with no acceptable
    text, or whose every text repeats a phrase, is left out)."""
    obj_options = chunk_options(model, None, style)
    if not obj_options:
        raise ValueError("the corpus has no usable text for the object's chunk ('the X is')")
    options = {id(n): chunk_options(model, n, style) for n in nodes}
    choice = {id(n): 0 for n in nodes}
    active = [n for n in nodes if options[id(n)]]
    for _ in range(4 * max(1, len(nodes)) + 1):
        p0, label0, t0 = obj_options[0]
        root = ChunkNode(label0, _fill(t0, None, object_name), None, p0)
        chunks = []
        for n in active:
            p, label, t = options[id(n)][choice[id(n)]]
            chunks.append(ChunkNode(label, _fill(t, n, object_name), n, p))
        # the place is told in the static style; route steps are placed around it
        place = [c for c in chunks if c.node.kind != "route"]
        steps = [c for c in chunks if c.node.kind == "route"]
        top = [root]
        container = {id(root): top}
        build_tree(model, root, place, "static", top, container)
        if steps:
            build_tree(model, root, steps, "dynamic", top, container)
        text = sentence_from_tree(top, style)
        repeats = repeated_phrases(text)
        if not repeats:
            return text, top, active
        # the least probable chunk that says the repeated phrase takes its next text or goes
        culprits = [c for c in chunks if any(r in " ".join(c.words).lower() or
                                             any(w in c.words for w in r.split() if w not in FUNCTION_WORDS)
                                             for r in repeats)]
        culprits = [c for c in culprits if c.node is not None and c.node.kind != "support"] or \
            [c for c in chunks if c.node is not None and c.node.kind != "support"]
        if not culprits:
            return text, top, active
        worst = min(culprits, key=lambda c: (c.node.probability, c.probability))
        n = worst.node
        if choice[id(n)] + 1 < len(options[id(n)]):
            choice[id(n)] += 1
        else:
            active = [m for m in active if m is not n]
    return text, top, active

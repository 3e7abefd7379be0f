"""Bracket notation for annotated descriptions, grounding rules, and the CSISL XML/CSV writers.

The generator writes every phrase in a compact notation::

    [ORMTP go/VB forward/RB and/CC [ORMRP turn/VB right/DIR]]

``word/TAG`` is one word with its POS tag, ``[LABEL`` opens a chunk and ``]`` closes it. A chunk
may carry explicit grounding after a ``|``: ``[ORMRP|room=living_room`` or
``[IRMRP|ref=room|dir=center`` (underscores stand for spaces). Chunks without explicit grounding
are grounded by :func:`ground_chunk` from their own words and the description's context (the
room the route leads into and the target object).

The writers produce the CSISL formats: ``<S>`` elements whose chunk elements nest and whose
words are elements named by their POS tag, and the chunk-grounding CSV (one row per chunk,
pre-order, ``Chunk Content`` = the chunk's own words as ``TAG word TAG word``).
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass, field
from xml.sax.saxutils import escape, quoteattr

CHUNK_LABELS = ("ORMTP", "ORMRP", "IRMTP", "IRMRP", "FURTP", "FURRP", "OBTP", "OBRP", "PERS", "CONF")

#: word tags this corpus uses (Penn Treebank plus the CSISL semantic tags)
WORD_TAGS = frozenset({
    "DT", "VB", "NN", "IN", "RB", "DIR", "PRP", "FUR", "CC", "ON", "TO", "RM", "VBZ", "JJ",
    "IGN", "VBP", "NNS", "MD", "WHO", "STR", "EX", "CD", "VBD", "VBG", "WRB", "WDT", "VBN",
    "VBR", "RP", "POS", "JJR", "RBR", "WP", "JJS",
})

GROUNDING_FIELDS = ("target room", "target object", "reference", "direction", "target")
NA = "N/A"
CSV_HEADER = ("CMD#", "Chunk Name", "Chunk Content", *GROUNDING_FIELDS)


@dataclass
class Word:
    text: str
    tag: str


@dataclass
class Node:
    """A chunk (``label`` set) or the sentence root (``label`` None)."""

    label: str | None
    items: list = field(default_factory=list)
    ground: dict = field(default_factory=dict)   # explicit grounding overrides
    grounding: dict | None = None                # final grounding, set by ground_tree

    def own_words(self) -> list[Word]:
        return [i for i in self.items if isinstance(i, Word)]

    def children(self) -> list["Node"]:
        return [i for i in self.items if isinstance(i, Node)]

    def words(self) -> list[Word]:
        out: list[Word] = []
        for i in self.items:
            out.extend(i.words() if isinstance(i, Node) else [i])
        return out

    def walk(self):
        """Pre-order over the chunks below (and including, unless root) this node."""
        if self.label is not None:
            yield self
        for c in self.children():
            yield from c.walk()

    def text(self) -> str:
        return " ".join(w.text for w in self.words())

    def bracketed(self) -> str:
        parts = []
        for i in self.items:
            parts.append(i.bracketed() if isinstance(i, Node) else f"{i.text}/{i.tag}")
        inner = " ".join(parts)
        return inner if self.label is None else f"[{self.label} {inner}]"


class NotationError(ValueError):
    pass


_KEYS = {"room": "target room", "object": "target object", "ref": "reference",
         "dir": "direction", "target": "target"}


def parse(text: str) -> Node:
    """Parse bracket notation into a root :class:`Node`; raise NotationError on bad input."""
    root = Node(None)
    stack = [root]
    for tok in text.replace("[", " [").replace("]", " ] ").split():
        if tok.startswith("["):
            head, *opts = tok[1:].split("|")
            if head not in CHUNK_LABELS:
                raise NotationError(f"unknown chunk label {head!r} in {text!r}")
            node = Node(head)
            for opt in opts:
                key, _, val = opt.partition("=")
                if key not in _KEYS:
                    raise NotationError(f"unknown grounding key {key!r} in {text!r}")
                node.ground[_KEYS[key]] = val.replace("_", " ")
            stack[-1].items.append(node)
            stack.append(node)
        elif tok == "]":
            if len(stack) == 1:
                raise NotationError(f"unbalanced ']' in {text!r}")
            stack.pop()
        else:
            word, sep, tag = tok.rpartition("/")
            if not sep or not word or tag not in WORD_TAGS:
                raise NotationError(f"bad word {tok!r} (need word/TAG with a known tag) in {text!r}")
            stack[-1].items.append(Word(word, tag))
    if len(stack) != 1:
        raise NotationError(f"unclosed chunk in {text!r}")
    return root


# ---------------------------------------------------------------- grounding rules

FURNITURE_CATEGORY = {
    "table": "table", "tables": "table", "desk": "table", "desks": "table", "nightstand": "table",
    "stand": "table", "counter": "table", "dresser": "table",
    "chair": "chair", "chairs": "chair", "couch": "couch", "sofa": "couch", "couches": "couch",
    "bed": "bed", "beds": "bed", "sofas": "couch", "nightstands": "table",
}
ROOM_WORDS = {"bedroom": "bedroom", "office": "office", "studio": "studio",
              "livingroom": "living room", "bedrooms": "bedroom"}
ROOM_PREFIX = {"living": "living room", "meeting": "meeting room", "sitting": "living room"}
#: words that name each target object (any one of them in an OBTP grounds the object)
OBJECT_WORDS = {
    "fork": {"fork", "forks"}, "glasses case": {"glasses", "case", "eyeglasses", "eyeglass"},
    "laptop": {"laptop", "computer"}, "monitor": {"monitor", "screen"}, "mug": {"mug", "cup"},
    "statue": {"statue", "figurine", "sculpture"},
}
_TURN_VERBS = {"turn", "take", "make", "hang", "veer", "bear"}
_MOTION_VERBS = {"go", "walk", "move", "head", "continue", "keep", "come", "proceed", "drive",
                 "roll", "step", "get", "follow"}


_INTENSIFIED = {"there", "here", "away", "next", "by", "in", "on", "behind", "at", "when", "as", "smack"}


def _dir_words(words: list[Word]) -> list[str]:
    """The direction words of a phrase; "right" as an intensifier ("right there", "right by") is
    not a direction (an RB-tagged "right" before a place word)."""
    out = []
    for i, w in enumerate(words):
        t = w.text.lower()
        if t not in ("left", "right"):
            continue
        nxt = words[i + 1].text.lower() if i + 1 < len(words) else ""
        if w.tag == "RB" and nxt in _INTENSIFIED:
            continue
        out.append(t)
    return out


def _room_named(words: list[Word]) -> str | None:
    found = None
    low = [w.text.lower() for w in words]
    for i, w in enumerate(low):
        if w in ROOM_WORDS:
            found = ROOM_WORDS[w]
        elif w == "room" and i > 0 and low[i - 1] in ROOM_PREFIX:
            found = ROOM_PREFIX[low[i - 1]]
    return found


def _furniture(words: list[Word]) -> str | None:
    cat = None
    for w in words:
        if w.tag == "FUR" and w.text.lower() in FURNITURE_CATEGORY:
            cat = FURNITURE_CATEGORY[w.text.lower()]
    return cat


def ground_irmrp(words: list[Word]) -> tuple[str, str]:
    """(reference, direction) of an inside-room reference phrase, from its own words."""
    low = {w.text.lower() for w in words}
    dirs = _dir_words(words)
    d = dirs[-1] if dirs else None
    first = words[0].text.lower() if words and words[0].tag != "RB" else ""
    structure = {w.text.lower() for w in words if w.tag == "STR"}
    if low & {"halfway", "middle", "center", "centre", "midway"}:
        return "room", d or "center"
    if structure & {"wall", "walls"}:
        if d:
            return "wall", d
        if low & {"back", "far", "end", "opposite", "other", "rear"}:
            return "wall", "back"
        return "wall", "beside"
    if structure & {"door", "doorway", "entrance", "doors", "entryway", "opening"}:
        if d:
            return "door", d
        if "behind" in low:
            return "door", "back"
        if low & {"across", "opposite", "facing", "front"}:
            return "door", "front"
        return "door", "beside"
    if "around" in low and "turn" in low:
        return "move", "back"
    if d and (low & _TURN_VERBS or "again" in low or first in ("left", "right", "then")):
        return "move", d
    if low & {"back", "end", "far", "corner", "rear"} and not ("back" in low and low & {"come", "step", "go"} and "the" not in low):
        return "room", d or "back"
    if d:
        if low & _MOTION_VERBS and not low & {"on", "to", "at"}:
            return "move", d
        if "room" in low and not low & {"you", "your", "his", "brian"}:
            return "room", d  # "on the right side of the room": the room's side, not the listener's
        return "robot", d
    if "behind" in low:
        return "robot", "back"
    if low & _MOTION_VERBS or low & {"forward", "straight"}:
        return "move", "front"
    if low & {"ahead", "front"}:
        return "robot", "front"
    return "move", "front"


def ground_furrp(words: list[Word]) -> tuple[str, str]:
    """(reference, direction) of a furniture reference phrase."""
    low = {w.text.lower() for w in words}
    ref = _furniture(words) or "table"
    dirs = _dir_words(words)
    if "between" in low:
        return ref, "between"
    if dirs:
        return ref, dirs[-1]
    if "behind" in low or "past" in low or "beyond" in low:
        return ref, "back"
    if low & {"front", "across", "opposite", "facing"}:
        return ref, "front"
    return ref, "beside"


#: words that alone (with fillers) tell the robot to stop
STOP_ONLY = {"stop", "halt", "there", "here", "and", "then", "now", "right", "just", "okay", "ok", "um", "uh"}
_OBJECT_TAGS = {"NN", "NNS", "FUR"}


def ground_obrp(words: list[Word]) -> tuple[str, str]:
    """(reference, direction) of an object reference phrase ("by the lamp" → lamp, beside): the
    object is the run of nouns said last; "N/A" when it names none ("next to it")."""
    nouns: list[str] = []
    run: list[str] = []
    for w in words:
        if w.tag in _OBJECT_TAGS and w.text.lower() not in FURNITURE_CATEGORY:
            run.append(w.text.lower())
        else:
            if run:
                nouns = run
            run = []
    nouns = run or nouns
    if not nouns:
        return NA, NA
    ref = " ".join(nouns)
    low = {w.text.lower() for w in words}
    dirs = _dir_words(words)
    if dirs:
        return ref, dirs[-1]
    if "behind" in low:
        return ref, "back"
    if low & {"front"}:
        return ref, "front"
    if "between" in low:
        return ref, "between"
    return ref, "beside"


def ground_chunk(node: Node, ctx: dict, has_ormrp_child: bool) -> dict:
    """The five grounding fields of one chunk (``N/A`` where none)."""
    g = {f: NA for f in GROUNDING_FIELDS}
    own = node.own_words()
    lab = node.label
    if lab == "ORMTP":
        named = _room_named(own)
        if named:
            g["target room"] = named
        elif not has_ormrp_child and (_dir_words(own) or {w.text.lower() for w in own} & {"door", "doorway"}):
            g["target room"] = ctx["room"]
    elif lab == "ORMRP":
        g["target room"] = _room_named(own) or ctx["room"]
    elif lab == "OBTP":
        # only a phrase that names the object grounds it ("it's on the table" names none)
        if {w.text.lower() for w in own} & OBJECT_WORDS.get(ctx["object"], {ctx["object"]}):
            g["target object"] = ctx["object"]
    elif lab == "IRMRP":
        low = {w.text.lower() for w in own}
        if low <= STOP_ONLY and low & {"stop", "halt"}:
            g["reference"] = "stop"
        else:
            g["reference"], g["direction"] = ground_irmrp(own)
    elif lab == "OBRP":
        g["reference"], g["direction"] = ground_obrp(own)
    elif lab == "PERS":
        dirs = _dir_words(own)
        if dirs:
            g["reference"], g["direction"] = "robot", dirs[-1]
    elif lab == "FURTP":
        g["target"] = _furniture(own) or "table"
    elif lab == "FURRP":
        g["reference"], g["direction"] = ground_furrp(own)
    g.update(node.ground)
    return g


def ground_tree(root: Node, ctx: dict) -> None:
    """Set ``grounding`` on every chunk of a description."""
    def visit(node: Node, room: str):
        room = node.ground.get("target room", room) if node.label in ("ORMTP", "ORMRP") else room
        if node.label is not None:
            has_ormrp = any(c.label == "ORMRP" for c in node.children())
            node.grounding = ground_chunk(node, {**ctx, "room": room}, has_ormrp)
        for c in node.children():
            visit(c, room)
    visit(root, ctx["room"])


# ---------------------------------------------------------------- writers

def to_xml(root: Node, attrs: dict) -> str:
    lines = ["<S" + "".join(f" {k}={quoteattr(str(v))}" for k, v in attrs.items()) + ">"]

    def emit(node: Node, depth: int):
        pad = "  " * depth
        for i in node.items:
            if isinstance(i, Node):
                lines.append(f"{pad}<{i.label}>")
                emit(i, depth + 1)
                lines.append(f"{pad}</{i.label}>")
            else:
                lines.append(f"{pad}<{i.tag}>{escape(i.text)}</{i.tag}>")
    emit(root, 1)
    lines.append("</S>")
    return "\n".join(lines)


def csv_rows(cmd: int, root: Node) -> list[list[str]]:
    rows = []
    for ch in root.walk():
        content = " ".join(f"{w.tag} {w.text}" for w in ch.own_words())
        rows.append([str(cmd), ch.label, content, *(ch.grounding[f] for f in GROUNDING_FIELDS)])
    return rows


def write_csv_text(rows: list[list[str]]) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(CSV_HEADER)
    w.writerows(rows)
    return buf.getvalue()

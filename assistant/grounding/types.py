"""Grounding types: chunk records, chunk groundings, RDT nodes and the grounding plan.

* :class:`ChunkRecord` — what a grounder sees of one chunk: its label (``FURTP``), its own
  words and POS tags (not those of nested chunks), its parent label and its child labels.
* :class:`ChunkGrounding` — the five grounding fields of one chunk (dissertation 4.4.2):
  target room, target object, reference, direction, target; ``None`` where the chunk says
  nothing about a field (``N/A`` in the CSV files).
* :class:`RDT`, :class:`RDTNode`, :class:`GroundingPlan` — the navigation instruction
  (dissertation 4.3 II.B): a target room, RDT nodes in execution order, a target object.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from assistant.rdt import NO_TARGET, RDT

#: the five grounding fields, in the column order of the chunk-grounding CSV
FIELDS = ("target room", "target object", "reference", "direction", "target")
#: field → attribute name of :class:`ChunkGrounding`
FIELD_ATTRS = {"target room": "room", "target object": "object", "reference": "reference",
               "direction": "direction", "target": "target"}
#: the grounding *types* of step 1 (dissertation 4.3 II.C) and the fields each one fills
TYPE_FIELDS = {
    "room": ("target room",),
    "object": ("target object",),
    "rdt": ("reference", "direction", "target"),
}
#: top-level chunks have this parent label
ROOT = "S"


@dataclass(frozen=True)
class ChunkRecord:
    """One chunk as a grounder sees it.

    ``words``/``pos``: the chunk's own tokens (nested chunks excluded), as written.
    ``parent``: label of the enclosing chunk, ``"S"`` at top level, None when unknown (a CSV
    row read without its tree). ``children``: labels of the directly nested chunks, in order,
    or None when unknown. ``world``: the home the command was given in (``apartment``), or
    None — which room "on the right" means depends on it.
    """

    label: str
    words: tuple[str, ...]
    pos: tuple[str, ...]
    parent: str | None = None
    children: tuple[str, ...] | None = None
    world: str | None = None

    @property
    def text(self) -> str:
        return " ".join(self.words)

    def content(self) -> str:
        """The CSV form ``TAG word TAG word …``."""
        return " ".join(f"{p} {w}" for w, p in zip(self.words, self.pos))


@dataclass(frozen=True)
class ChunkGrounding:
    """The grounding of one chunk; ``None`` for a field the chunk does not ground."""

    room: str | None = None
    object: str | None = None
    reference: str | None = None
    direction: str | None = None
    target: str | None = None

    def get(self, field_name: str) -> str | None:
        return getattr(self, FIELD_ATTRS[field_name])

    def as_tuple(self) -> tuple[str | None, ...]:
        return tuple(self.get(f) for f in FIELDS)

    @classmethod
    def from_fields(cls, values: dict[str, str | None]) -> "ChunkGrounding":
        return cls(**{FIELD_ATTRS[f]: values.get(f) for f in FIELDS})

    @property
    def kind(self) -> str:
        """The grounding type of step 1: ``room``, ``object``, ``rdt``, combinations joined by
        ``+`` (``object+rdt``), or ``none``."""
        kinds = [k for k, fields in TYPE_FIELDS.items() if any(self.get(f) for f in fields)]
        return "+".join(kinds) if kinds else "none"

    def to_dict(self) -> dict:
        return {f: self.get(f) for f in FIELDS}


@dataclass(frozen=True)
class LabelledCommand:
    """One command of a chunk-grounding file: its chunks and their gold groundings."""

    number: str
    records: tuple[ChunkRecord, ...]
    groundings: tuple[ChunkGrounding, ...]
    source: str = ""


@dataclass(frozen=True)
class RDTNode:
    """One target with one or more reference-direction pairs, tried in order (4.3 II.B).

    A node with no pair (``"the mug is on the table"``) only names its target; its string form
    is then ``room-center-<target>`` — search the target room from its centre — and
    :attr:`referenced` is False. ``support`` is the word the person used for the target
    (``nightstand``, ``desk``) when it differs from the category word. ``descriptors``: the
    size, shape and kind words said with the target, canonical (``("small", "round")`` for
    "the little round table"; :data:`~assistant.grounding.vocabulary.DESCRIPTORS`).
    ``distance_m`` / ``degrees``: how far a move goes ("two steps forward": 1.2 m, a step being
    :data:`~assistant.grounding.amounts.STEP_M`) and how far a turn turns ("turn left 90
    degrees"); None when not said. A ``stop`` node (``stop-center-non``) ends the motion where
    the robot is.
    """

    target: str
    pairs: tuple[tuple[str, str], ...] = ()
    support: str | None = None
    implied_target: bool = False
    descriptors: tuple[str, ...] = ()
    distance_m: float | None = None
    degrees: float | None = None

    @property
    def referenced(self) -> bool:
        return bool(self.pairs)

    @property
    def rdts(self) -> list[RDT]:
        if not self.pairs:
            return [RDT("room", "center", self.target)]
        return [RDT(r, d, self.target) for r, d in self.pairs]

    def __str__(self) -> str:
        return str(self.rdts[0])

    @property
    def dynamic(self) -> bool:
        return all(r.dynamic for r in self.rdts) and self.referenced

    def to_dict(self) -> dict:
        return {"rdt": str(self), "target": self.target,
                "pairs": [[r, d] for r, d in self.pairs],
                "alternatives": [str(r) for r in self.rdts],
                "support": self.support, "implied_target": self.implied_target,
                "descriptors": list(self.descriptors), "distance_m": self.distance_m,
                "degrees": self.degrees}


@dataclass
class GroundingPlan:
    """A command grounded: target room (or None), RDT nodes in execution order, target object.

    ``kind``: ``dynamic`` (only move/room/wall/door nodes), ``static`` (furniture or robot
    references/targets only), ``mixed`` (both). ``support`` is the furniture word the object is
    on (the last node's target word, as said), or None. ``unused`` lists words the plan could
    not use; ``flags`` says what is missing or ambiguous, so the dialogue can ask.
    """

    room: str | None = None
    nodes: list[RDTNode] = field(default_factory=list)
    object: str | None = None
    kind: str = "static"
    support: str | None = None
    unused: list[str] = field(default_factory=list)
    flags: list[str] = field(default_factory=list)

    @property
    def node_strings(self) -> list[str]:
        return [str(n) for n in self.nodes]

    def to_dict(self) -> dict:
        return {"room": self.room, "nodes": self.node_strings, "object": self.object,
                "support": self.support, "kind": self.kind,
                "node_details": [n.to_dict() for n in self.nodes]}

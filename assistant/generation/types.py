"""Types of the generation layer: what the search reports, what content selection picks, what
surface realization builds (dissertation 6.2 II.C–E).

* :class:`ContentNode` — one candidate piece of content (the room, the support, or an RDT node
  such as ``couch-front-table``) with its probability ``P_Γ(y)`` in the environment.
* :class:`ChunkNode` — one chunk of the generated sentence (text, chunk type) placed in the
  chunk tree built by Algorithm 1.
* :class:`GeneratedDescription` — the answer: sentence, selected nodes, chunk tree, timings.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from assistant.perception.objects import Sighting

#: how "where is my X" finds the object: the robot searches (``sensed``) or the world file
#: answers (``oracle``, to separate the language from the search)
SEARCH_MODES = ("sensed", "oracle")

#: description styles: a static description ("the mug is on the table in front of the couch")
#: or a how-to-find (dynamic) one from the listener's pose ("go into the living room, turn right…")
STYLES = ("static", "dynamic")


@dataclass
class ContentNode:
    """One candidate content item.

    ``kind``: ``room`` (the object's room), ``support`` (the furniture it lies on), ``relation``
    (an RDT node about the support: ``reference-direction-target``) or ``route`` (a how-to-find
    step: ``room-enter-non`` or ``move-<dir>-non``). ``key`` is the corpus key the co-occurrence
    weights and the chunk texts are learned for (``room``, ``support``, ``furniture-front``,
    ``wall-left``, ``move-right``…). ``words`` fill the template slots. ``probability`` is
    ``P_Γ(y)`` in [0, 1]; ``reference_id`` names the reference entity (None for the room
    and support).
    """

    kind: str
    key: str
    rdt: str | None
    probability: float
    words: dict = field(default_factory=dict)
    reference_id: str | None = None

    def to_dict(self) -> dict:
        return {"kind": self.kind, "key": self.key, "rdt": self.rdt,
                "probability": round(float(self.probability), 4), "words": dict(self.words),
                "reference": self.reference_id}


@dataclass
class ChunkNode:
    """One chunk in the tree: its words, chunk type (``OBTP``…), the content it realizes, and
    the chunks nested before (``left``) and after (``right``) its own words."""

    label: str
    words: list[str]
    node: ContentNode | None = None
    probability: float = 1.0
    left: list["ChunkNode"] = field(default_factory=list)
    right: list["ChunkNode"] = field(default_factory=list)

    @property
    def text(self) -> str:
        return " ".join(self.words)

    def in_order(self) -> list[str]:
        """Left children, own words, right children (dissertation: in-order traversal)."""
        out: list[str] = []
        for child in self.left:
            out.extend(child.in_order())
        out.extend(self.words)
        for child in self.right:
            out.extend(child.in_order())
        return out

    def bracketed(self) -> str:
        parts = [c.bracketed() for c in self.left] + list(self.words) + [c.bracketed() for c in self.right]
        return "[" + self.label + " " + " ".join(parts) + "]"

    def to_dict(self) -> dict:
        return {"label": self.label, "text": self.text,
                "rdt": self.node.rdt if self.node else None,
                "left": [c.to_dict() for c in self.left],
                "right": [c.to_dict() for c in self.right]}


@dataclass
class GeneratedDescription:
    """The answer to "where is my X?"."""

    found: bool
    description: str
    object: str
    style: str = "static"
    sighting: Sighting | None = None
    selected: list[ContentNode] = field(default_factory=list)
    candidates: list[ContentNode] = field(default_factory=list)
    tree: ChunkNode | None = None
    objective: float | None = None
    ambiguous: bool = False
    search: str = "oracle"
    environment: str = "oracle"
    search_seconds: float = 0.0
    composition_seconds: float = 0.0
    searched_rooms: list[str] = field(default_factory=list)
    #: the search's own report (:meth:`SearchResult.to_dict` without the furniture list) when
    #: the answer comes from a sensed search; None for the oracle search
    search_report: dict | None = None

    @property
    def nodes(self) -> list[str]:
        """The selected RDT nodes as strings, like ``assistant parse`` gives them: one per stated
        relation of the support (``couch-front-table``); ``room-center-<support>`` when only the
        support is said. The room and the route steps are not RDT nodes."""
        relations = [n.rdt for n in self.selected if n.kind == "relation" and n.rdt]
        if relations:
            return relations
        return [n.rdt for n in self.selected if n.kind == "support" and n.rdt]

    def to_dict(self) -> dict:
        s = self.sighting
        room = next((n.words.get("room") for n in self.selected if n.kind == "room"), None)
        return {
            "object": self.object,
            "found": self.found,
            "description": self.description,
            "style": self.style,
            "nodes": self.nodes,
            "room": room if room else (s.room if s else None),
            "seen_at": ({"x": s.x_m, "y": s.y_m, "z": s.z_m, "room": s.room,
                         "seen_from": None if s.seen_from is None else
                         [s.seen_from.x, s.seen_from.y, s.seen_from.theta],
                         "time_s": s.timestamp_s} if s else None),
            "selected": [n.to_dict() for n in self.selected],
            "candidates": [n.to_dict() for n in self.candidates],
            "objective": self.objective,
            "ambiguous": self.ambiguous,
            "tree": self.tree.to_dict() if self.tree else None,
            "bracketed": self.tree.bracketed() if self.tree else None,
            "search": self.search,
            "environment": self.environment,
            "searched_rooms": list(self.searched_rooms),
            "search_seconds": self.search_seconds,
            "composition_seconds": self.composition_seconds,
            "search_report": self.search_report,
        }

"""Content selection (dissertation 6.2 II.D): which RDT nodes describe where the object is.

1. **Candidates** (:func:`candidate_nodes`): from the environment model — the object's room,
   the furniture it lies on (the *support*), and RDT nodes about the support: a furniture
   reference with a front (``couch-front-table``, DIR-SRV of the support w.r.t. the reference),
   any furniture close by (``bed-beside-table``, DIST-SRV), the room's walls seen from its door
   (``wall-left-table``), its middle (``room-center-table``) and its doors
   (``door-beside-table``). Each has ``P_Γ(y)`` from the spatial layer (SRV weights), and a
   test of whether the same relation would hold for another piece of furniture.
   Only relations that hold are candidates (the stated direction is the strongest DIR-SRV word
   and the distance is near), so every selection is true.
2. **Objective** (:func:`select_content`): equation (2),
   ``O(W) = Σ w_k P_k / Σ w_k + Σ_{k1<k2} v_{k1k2} w_k1 w_k2 P_k1 P_k2 − α Σ w_k / K``,
   α = 0.1, with ``v`` the corpus co-occurrence weights, maximised **exactly** over every subset
   (vectorised over all 2^K subsets; K ≤ 14 candidates). Constraints: the support is always
   said; at most one node per reference word (one thing about "the chair" even when there are two
   chairs; one wall; the middle of the room); at most two relations; the selection
   must single the support out among the furniture with the same word (the room or a relation
   must be false for every other table) — when no subset does, the subsets that rule out the
   most look-alikes are kept and the best of them is flagged ``ambiguous``. Before maximising,
   each relation's ``P`` is shared among the look-alikes it also fits (``P / (1 + n)``: the
   chance it leads a listener to this support).
3. **Listener filter**: when the listener stands in the object's room the room is not said.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from assistant.generation.entry import entry_heading
from assistant.generation.types import ContentNode
from assistant.geometry import box_polygon
from assistant.spatial.resolve import closeness, strongest_direction
from assistant.spatial.srv import dir_srv, dist_srv
from assistant.world import Entity, EntityKind
from assistant.world import load_catalogue

__all__ = ["ALPHA", "LISTENER_SHARE", "SIZE_WORDS", "UNIQUENESS", "Candidate", "candidate_nodes", "objective_values",
           "select_content", "support_of", "wall_band"]

ALPHA = 0.1
#: a directional relation holds when its DIR-SRV weight is the strongest of the four outer
#: words and at least this large …
MIN_DIRECTION = 0.4
#: … and the DIST-SRV near + superposition (+ half of middle) is at least this
MIN_NEAR = 0.5
MAX_CANDIDATES = 14
#: at most this many relations about the support: people seldom say more (of the 346 static
#: descriptions of corpus/, 2 state three relations, none more), and a third one makes the
#: sentence long and, in our tests, hard for the parser to read back
MAX_RELATIONS = 2
#: "against the wall": the support's footprint within this gap of the wall (metres)
MAX_WALL_GAP_M = 0.5
#: … and a look-alike within this gap is not told apart by "against the wall"
LOOSE_WALL_GAP_M = 0.75
#: "at the back (of the room)": the support's centre beyond this share of the room's depth
BACK_DEPTH = 2 / 3
OUTER = ("front", "left", "back", "right")
#: a look-alike is not ruled out by a furniture relation when it fits at least this share of
#: the support's fit (the listener takes the best-fitting one; close seconds stay confusable)
LISTENER_SHARE = 0.75
#: support words that tell a table's size, understood by the grounder (``end table`` →
#: nightstand → a small table); offered only when a table of the other size is in the room
SIZE_WORDS = load_catalogue().words.support_names
SIZE_PROBABILITY = 0.6
#: weight of the uniqueness term: the share of look-alikes the selection rules out
UNIQUENESS = 0.5
WALL_SIDES = {"left": math.pi / 2, "right": -math.pi / 2, "back": 0.0}


@dataclass
class Candidate:
    """A content node with its truth test for other furniture and its group (one per group)."""

    node: ContentNode
    holds_for: Callable[[object], bool]
    group: str
    forced: bool = False


def _near_or_middle(dist) -> float:
    d = dist.as_dict()
    return d["superposition"] + d["near"] + 0.5 * d["middle"]


def support_of(sighting, furniture: list) -> object | None:
    """The furniture entity the object lies on: the one whose footprint is nearest to the
    object's position (within 0.5 m), preferring its room."""
    best, best_d = None, 0.5
    p = np.array([sighting.x_m, sighting.y_m])
    for ent in furniture:
        if not len(ent.cells):
            continue
        d = float(np.min(np.linalg.norm(ent.points_m() - p, axis=1)))
        if sighting.room and ent.room and ent.room != sighting.room:
            d += 0.25
        if d < best_d:
            best, best_d = ent, d
    return best


def room_depth(room, heading: float, point) -> float:
    """How far into ``room`` a point is for someone walking in with ``heading``: 0 at the side
    they enter by, 1 at the far side (the room's bounding box, along the heading's axis)."""
    poly = room.polygon_array
    axis_angle = round(heading / (math.pi / 2)) * (math.pi / 2)
    direction = np.array([math.cos(axis_angle), math.sin(axis_angle)])
    proj = poly @ direction
    lo, hi = float(proj.min()), float(proj.max())
    return float((np.asarray(point) @ direction - lo) / (hi - lo)) if hi > lo else 0.5


def wall_side(room, side_angle: float) -> tuple[str, int, float]:
    """The side of ``room``'s bounding box whose outward normal is nearest ``side_angle``:
    ``(compass letter, axis (0 = x, 1 = y), coordinate of the side in metres)``."""
    poly = room.polygon_array
    xmin, ymin = poly.min(axis=0)
    xmax, ymax = poly.max(axis=0)
    normals = {0.0: ("E", 0, xmax), math.pi / 2: ("N", 1, ymax), math.pi: ("W", 0, xmin),
               -math.pi / 2: ("S", 1, ymin)}
    best = min(normals, key=lambda a: abs(math.atan2(math.sin(side_angle - a), math.cos(side_angle - a))))
    return normals[best]


def wall_band(room, side_angle: float, grid, thickness_m: float = 0.2):
    """The strip along the side of ``room`` (bounding box) whose outward normal is nearest
    ``side_angle``, as an entity on ``grid``."""
    poly = room.polygon_array
    xmin, ymin = poly.min(axis=0)
    xmax, ymax = poly.max(axis=0)
    letter, _, _ = wall_side(room, side_angle)
    t = thickness_m
    box = {"E": (xmax - t, ymin, xmax, ymax), "W": (xmin, ymin, xmin + t, ymax),
           "N": (xmin, ymax - t, xmax, ymax), "S": (xmin, ymin, xmax, ymin + t)}[letter]
    return Entity.from_polygon(f"wall:{room.name}:{letter}", "wall", EntityKind.LONG_TERM,
                               box_polygon(*box), grid, room=room.name)


class _Relations:
    """The spatial layer's readings of furniture pairs for one description, each pair's SRVs
    computed once (:mod:`assistant.spatial.resolve`)."""

    def __init__(self):
        self._memo: dict = {}

    def _once(self, key, compute):
        if key not in self._memo:
            self._memo[key] = compute()
        return self._memo[key]

    def dir_srv(self, ref, x):
        return self._once(("dir", ref.id, x.id), lambda: dir_srv(ref, x))

    def dist_srv(self, ref, x):
        return self._once(("dist", ref.id, x.id), lambda: dist_srv(ref, x))

    def directional(self, ref, x, strict: bool = True):
        """(strongest outer direction, P) of ``x`` around ``ref`` when it holds, else None.
        ``strict`` (for the support: say only what is clearly true) needs the DIST-SRV near
        + superposition + half of middle ≥ MIN_NEAR; otherwise (for a look-alike: rule out only
        what is clearly false) it is enough that ``far`` is not the strongest distance word."""
        if x is ref or ref.orientation_rad is None:
            return None
        word, weight = self._once(("strongest", ref.id, x.id), lambda: strongest_direction(ref, x))
        dist = self.dist_srv(ref, x)
        prox = _near_or_middle(dist)
        close = prox >= MIN_NEAR if strict else dist.strongest()[0] != "far"
        return (word, weight * prox) if weight >= MIN_DIRECTION and close else None

    def beside(self, ref, x) -> float:
        return 0.0 if x is ref else closeness(self.dist_srv(ref, x))


def candidate_nodes(sighting, support, furniture: list, floorplan, listener_pose=None,
                    include_room: bool = True, policy_score=None) -> list[Candidate]:
    """Every true candidate content node for the object (see the module docstring).
    ``policy_score``: a :class:`~assistant.generation.policy_score.PolicyRelationScore`; a
    furniture relation's probability is then the geometric mean of the spatial relations'
    (direction weight × nearness) and the learned policy model's score of the pair (kept alone
    when no model covers the RDT)."""
    room_name = support.room or sighting.room
    room = floorplan.room(room_name)
    word = support.name
    out: list[Candidate] = [Candidate(ContentNode("support", "support", f"room-center-{word}", 1.0,
                                                  {"support": word}, support.id),
                                      lambda x: True, "support", forced=True)]
    listener_inside = listener_pose is not None and room.contains(listener_pose.x, listener_pose.y)
    if include_room and not listener_inside:
        # said whenever the listener is elsewhere (6.2 II.D: only a listener in the room makes
        # it unnecessary): a robot, or a person, told only "on the table to the right of the
        # bed" does not know which room to go to
        out.append(Candidate(ContentNode("room", "room", None, 1.0, {"room": room_name}),
                             lambda x, r=room_name: x.room == r, "room", forced=True))
    relations = _Relations()
    out += _furniture_candidates(support, furniture, room_name, relations, policy_score)
    out += _size_candidates(support, furniture, room_name)
    out += _wall_candidates(support, room, floorplan, listener_pose, relations)
    out += _centre_candidates(support, room)
    out += _door_candidates(support, room_name, floorplan, relations)
    return out


def _furniture_candidates(support, furniture, room_name: str, relations: _Relations,
                          policy_score) -> list[Candidate]:
    """Relations to the furniture of the support's room, per reference word: "the chair" may
    be any chair of the room, so a relation rules a distractor out only when it holds for none
    of them."""
    word = support.name
    by_word: dict[str, list] = {}
    for ref in furniture:
        if ref is not support and ref.room == room_name and len(ref.cells):
            by_word.setdefault(ref.name, []).append(ref)
    out = []
    for ref_word, refs in sorted(by_word.items()):
        best: dict[str, tuple[float, str]] = {}  # direction → (P, reference id)
        for ref in refs:
            got = relations.directional(ref, support)
            if got is not None and got[1] > best.get(got[0], (0.0, ""))[0]:
                best[got[0]] = (got[1], ref.id)
            p = relations.beside(ref, support)
            if p >= MIN_NEAR and p > best.get("beside", (0.0, ""))[0]:
                best["beside"] = (p, ref.id)
        for direction, (p, ref_id) in sorted(best.items()):
            if policy_score is not None:
                ref = next(r for r in refs if r.id == ref_id)
                srvs = {"dir:ref->tar": relations.dir_srv(ref, support),
                        "dist:ref->tar": relations.dist_srv(ref, support),
                        "dist:tar->ref": relations.dist_srv(support, ref)}
                q = policy_score.score(f"{ref_word}-{direction}-{word}", srvs)
                if q is not None:
                    p = math.sqrt(p * q)
            out.append(Candidate(
                ContentNode("relation", f"furniture-{direction}", f"{ref_word}-{direction}-{word}", p,
                            {"ref": ref_word, "direction": direction}, ref_id),
                _look_alike_test(direction, refs, room_name, relations, LISTENER_SHARE * p),
                "ref:" + ref_word))
    return out


def _look_alike_test(direction: str, refs: list, room_name: str, relations: _Relations, bar: float):
    """Whether a furniture relation leaves a look-alike ``x`` confusable with the support.

    The references are in the support's room: furniture elsewhere is not near them. A
    look-alike stays a candidate for the listener only when the relation holds for it loosely
    AND fits it nearly as well as the support (``bar``: a listener, like the fetch task, takes
    the table that fits "in front of the couch" best); "by the bed" says nothing of the side,
    so any look-alike near one is confusable."""
    if direction == "beside":
        return lambda x: x.room == room_name and any(relations.beside(r, x) >= MIN_NEAR for r in refs)

    def test(x):
        if x.room != room_name:
            return False
        for r in refs:
            got = relations.directional(r, x, False)
            if got is not None and got[0] == direction and got[1] >= bar:
                return True
        return False
    return test


def _size_candidates(support, furniture, room_name: str) -> list[Candidate]:
    """"the end table": the support's size tells it from tables of the other size."""
    size_word = SIZE_WORDS.get(getattr(support, "category", None) or "")
    if size_word is None or not any(
            x is not support and x.name == support.name and x.room == room_name
            and getattr(x, "category", None) and x.category != support.category for x in furniture):
        return []
    return [Candidate(ContentNode("size", "size", None, SIZE_PROBABILITY, {"support": size_word}),
                      lambda x, c=support.category: getattr(x, "category", None) == c, "size")]


def _wall_candidates(support, room, floorplan, listener_pose, relations: _Relations) -> list[Candidate]:
    """"against the left wall", the walls named as one walks into the room."""
    heading = entry_heading(floorplan, room.name, listener_pose)
    if heading is None:
        return []
    out = []
    for side, offset in WALL_SIDES.items():
        band = wall_band(room, heading + offset, support.grid)
        _, axis, coord = wall_side(room, heading + offset)

        def against(x, strict=True, band=band, axis=axis, coord=coord):
            """Strict for the support; for a look-alike, anything a listener might still
            call "against the wall" counts."""
            if x.room != band.room:
                return False
            gap = float(np.abs(x.points_m()[:, axis] - coord).min())
            if not strict:
                return gap <= LOOSE_WALL_GAP_M
            return gap <= MAX_WALL_GAP_M and closeness(relations.dist_srv(band, x)) >= MIN_NEAR

        if against(support):
            out.append(Candidate(
                ContentNode("relation", f"wall-{side}", f"wall-{side}-{support.name}",
                            closeness(relations.dist_srv(band, support)), {"direction": side}, band.id),
                lambda x, f=against: f(x, strict=False), "wall"))
    return out


def _centre_candidates(support, room) -> list[Candidate]:
    """"in the middle of the room"."""
    poly = room.polygon_array
    size = float(min(poly.max(axis=0) - poly.min(axis=0)))
    centre = (poly.max(axis=0) + poly.min(axis=0)) / 2

    def central(x):
        return math.exp(-(float(np.linalg.norm(x.centroid_m - centre)) / (0.2 * size)) ** 2)

    p = central(support)
    if p < MIN_NEAR:
        return []
    return [Candidate(ContentNode("relation", "room-center", f"room-center-{support.name}", p,
                                  {"direction": "center"}),
                      lambda x: x.room == room.name and central(x) >= MIN_NEAR, "wall")]


def _door_candidates(support, room_name: str, floorplan, relations: _Relations) -> list[Candidate]:
    """"by the door"."""
    out = []
    for door in floorplan.doors_of(room_name):
        cx, cy = door.centre
        half = door.width_m / 2
        ent = Entity.from_polygon(f"door:{door.name}", "door", EntityKind.LONG_TERM,
                                  box_polygon(cx - half, cy - half, cx + half, cy + half), support.grid)
        p = closeness(relations.dist_srv(ent, support))
        if p >= MIN_NEAR:
            out.append(Candidate(ContentNode("relation", "door-beside", f"door-beside-{support.name}", p,
                                             {"direction": "beside"}, ent.id),
                                 lambda x, ent=ent: (x.room == room_name
                                                     and closeness(relations.dist_srv(ent, x)) >= MIN_NEAR),
                                 "door"))
    return out


def objective_values(masks: np.ndarray, p: np.ndarray, v: np.ndarray, alpha: float = ALPHA) -> np.ndarray:
    """Equation (2) for every row of ``masks`` (S, K) of 0/1: mean probability of the selected
    nodes, plus the co-occurrence term over unordered pairs, minus α·|W|/K."""
    masks = masks.astype(float)
    k = p.shape[0]
    count = masks.sum(axis=1)
    mean = np.divide(masks @ p, count, out=np.zeros_like(count), where=count > 0)
    mp = masks * p
    v0 = v.copy()
    np.fill_diagonal(v0, 0.0)
    pairs = 0.5 * np.einsum("si,ij,sj->s", mp, v0, mp)
    return mean + pairs - alpha * count / k


def select_content(candidates: list[Candidate], model, distractors: list, alpha: float = ALPHA
                   ) -> tuple[list[ContentNode], float, bool]:
    """Maximise O(W) exactly over the subsets of ``candidates`` (see the module docstring).

    ``distractors``: furniture the support could be confused with (same word). Returns the
    selected nodes (candidate order), the objective value and whether the selection still
    leaves the support ambiguous."""
    cands = sorted(candidates, key=lambda c: (not c.forced, -c.node.probability))[:MAX_CANDIDATES]
    k = len(cands)
    # P_Γ(y): the chance that the node leads a listener to this support rather than to
    # another piece of furniture with the same word — its truth weight shared among the
    # furniture it holds for
    holds = np.array([[c.holds_for(x) for x in distractors] for c in cands], dtype=bool) \
        if distractors else np.zeros((k, 0), dtype=bool)
    for c, row in zip(cands, holds):
        if not c.forced:
            c.node.probability = c.node.probability / (1.0 + float(row.sum()))
    p = np.array([c.node.probability for c in cands])
    v = np.array([[model.cooccurrence(a.node.key, b.node.key) for b in cands] for a in cands])
    free = [i for i, c in enumerate(cands) if not c.forced]
    n = len(free)
    bits = ((np.arange(2 ** n)[:, None] >> np.arange(n)[None, :]) & 1).astype(bool)
    masks = np.zeros((2 ** n, k), dtype=bool)
    for i, c in enumerate(cands):
        if c.forced:
            masks[:, i] = True
    masks[:, free] = bits
    # one node per group
    ok = np.ones(len(masks), dtype=bool)
    groups: dict[str, list[int]] = {}
    for i, c in enumerate(cands):
        groups.setdefault(c.group, []).append(i)
    for idx in groups.values():
        if len(idx) > 1:
            ok &= masks[:, idx].sum(axis=1) <= 1
    # singling out: every distractor is ruled out by at least one selected node
    if distractors:
        rules_out = (~holds).astype(float)
        unique = ((masks.astype(float) @ rules_out) >= 1).all(axis=1)
    else:
        unique = np.ones(len(masks), dtype=bool)
    relation_rows = [i for i, c in enumerate(cands) if c.node.kind == "relation"]
    if relation_rows:
        ok &= masks[:, relation_rows].sum(axis=1) <= MAX_RELATIONS
    values = objective_values(masks, p, v, alpha)
    if distractors:
        # the uniqueness term: the share of look-alikes the selection rules out
        values = values + UNIQUENESS * ((masks.astype(float) @ rules_out) >= 1).mean(axis=1)
    feasible = ok & unique
    ambiguous = not feasible.any()
    if ambiguous and distractors:
        # nothing singles it out: rule out as many look-alikes as possible, then maximise O(W)
        covered = (masks.astype(float) @ rules_out >= 1).sum(axis=1)
        feasible = ok & (covered == covered[ok].max())
    pool = np.where(feasible if feasible.any() else ok)[0]
    best = pool[np.argmax(values[pool])]
    chosen = [cands[i].node for i in range(k) if masks[best, i]]
    return chosen, float(values[best]), ambiguous

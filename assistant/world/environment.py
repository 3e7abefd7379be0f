"""The environment model: the robot's one picture of the home (dissertation 3.5, 5.4.1).

Long-term entities (rooms, walls, doors) come from the world file's floor plan — the robot is
told the layout. Short-term entities (furniture) come from perception: every frame's detections
are fused into *tracks*, matched by footprint overlap on the world grid. A track keeps, per
grid cell, how often it was seen there; a category vote weighted by confidence; a
confidence-weighted circular mean of its orientation. A view cut by the image border shows
part of an item — the end of a couch looks like a chair — so a category whose largest model is
far smaller than the floor the track covers loses the vote to one that can cover it (the couch
whose two ends, each seen alone, were read as chairs), and facing and centre come from the
views that named the track's category. A track the robot looks straight at
(its cells in view) without seeing it loses support and is dropped once it has been missed more
often than seen: furniture moved without telling the robot disappears from the model. A track's
position (attributes ``x``, ``y``) is the weighted median of the detector's centre
estimates, which are better than the centroid of the cells seen from one side. A track whose
category no view named with confidence (each such detection ``unsure``) carries the attribute
``unsure``: a task looks at it again from another pose before acting on it; one sure view
of that category clears it.
"""

from __future__ import annotations

import dataclasses
import math
from collections import defaultdict
from dataclasses import dataclass, field

import numpy as np

from assistant.geometry import GridMap, Pose2D, rectangle_fill
from assistant.world.entities import floorplan_entities, world_grid
from assistant.world.entity import Entity, EntityKind
from assistant.world.model import World

#: categories with a front: two of them facing different ways are two items
FRONT_CATEGORIES = frozenset({"chair", "couch", "bed"})


def _largest_footprint_m2(category: str) -> float:
    """The largest floor area (m²) of the catalogue's models of ``category``."""
    from assistant.world.catalogue import load_catalogue

    return max(load_catalogue().footprints_m2(category), default=0.0)


@dataclass(frozen=True)
class _Seen:
    """One detection a track absorbed: its cells, weight and what it said. ``partial``: the
    view ran out of the image, so it showed part of the item; ``merged``: a view of this item
    and another, kept when a track was split — its cells count, its words do not; ``unsure``:
    the detector was unsure of its category (the detection's ``unsure`` attribute)."""

    cells: frozenset
    weight: float
    category: str
    orientation: float | None
    subclass: str | None
    xy: tuple[float, float] | None
    partial: bool = False
    merged: bool = False
    unsure: bool = False


@dataclass(frozen=True)
class _Reading:
    """What a track's views say of its item: category, subclass, facing (radians or None),
    centre (metres, world frame, or None) and whether every view that named the category was
    unsure of it (``unsure``: look again before acting on it)."""

    category: str
    subclass: str | None
    orientation: float | None
    centre: tuple[float, float] | None
    unsure: bool = False


@dataclass
class _Track:
    id: str
    hits: dict = field(default_factory=lambda: defaultdict(float))  # (iy, ix) → weight
    seen: int = 0
    missed: int = 0
    confidence: float = 0.0
    history: list = field(default_factory=list)  # _Seen of every detection absorbed
    reading: _Reading | None = None  # what ``EnvironmentModel.read`` made of it; None: stale

    def cells(self, share: float) -> np.ndarray:
        """Cells seen in at least ``share`` of the best cell's weight."""
        if not self.hits:
            return np.zeros((0, 2), dtype=int)
        top = max(self.hits.values())
        return np.array(sorted(c for c, w in self.hits.items() if w >= share * top), dtype=int)


def _weighted_median(values: np.ndarray, weights: np.ndarray) -> float:
    """The value at half the total weight (the mean of the two values around it when half
    falls exactly between them): one glimpse with a centre far off does not move it."""
    order = np.argsort(values)
    v, cum = values[order], np.cumsum(weights[order])
    half = cum[-1] / 2.0
    i = int(np.searchsorted(cum, half))
    if i + 1 < len(v) and math.isclose(cum[i], half):
        return float((v[i] + v[i + 1]) / 2.0)
    return float(v[i])


def _cut(det: Entity) -> bool:
    """Whether a detection's view ran out of the image (the detector's ``partial``)."""
    return bool(det.attributes.get("partial", False))


def _attributes(track: _Track, reading: _Reading) -> dict:
    out = {"seen": track.seen, "subclass": reading.subclass, "unsure": reading.unsure}
    if reading.centre is not None:
        out["x"], out["y"] = reading.centre
    return out


class EnvironmentModel:
    """Entities of one home, kept up to date from perception.

    ``update(entities, robot_pose)`` fuses one frame's short-term entities (e.g. from
    :meth:`FurnitureDetector.detect`): each is matched to the track whose footprint it overlaps
    most (intersection over the smaller footprint ≥ ``match_overlap``, or centres nearer than
    ``match_distance_m``), else starts a new track; a view cut by the image border is matched
    against the track's *extent*, all cells seen at least ``extent_share`` of its best cell
    (it shows an item's end, the part seen least), a whole view against its footprint
    (``cell_share``). A detection of an item with a front that covers only part of its track
    and faces ``split_turn_rad`` or more away from it splits the track in two (two couches in
    an L that an early view saw as one sample). A track's category is the vote's winner among
    the categories whose largest catalogue model covers at least 1/``size_margin`` of the
    track's extent (the winner of all votes when none does). ``entities()`` gives the
    long-term entities followed by the furniture, named by category word (``table``, ``chair``…), with ids in
    order of first detection.
    """

    def __init__(self, world: World, resolution_m: float = 0.1, match_overlap: float = 0.25,
                 match_distance_m: float = 0.45, cell_share: float = 0.3,
                 view_range_m: float = 4.0, view_half_fov_rad: float = math.radians(26.0),
                 split_turn_rad: float = math.radians(60.0), split_min_area_m2: float = 0.3,
                 split_min_track_share: float = 1.6, split_max_fill: float = 0.7,
                 size_margin: float = 2.5, extent_share: float = 0.1):
        self.world = world
        self.grid: GridMap = world_grid(world, resolution_m)
        self.long_term: list[Entity] = floorplan_entities(world, self.grid)
        self.match_overlap = match_overlap
        self.match_distance_m = match_distance_m
        self.cell_share = cell_share
        self.view_range_m = view_range_m
        self.view_half_fov_rad = view_half_fov_rad
        self.split_turn_rad = split_turn_rad
        self.split_min_area_m2 = split_min_area_m2
        self.split_min_track_share = split_min_track_share
        self.split_max_fill = split_max_fill
        self.size_margin = size_margin
        self.extent_share = extent_share
        self._tracks: list[_Track] = []
        self._next = 0
        self.frames = 0

    # ------------------------------------------------------------------ updating
    def update(self, detections: list[Entity], robot_pose: Pose2D | None = None) -> list[Entity]:
        """Fuse one frame's detections; with ``robot_pose``, tracks in view but not detected
        lose support. Returns the current furniture entities."""
        self.frames += 1
        matched: set[str] = set()
        for det in detections:
            cells = self._cells_of(det)
            if len(cells) == 0:
                continue
            track = self._match(cells, self.extent_share if _cut(det) else self.cell_share)
            if track is not None and self._is_another_item(track, det, cells):
                track = self._split_off(track, cells)
            if track is None:
                track = self._new_track()
            self._absorb(track, det, cells)
            matched.add(track.id)
        if robot_pose is not None:
            for track in list(self._tracks):
                if track.id in matched:
                    continue
                if self._in_view(track, robot_pose):
                    track.missed += 1
                    if track.missed > track.seen:
                        self._tracks.remove(track)
        return self.furniture()

    def _cells_of(self, det: Entity) -> np.ndarray:
        """The detection's cells on this model's grid (re-gridded if it came on another)."""
        if det.grid == self.grid:
            cells = det.cells
        else:
            cells = self.grid.world_to_cell(det.points_m())
        cells = np.asarray(cells, dtype=int).reshape(-1, 2)
        cells = cells[self.grid.contains_cells(cells)]
        return np.unique(cells, axis=0) if len(cells) else cells

    def _match(self, cells: np.ndarray, share: float) -> _Track | None:
        """The track whose cells (seen at least ``share`` of its best cell's weight) the
        detection's ``cells`` overlap most, or None."""
        best, best_score = None, 0.0
        keys = {tuple(c) for c in cells}
        centre = self.grid.cell_to_world(cells).mean(axis=0)
        for track in self._tracks:
            tc = track.cells(share)
            if len(tc) == 0:
                continue
            inter = len(keys & {tuple(c) for c in tc})
            score = inter / min(len(keys), len(tc))
            dist = float(np.linalg.norm(self.grid.cell_to_world(tc).mean(axis=0) - centre))
            if score < self.match_overlap and dist < self.match_distance_m:
                score = self.match_overlap  # small items seen from two sides barely overlap
            if score >= self.match_overlap and score > best_score:
                best, best_score = track, score
        return best

    def _absorb(self, track: _Track, det: Entity, cells: np.ndarray) -> None:
        xy = None
        if "x" in det.attributes and "y" in det.attributes:  # the detector's centre estimate
            xy = (float(det.attributes["x"]), float(det.attributes["y"]))
        seen = _Seen(frozenset((int(c[0]), int(c[1])) for c in cells), max(float(det.confidence), 0.05),
                     det.category or det.name, det.orientation_rad, det.attributes.get("subclass"), xy,
                     partial=_cut(det), unsure=bool(det.attributes.get("unsure", False)))
        self._add(track, seen)
        track.missed = max(0, track.missed - 1)

    @staticmethod
    def _add(track: _Track, seen: _Seen) -> None:
        w = seen.weight
        for c in seen.cells:
            track.hits[c] += w
        if not seen.merged:
            track.seen += 1
            track.confidence = 1.0 - (1.0 - track.confidence) * (1.0 - min(w, 0.95))
        track.history.append(seen)
        track.reading = None

    def _is_another_item(self, track: _Track, det: Entity, cells: np.ndarray) -> bool:
        """Whether a detection that overlaps ``track`` is a second item the track has merged
        with a first (two couches in an L seen as one from an early view): a piece of furniture
        with a front covering only part of the track, facing at least
        :attr:`split_turn_rad` away from it, with enough of the track left beside it, on a track
        larger than :attr:`split_min_track_share` times the catalogue's largest item of that
        category (one couch whose front a view got wrong is not split) and filling less than
        :attr:`split_max_fill` of its best rectangle (an L, not a bed seen in parts). A view cut by
        the image border naming a category too small for the track's extent is part of the
        track's item (a couch's end looks like a chair), not a second item."""
        reading = self.read(track)
        if det.orientation_rad is None or reading.orientation is None:
            return False
        if (det.category or det.name) not in FRONT_CATEGORIES:
            return False
        if _cut(det) and not self._fits(det.category or det.name, self._extent_m2(track)):
            return False
        turn = abs(math.remainder(det.orientation_rad - reading.orientation, 2 * math.pi))
        if turn < self.split_turn_rad:
            return False
        mine = track.cells(self.cell_share)
        cell_area = self.grid.resolution_m ** 2
        if len(mine) * cell_area < self.split_min_track_share * _largest_footprint_m2(det.category or det.name):
            return False  # no bigger than one such item: a detection that got its front wrong
        if rectangle_fill(mine)[0] >= self.split_max_fill:
            return False  # one rectangle (a bed seen in parts), not two items at an angle
        keys = {tuple(c) for c in cells}
        rest = [c for c in map(tuple, mine) if c not in keys]
        return (len(mine) - len(rest) < 0.6 * len(mine)
                and len(rest) * cell_area >= self.split_min_area_m2)

    def _extent_m2(self, track: _Track) -> float:
        """Area (m²) of the track's extent: the cells seen at least :attr:`extent_share` of its
        best cell's weight."""
        return len(track.cells(self.extent_share)) * self.grid.resolution_m ** 2

    def _fits(self, category: str, extent_m2: float) -> bool:
        """Whether an item of ``category`` can be as large as a track's extent (m²): its largest
        catalogue footprint × :attr:`size_margin` is at least that."""
        return extent_m2 <= self.size_margin * _largest_footprint_m2(category)

    def read(self, track: _Track) -> _Reading:
        """What the track's views say. The category: the weighted vote of its views (of the
        views of both items after a split, while it has no other), won by the categories that
        can be as large as the track's extent (:meth:`_fits`) — else by all. Facing (circular
        mean), centre (weighted median of the detector's centre estimates, per axis) and
        subclass: from the views that named that category, by weight. Kept on the track until
        it absorbs another view (every frame reads every track)."""
        if track.reading is None:
            track.reading = self._reading(track)
        return track.reading

    def _reading(self, track: _Track) -> _Reading:
        spoke = [s for s in track.history if not s.merged]
        views = spoke or track.history
        votes: dict = defaultdict(float)
        for seen in views:
            votes[seen.category] += seen.weight
        extent_m2 = self._extent_m2(track)
        fits = {c: w for c, w in votes.items() if self._fits(c, extent_m2)}
        category = max((fits or votes).items(), key=lambda kv: kv[1])[0]
        named = [s for s in spoke if s.category == category]
        sin = sum(s.weight * math.sin(s.orientation) for s in named if s.orientation is not None)
        cos = sum(s.weight * math.cos(s.orientation) for s in named if s.orientation is not None)
        placed = [s for s in named if s.xy is not None]
        centre = None
        if placed:
            w = np.array([s.weight for s in placed])
            xy = np.array([s.xy for s in placed])
            centre = (_weighted_median(xy[:, 0], w), _weighted_median(xy[:, 1], w))
        subclass = next((s.subclass for s in reversed(named) if s.subclass), None)
        return _Reading(category, subclass, None if sin == 0.0 and cos == 0.0 else math.atan2(sin, cos),
                        centre, bool(named) and all(s.unsure for s in named))

    def _split_off(self, track: _Track, cells: np.ndarray) -> _Track:
        """Split ``track`` in two along ``cells`` (the second item's): the detections that lay
        mostly on those cells go to a new track, those that lay mostly off them stay, and the
        ones that spanned both (the merged views) keep only their cells off them and say
        nothing of either item's front or category. Returns the new track."""
        keys = {(int(c[0]), int(c[1])) for c in cells}
        stay = _Track(track.id, missed=track.missed)  # takes the track's place in the model
        self._tracks[self._tracks.index(track)] = stay
        new = self._new_track()
        for seen in track.history:
            on = len(seen.cells & keys) / max(1, len(seen.cells))
            if on >= 0.6:
                self._add(new, seen)
            elif on <= 0.2:
                self._add(stay, seen)
            else:  # a view of both: its cells off the new item's stay, its words only count
                # while the track has no other view (``read``)
                self._add(stay, dataclasses.replace(seen, cells=seen.cells - keys, merged=True))
        return new

    def _new_track(self) -> _Track:
        """A new, empty track with the next id, added to the model."""
        track = _Track(f"furniture:{self._next}")
        self._next += 1
        self._tracks.append(track)
        return track

    def _in_view(self, track: _Track, pose: Pose2D) -> bool:
        """Whether the track's centre lies well inside the camera's field of view and range."""
        cells = track.cells(self.cell_share)
        if len(cells) == 0:
            return False
        local = pose.to_local(self.grid.cell_to_world(cells).mean(axis=0)[None])[0]
        dist = math.hypot(*local)
        bearing = abs(math.atan2(local[1], local[0]))
        return 1.0 < dist < self.view_range_m - 0.5 and bearing < self.view_half_fov_rad * 0.8

    # ------------------------------------------------------------------ reading
    def furniture(self) -> list[Entity]:
        """The furniture tracks as short-term entities."""
        from assistant.world.catalogue import category_word

        out = []
        for track in self._tracks:
            cells = track.cells(self.cell_share)
            if len(cells) == 0:
                continue
            reading = self.read(track)
            category = reading.category
            has_front = category in FRONT_CATEGORIES
            room = self.world.floorplan.room_at(*self.grid.cell_to_world(cells).mean(axis=0))
            out.append(Entity(track.id, category_word(category), EntityKind.SHORT_TERM, self.grid,
                              cells, reading.orientation if has_front else None, category=category,
                              room=room.name if room else None, confidence=track.confidence,
                              attributes=_attributes(track, reading)))
        return out

    def entities(self, robot_pose: Pose2D | None = None) -> list[Entity]:
        """Long-term entities, then furniture, then (with a pose) the current robot."""
        out = list(self.long_term) + self.furniture()
        if robot_pose is not None:
            out.append(Entity.robot(robot_pose, self.grid))
        return out

    def clear(self) -> None:
        """Forget every perceived entity (the floor plan stays)."""
        self._tracks.clear()
        self._next = 0
        self.frames = 0

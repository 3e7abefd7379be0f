"""World state feature (dissertation 5.4, 5.5.1): the bag of SRVs a policy scores.

The entities of an RDT node are the current robot ``CR`` (a candidate pose), the original
robot ``OR`` (the pose when the node began), the node's ``ref`` (reference) and ``tar``
(target). A :class:`WSF` holds the DIR-SRV and DIST-SRV of every ordered pair of distinct
entities plus the ROT-SRV ``OR -> CR``, always in the order of :func:`srv_slots`, so two
WSFs can be compared value by value and a policy can read one as a vector. A DIR-SRV whose
reference has no front when there is no viewer, and every SRV of a missing entity (a node
without a reference or target), is listed in ``absent`` instead of being zero.

For a search over many candidate poses use :class:`WSFBuilder`: it computes the pairs among
``OR``, ``ref`` and ``tar`` once and, per candidate, only the pairs that involve ``CR`` (a
small disc); when two entities do not overlap, one correlation serves both directions
(``F^{YX}(θ) = F^{XY}(θ + π)``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from assistant.geometry import GridMap, Pose2D
from assistant.spatial.forces import (
    DEFAULT_DIRECTIONS,
    Correlation,
    direction_angles,
    histogram_from_correlation,
    ray_integrals_batch,
)
from assistant.spatial.srv import (
    SRV,
    DirSRV,
    DistSRV,
    aligned_cells,
    direction_word_angles,
    distance_histogram,
    DIST_BIN_M,
    DIST_BINS,
    DIST_MEMBERSHIPS,
    nearest_distances_cells,
    rot_srv,
    split_histogram,
)

ROLES = ("CR", "OR", "ref", "tar")
ROLE_NAMES = {"CR": "current robot", "OR": "original robot", "ref": "reference", "tar": "target"}
#: default viewer: the original robot's heading (the robot's heading when the node began)
VIEWER_ORIGINAL_ROBOT = "original_robot"


def srv_slots() -> list[tuple[str, str, str]]:
    """Every possible SRV of a WSF as ``(kind, reference_role, described_role)``, in the
    stable order of :meth:`WSF.keys`: all DIR pairs, all DIST pairs, then ROT ``OR -> CR``."""
    slots = []
    for kind in ("dir", "dist"):
        for ref in ROLES:
            for desc in ROLES:
                if ref != desc:
                    slots.append((kind, ref, desc))
    slots.append(("rot", "OR", "CR"))
    return slots


_SLOTS = srv_slots()
_SLOT_INDEX = {slot: i for i, slot in enumerate(_SLOTS)}


@dataclass(frozen=True, eq=False)
class WSF:
    """A world state feature: ``srvs`` in :func:`srv_slots` order (present ones only) and
    ``absent`` (the ``"kind:ref->described"`` names of the slots with no SRV)."""

    srvs: tuple[SRV, ...]
    absent: tuple[str, ...]

    def keys(self) -> list[str]:
        """One name per value of :meth:`as_vector`, e.g. ``"dir:ref->CR:front"``."""
        return [key for srv in self.srvs for key in srv.keys()]

    def as_vector(self) -> np.ndarray:
        """All present SRV values concatenated in :meth:`keys` order."""
        if not self.srvs:
            return np.zeros(0)
        return np.concatenate([np.asarray(s.values, dtype=float) for s in self.srvs])

    def get(self, kind: str, reference: str, described: str) -> SRV | None:
        for srv in self.srvs:
            if srv.kind == kind and srv.pair == (reference, described):
                return srv
        return None

    def __getitem__(self, name: str) -> SRV:
        """``wsf["dir:ref->CR"]``; KeyError names the absent or unknown slot."""
        for srv in self.srvs:
            if srv.name == name:
                return srv
        if name in self.absent:
            raise KeyError(f"{name} is absent from this world state feature")
        raise KeyError(f"no SRV {name!r}; present: {', '.join(s.name for s in self.srvs)}")

    def __iter__(self):
        return iter(self.srvs)

    def __len__(self) -> int:
        return len(self.srvs)

    def allclose(self, other: "WSF", atol: float = 1e-9) -> bool:
        """Same present SRVs, same absences, values within ``atol``."""
        return (self.keys() == other.keys() and set(self.absent) == set(other.absent)
                and np.allclose(self.as_vector(), other.as_vector(), rtol=0, atol=atol))

    def to_dict(self) -> dict:
        return {"srvs": {s.name: s.as_dict() for s in self.srvs}, "absent": list(self.absent)}


class _Part:
    """An entity reduced to what the WSF needs: cells on the common grid and a front."""

    __slots__ = ("cells", "orientation", "centre")

    def __init__(self, cells: np.ndarray, orientation: float | None):
        self.cells = cells
        self.orientation = orientation
        self.centre = None  # (iy, ix) of a robot disc built from a pose


class WSFBuilder:
    """World state features of one RDT node at many candidate robot poses.

    ``original_robot``: the robot when the node began (an :class:`~assistant.world.Entity`
    from ``Entity.robot`` or a :class:`~assistant.geometry.Pose2D`); ``reference`` and
    ``target``: entities or None; ``viewer_heading_rad``: the heading that gives front-less
    references their frame — by default the original robot's heading, None for no viewer.
    Pose arguments become robot discs on ``grid`` (default: the grid of the first entity);
    a pose is snapped to the cell that contains it.
    """

    def __init__(self, original_robot, reference=None, target=None,
                 viewer_heading_rad: float | None | str = VIEWER_ORIGINAL_ROBOT,
                 directions: int = DEFAULT_DIRECTIONS, grid: GridMap | None = None,
                 robot_radius_m: float | None = None):
        from assistant.world import ROBOT_RADIUS_M, Entity

        if grid is None:
            for candidate in (reference, target, original_robot):
                if candidate is not None and not isinstance(candidate, Pose2D):
                    grid = candidate.grid
                    break
        if grid is None:
            raise ValueError("give a grid: no entity to take one from (all robots are poses)")
        self.grid = grid
        self.directions = int(directions)
        radius = ROBOT_RADIUS_M if robot_radius_m is None else float(robot_radius_m)
        # the robot disc as cell offsets from the cell holding its centre
        reach = int(np.ceil(radius / grid.resolution_m)) + 2
        # a small grid of the same cell size, just big enough to hold the disc
        host = GridMap(grid.resolution_m, 0.0, 0.0, 2 * reach + 1, 2 * reach + 1)
        mid = np.array([host.height_cells // 2, host.width_cells // 2])
        centre = host.cell_to_world(mid[None, :])[0]
        disc = Entity.robot(Pose2D(centre[0], centre[1], 0.0), host, radius_m=radius)
        self._disc = np.asarray(disc.cells).reshape(-1, 2) - mid
        if not len(self._disc):
            self._disc = np.zeros((1, 2), dtype=np.int64)

        self._or = self._robot_part(original_robot)
        if viewer_heading_rad == VIEWER_ORIGINAL_ROBOT:
            viewer_heading_rad = self._or.orientation
        self.viewer_heading_rad = viewer_heading_rad
        self._fixed: dict[str, _Part] = {"OR": self._or}
        for role, ent in (("ref", reference), ("tar", target)):
            if ent is not None:
                cells = aligned_cells(ent, grid)
                if not len(cells):
                    raise ValueError(f"the {ROLE_NAMES[role]} entity {ent.id!r} has no cells")
                self._fixed[role] = _Part(cells, ent.orientation_rad)
        self._frames: dict[str, tuple[str, np.ndarray] | None] = {}
        self._disc_corr: dict[str, Correlation] = {}
        self._fixed_srvs: dict[tuple[str, str, str], SRV] = {}
        roles = list(self._fixed)
        for i, x in enumerate(roles):
            for y in roles[i + 1:]:
                self._pair_srvs(x, self._fixed[x], y, self._fixed[y], self._fixed_srvs)

    # ------------------------------------------------------------------ parts
    def _robot_part(self, robot) -> _Part:
        if isinstance(robot, Pose2D):
            centre = self.grid.world_to_cell(np.array([[robot.x, robot.y]]))[0]
            part = _Part(self._disc + centre, robot.theta)
            part.centre = (int(centre[0]), int(centre[1]))
            return part
        if robot is None:
            raise ValueError("the original robot is required (its pose when the node began)")
        cells = aligned_cells(robot, self.grid)
        if not len(cells):
            raise ValueError(f"robot entity {robot.id!r} has no cells on the grid")
        if robot.orientation_rad is None:
            raise ValueError(f"robot entity {robot.id!r} has no heading (orientation_rad)")
        return _Part(cells, robot.orientation_rad)

    def _frame(self, role: str, part: _Part):
        """``(frame, memberships (K, 4))`` of a reference role, or None without a frame."""
        if role in self._frames:
            return self._frames[role]
        words = direction_word_angles(part.orientation, self.viewer_heading_rad)
        frame = None if words is None else (words[0], _memberships(words[1], self.directions))
        self._frames[role] = frame
        return frame

    # ------------------------------------------------------------------ pairs
    def _pair_srvs(self, x: str, px: _Part, y: str, py: _Part, out: dict,
                   corr_y_wrt_x: Correlation | None = None) -> None:
        """DIR and DIST SRVs of both ordered pairs of x and y into ``out``.

        ``corr_y_wrt_x`` may pass the cell correlation of y (argument) and x (referent)."""
        k = self.directions
        fx, fy = self._frame(x, px), self._frame(y, py)
        if fx is not None or fy is not None:
            if corr_y_wrt_x is None:
                corr_y_wrt_x = Correlation.of_cells(py.cells, px.cells)
            if corr_y_wrt_x.count_at(0, 0) > 0 or k % 2:  # overlap: split inside / outside
                if fx is not None:
                    h = split_histogram(py.cells, px.cells, k)
                    out[("dir", x, y)] = DirSRV((x, y), np.concatenate([h[:k] @ fx[1], h[k:] @ fx[1]]),
                                                frame=fx[0], histogram=h)
                if fy is not None:
                    h = split_histogram(px.cells, py.cells, k)
                    out[("dir", y, x)] = DirSRV((y, x), np.concatenate([h[:k] @ fy[1], h[k:] @ fy[1]]),
                                                frame=fy[0], histogram=h)
            else:
                h = histogram_from_correlation(corr_y_wrt_x, k, "hybrid")
                self._apart_dir_srvs(x, fx, y, fy, h, out)
        self._dist_srvs(x, px, y, py, out)

    def _apart_dir_srvs(self, x, fx, y, fy, h: np.ndarray, out: dict) -> None:
        """DIR SRVs of two entities that do not overlap, from y's histogram w.r.t. x:
        x's histogram w.r.t. y is the same turned by π (F^{xy}(θ) = F^{yx}(θ + π))."""
        k = self.directions
        zeros4 = np.zeros(4)
        if fx is not None:
            out[("dir", x, y)] = DirSRV((x, y), np.concatenate([h @ fx[1], zeros4]), frame=fx[0],
                                        histogram=np.concatenate([h, np.zeros(k)]))
        if fy is not None:
            h_rev = np.concatenate([h[k // 2:], h[:k // 2], np.zeros(k)])
            out[("dir", y, x)] = DirSRV((y, x), np.concatenate([h_rev[:k] @ fy[1], zeros4]),
                                        frame=fy[0], histogram=h_rev)

    def _dist_srvs(self, x: str, px: _Part, y: str, py: _Part, out: dict) -> None:
        res = self.grid.resolution_m
        d_yx, d_xy = _pair_distances(py.cells, px.cells)
        hist = distance_histogram(d_yx * res)
        out[("dist", x, y)] = DistSRV((x, y), hist @ DIST_MEMBERSHIPS, histogram=hist)
        hist = distance_histogram(d_xy * res)
        out[("dist", y, x)] = DistSRV((y, x), hist @ DIST_MEMBERSHIPS, histogram=hist)

    def _batch_dist_srvs(self, cr: _Part, items: list, out: dict) -> None:
        """DIST SRVs between CR and several entities with one distance matrix."""
        total = sum(len(part.cells) for _, part in items)
        if len(cr.cells) * total > 200_000:
            for role, part in items:
                self._dist_srvs("CR", cr, role, part, out)
            return
        cells = np.concatenate([part.cells for _, part in items])
        lens = np.array([len(part.cells) for _, part in items])
        starts = np.concatenate([[0], np.cumsum(lens)[:-1]])
        dy = cr.cells[:, 0:1] - cells[None, :, 0]
        dx = cr.cells[:, 1:2] - cells[None, :, 1]
        d2 = dy * dy + dx * dx  # (CR cells, all cells of the items), cells²
        scale = self.grid.resolution_m / DIST_BIN_M
        n = len(items)
        # item cells → CR, and CR cells → each item; bin both in one bincount each
        bins_e = np.minimum((np.sqrt(d2.min(axis=0)) * scale + 1e-9).astype(np.intp), DIST_BINS - 1)
        bins_e += np.repeat(np.arange(n) * DIST_BINS, lens)
        hist_e = np.bincount(bins_e, minlength=n * DIST_BINS).reshape(n, DIST_BINS) / lens[:, None]
        bins_c = np.minimum((np.sqrt(np.minimum.reduceat(d2, starts, axis=1)) * scale + 1e-9)
                            .astype(np.intp), DIST_BINS - 1) + np.arange(n) * DIST_BINS
        hist_c = np.bincount(bins_c.ravel(), minlength=n * DIST_BINS).reshape(n, DIST_BINS) / len(cr.cells)
        words_e = hist_e @ DIST_MEMBERSHIPS
        words_c = hist_c @ DIST_MEMBERSHIPS
        for i, (role, _) in enumerate(items):
            out[("dist", "CR", role)] = DistSRV(("CR", role), words_e[i], histogram=hist_e[i])
            out[("dist", role, "CR")] = DistSRV((role, "CR"), words_c[i], histogram=hist_c[i])

    def feature(self, current_robot) -> WSF:
        """The WSF with the current robot at ``current_robot`` (a Pose2D or robot Entity)."""
        k = self.directions
        cr = self._robot_part(current_robot)
        self._frames.pop("CR", None)  # the candidate's heading: its frame is per feature
        f_cr = self._frame("CR", cr)
        srvs = dict(self._fixed_srvs)
        batch = []  # pairs that do not overlap: their histograms are computed together
        for role, part in self._fixed.items():
            if cr.centre is not None:  # a pose: the disc's correlation, moved to the pose
                base = self._disc_corr.get(role)
                if base is None:
                    base = self._disc_corr[role] = Correlation.of_cells(part.cells, self._disc)
                cy, cx = cr.centre
                corr = Correlation(base.counts, base.offset_y - cy, base.offset_x - cx)
            else:
                corr = Correlation.of_cells(part.cells, cr.cells)
            f_role = self._frame(role, part)
            if (f_cr is None and f_role is None) or corr.count_at(0, 0) > 0 or k % 2:
                self._pair_srvs("CR", cr, role, part, srvs, corr)
            else:
                batch.append((role, part, corr, f_role))
        if batch:
            apart = [corr.apart() for _, _, corr, _ in batch]
            rays = ray_integrals_batch([corr for _, _, corr, _ in batch], k, (0, 2) if any(apart) else (0,))
            for (role, part, corr, f_role), ray, is_apart in zip(batch, rays, apart):
                h = ray[2] if is_apart else ray[0]
                total = h.sum()
                if total > 0:
                    h = h / total
                self._apart_dir_srvs("CR", f_cr, role, f_role, h, srvs)
            self._batch_dist_srvs(cr, [(role, part) for role, part, _, _ in batch], srvs)
        srvs[("rot", "OR", "CR")] = rot_srv(cr.orientation, self._or.orientation)
        present = sorted(srvs, key=_SLOT_INDEX.__getitem__)
        absent = tuple(f"{kind}:{r}->{d}" for kind, r, d in _SLOTS if (kind, r, d) not in srvs)
        return WSF(tuple(srvs[s] for s in present), absent)

    __call__ = feature


def _memberships(word_angles: np.ndarray, directions: int) -> np.ndarray:
    diff = direction_angles(directions)[:, None] - word_angles[None, :]
    cos = np.cos(diff)
    return np.where(cos > 0, cos * cos, 0.0)


def _pair_distances(a_cells: np.ndarray, b_cells: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Distances (cells) from each a-cell to the nearest b-cell and from each b-cell to the
    nearest a-cell."""
    if len(a_cells) * len(b_cells) > 60_000:
        return nearest_distances_cells(a_cells, b_cells), nearest_distances_cells(b_cells, a_cells)
    dy = a_cells[:, 0:1] - b_cells[None, :, 0]
    dx = a_cells[:, 1:2] - b_cells[None, :, 1]
    d2 = dy * dy + dx * dx
    return np.sqrt(d2.min(axis=1)), np.sqrt(d2.min(axis=0))


def world_state_feature(current_robot, original_robot, reference=None, target=None,
                        viewer_heading_rad: float | None | str = VIEWER_ORIGINAL_ROBOT,
                        directions: int = DEFAULT_DIRECTIONS, grid: GridMap | None = None) -> WSF:
    """The WSF of one RDT node at one robot pose (dissertation 5.5.1).

    ``current_robot`` and ``original_robot``: robot entities (``Entity.robot``) or poses;
    ``reference``/``target``: :class:`~assistant.world.Entity` or None. The viewer heading
    defaults to the original robot's heading; pass None for no viewer (then DIR-SRVs of
    front-less references are absent). For many poses of one node use :class:`WSFBuilder`.
    """
    builder = WSFBuilder(original_robot, reference, target, viewer_heading_rad, directions, grid)
    return builder.feature(current_robot)

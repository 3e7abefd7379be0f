"""Spatial relation variables (dissertation 5.4.2): DIR-SRV, DIST-SRV and ROT-SRV.

An SRV relates a *described* entity to a *reference* entity (``pair = (reference,
described)``); DIR and DIST are directional (A-to-B differs from B-to-A).

* **DIR-SRV** (equations 5-1 … 5-4): the described entity is split into the cells inside the
  reference and those outside; each part's histogram of forces with respect to the reference
  (hybrid F02: F2 when apart, F0 when touching or inside) is normalized, weighted by the part's
  share of cells and the two are concatenated (``2K`` values, outside first, summing to 1). The
  histogram is then read in the reference's frame and folded into eight words: *front, left,
  back, right* (outside part) and *inner-front … inner-right* (inside part).
  Each word ``q`` at absolute angle ``φ_q`` takes ``Σ_θ μ(θ − φ_q) F(θ)`` with the cosine
  membership ``μ(α) = cos²α`` for ``|α| < π/2`` (0 beyond). The four memberships sum to 1 at
  every angle, so the eight weights sum to 1. (Equation 5-3 prints a linear weight over
  ``±π/4`` that grows away from the peak — a typo; this smooth partition of unity keeps its
  intent and makes diagonal directions count half for each neighbour.)
* **Frames** (dissertation 4.3 II.B, as settled by the spatial-relations issue): a reference
  with a functional front (chair, couch, bed, the robot: ``orientation_rad`` not None) uses its
  *intrinsic* frame: front = its facing, left = facing + π/2. A reference without a front
  (tables, rooms) uses the *viewer's* frame — the robot's heading ``h`` at the start of the
  node, as a person standing there would see it: *front* is the side towards the viewer
  (``h + π``), *back* the far side (``h``), *left*/*right* the viewer's left/right
  (``h ± π/2``). Without a front and without a viewer there is no DIR-SRV (``None``).
* **DIST-SRV** (5-5 … 5-7): every described cell's distance (metres, between cell centres) to
  the nearest reference cell, as a 100-bin histogram over 0–10 m (0.1 m bins; farther cells
  land in the last bin), mapped onto *superposition, near, middle, far* with overlapping
  memberships — normalized Gaussians in ``log(d + 0.1 m)`` centred at 0, 0.4, 1.4 and 3.5 m —
  that are positive everywhere and sum to 1, so the vector changes smoothly with distance.
* **ROT-SRV**: the robot's rotation since the node began, ``wrap(CR.θ − OR.θ)`` in [-π, π).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np

from assistant.geometry import wrap_angle
from assistant.spatial.forces import DEFAULT_DIRECTIONS, Correlation, direction_angles, histogram_from_correlation

DIR_LABELS = ("front", "left", "back", "right", "inner-front", "inner-left", "inner-back", "inner-right")
DIST_LABELS = ("superposition", "near", "middle", "far")
ROT_LABELS = ("rotation",)
DIST_BINS = 100
DIST_BIN_M = 0.1
DIST_CENTRES_M = (0.0, 0.4, 1.4, 3.5)
DIST_WIDTH = 0.5  # in log(d + 0.1 m)
DIST_SOFTENING_M = 0.1


@dataclass(frozen=True, eq=False)
class SRV:
    """A spatial relation variable: ``values`` (one per label) for ``pair = (reference,
    described)``; ``name`` is ``"<kind>:<reference>-><described>"``."""

    kind: ClassVar[str] = "srv"
    labels: ClassVar[tuple[str, ...]] = ()

    pair: tuple[str, str]
    values: np.ndarray

    @property
    def name(self) -> str:
        return f"{self.kind}:{self.pair[0]}->{self.pair[1]}"

    @property
    def reference(self) -> str:
        return self.pair[0]

    @property
    def described(self) -> str:
        return self.pair[1]

    def __getitem__(self, label: str) -> float:
        try:
            return float(self.values[self.labels.index(label)])
        except ValueError:
            raise KeyError(f"{self.kind} SRV has no {label!r}; labels: {', '.join(self.labels)}") from None

    def as_dict(self) -> dict[str, float]:
        return {label: float(v) for label, v in zip(self.labels, self.values)}

    def strongest(self) -> tuple[str, float]:
        """The label with the largest weight, and that weight."""
        i = int(np.argmax(self.values))
        return self.labels[i], float(self.values[i])

    def keys(self) -> list[str]:
        return [f"{self.name}:{label}" for label in self.labels]

    def to_dict(self) -> dict:
        return {"kind": self.kind, "reference": self.pair[0], "described": self.pair[1],
                "values": self.as_dict()}

    def __repr__(self) -> str:
        vals = ", ".join(f"{k}={v:.3f}" for k, v in self.as_dict().items())
        return f"{type(self).__name__}({self.name}: {vals})"


@dataclass(frozen=True, eq=False, repr=False)
class DirSRV(SRV):
    """Eight direction weights (``DIR_LABELS``); ``frame`` is ``intrinsic`` or ``viewer``;
    ``histogram`` the weighted outside+inside histogram (2K values) it was folded from."""

    kind: ClassVar[str] = "dir"
    labels: ClassVar[tuple[str, ...]] = DIR_LABELS

    frame: str = "intrinsic"
    histogram: np.ndarray | None = field(default=None, repr=False)


@dataclass(frozen=True, eq=False, repr=False)
class DistSRV(SRV):
    """Four distance weights (``DIST_LABELS``); ``histogram`` the 100-bin distance histogram."""

    kind: ClassVar[str] = "dist"
    labels: ClassVar[tuple[str, ...]] = DIST_LABELS

    histogram: np.ndarray | None = field(default=None, repr=False)


@dataclass(frozen=True, eq=False, repr=False)
class RotSRV(SRV):
    """The robot's rotation (radians, in [-π, π)) since the node began."""

    kind: ClassVar[str] = "rot"
    labels: ClassVar[tuple[str, ...]] = ROT_LABELS


# ----------------------------------------------------------------------------- frames

def direction_word_angles(orientation_rad: float | None, viewer_heading_rad: float | None
                          ) -> tuple[str, np.ndarray] | None:
    """``(frame, angles)``: the absolute angles (radians) of front, left, back, right for a
    reference with ``orientation_rad`` (its front, or None) seen by a viewer heading
    ``viewer_heading_rad`` (or None). None when neither is known."""
    if orientation_rad is not None:
        f = float(orientation_rad)
        return "intrinsic", np.array([f, f + math.pi / 2, f + math.pi, f - math.pi / 2])
    if viewer_heading_rad is not None:
        h = float(viewer_heading_rad)
        return "viewer", np.array([h + math.pi, h + math.pi / 2, h, h - math.pi / 2])
    return None


_MEMBERSHIP_CACHE: dict[tuple[int, tuple[float, ...]], np.ndarray] = {}


def direction_memberships(word_angles: np.ndarray, directions: int = DEFAULT_DIRECTIONS) -> np.ndarray:
    """(K, 4) cosine memberships ``cos²(θ_k − φ_q)`` (0 beyond ±π/2) of each histogram angle
    in each of the four words."""
    key = (directions, tuple(np.round(word_angles, 12)))
    m = _MEMBERSHIP_CACHE.get(key)
    if m is None:
        diff = direction_angles(directions)[:, None] - np.asarray(word_angles)[None, :]
        cos = np.cos(diff)
        m = np.where(cos > 0, cos * cos, 0.0)
        if len(_MEMBERSHIP_CACHE) > 4096:
            _MEMBERSHIP_CACHE.clear()
        _MEMBERSHIP_CACHE[key] = m
    return m


def fold_directions(histogram_2k: np.ndarray, word_angles: np.ndarray) -> np.ndarray:
    """Eight DIR weights from an outside+inside histogram (equations 5-3, 5-4)."""
    k = len(histogram_2k) // 2
    m = direction_memberships(word_angles, k)
    return np.concatenate([histogram_2k[:k] @ m, histogram_2k[k:] @ m])


# ----------------------------------------------------------------------------- histograms

def split_histogram(described_cells: np.ndarray, reference_cells: np.ndarray,
                    directions: int = DEFAULT_DIRECTIONS) -> np.ndarray:
    """Equations 5-1, 5-2: the described entity's outside and inside parts' hybrid histograms
    with respect to the reference, each normalized and weighted by its share of cells,
    concatenated outside first (``2K`` values summing to 1)."""
    described_cells = np.asarray(described_cells).reshape(-1, 2)
    reference_cells = np.asarray(reference_cells).reshape(-1, 2)
    if not len(described_cells) or not len(reference_cells):
        raise ValueError("both entities need at least one cell for a direction SRV")
    inside = cells_inside(described_cells, reference_cells)
    n_in = int(inside.sum())
    n = len(described_cells)
    out = np.zeros(2 * directions)
    if n_in < n:
        corr = Correlation.of_cells(described_cells[~inside], reference_cells)
        out[:directions] = histogram_from_correlation(corr, directions, "hybrid") * ((n - n_in) / n)
    if n_in:
        corr = Correlation.of_cells(described_cells[inside], reference_cells)
        out[directions:] = histogram_from_correlation(corr, directions, "hybrid") * (n_in / n)
    return out


def cells_inside(cells: np.ndarray, region_cells: np.ndarray) -> np.ndarray:
    """Boolean per row of ``cells``: whether that cell is one of ``region_cells``."""
    lo = region_cells.min(axis=0)
    hi = region_cells.max(axis=0)
    mask = np.zeros(tuple(hi - lo + 1), dtype=bool)
    mask[region_cells[:, 0] - lo[0], region_cells[:, 1] - lo[1]] = True
    rel = cells - lo
    ok = np.all((rel >= 0) & (rel <= hi - lo), axis=1)
    result = np.zeros(len(cells), dtype=bool)
    result[ok] = mask[rel[ok, 0], rel[ok, 1]]
    return result


def nearest_distances_cells(described_cells: np.ndarray, reference_cells: np.ndarray) -> np.ndarray:
    """Distance (in cells, centre to centre) from each described cell to the nearest
    reference cell (0 on shared cells)."""
    d = np.asarray(described_cells, dtype=np.int64)
    r = np.asarray(reference_cells, dtype=np.int64)
    if len(d) * len(r) <= 60_000:
        dy = d[:, 0:1] - r[None, :, 0]
        dx = d[:, 1:2] - r[None, :, 1]
        return np.sqrt((dy * dy + dx * dx).min(axis=1))
    from scipy.ndimage import distance_transform_edt

    lo = np.minimum(d.min(axis=0), r.min(axis=0))
    hi = np.maximum(d.max(axis=0), r.max(axis=0))
    free = np.ones(tuple(hi - lo + 1), dtype=bool)
    free[r[:, 0] - lo[0], r[:, 1] - lo[1]] = False
    edt = distance_transform_edt(free)
    return edt[d[:, 0] - lo[0], d[:, 1] - lo[1]]


def distance_histogram(distances_m: np.ndarray) -> np.ndarray:
    """Equation 5-5: the share of described cells per 0.1 m distance bin over 0–10 m (100
    bins; distances beyond 10 m count in the last bin)."""
    idx = np.minimum((np.asarray(distances_m) / DIST_BIN_M + 1e-9).astype(np.int64), DIST_BINS - 1)
    counts = np.bincount(idx, minlength=DIST_BINS).astype(float)
    return counts / max(len(idx), 1)


def _distance_memberships() -> np.ndarray:
    x = (np.arange(DIST_BINS) + 0.5) * DIST_BIN_M
    x[0] = 0.0  # the first bin is the "on or in the reference" bin
    u = np.log(x + DIST_SOFTENING_M)
    uc = np.log(np.asarray(DIST_CENTRES_M) + DIST_SOFTENING_M)
    w = np.exp(-((u[:, None] - uc[None, :]) ** 2) / (2 * DIST_WIDTH ** 2))
    return w / w.sum(axis=1, keepdims=True)


DIST_MEMBERSHIPS = _distance_memberships()  # (100, 4); rows sum to 1, all entries > 0


# ----------------------------------------------------------------------------- SRVs of entities

def aligned_cells(entity, grid) -> np.ndarray:
    """``entity.cells`` expressed on ``grid`` (same resolution, origins a whole number of
    cells apart); raises ValueError otherwise."""
    g = entity.grid
    if g == grid:
        return np.asarray(entity.cells).reshape(-1, 2)
    if abs(g.resolution_m - grid.resolution_m) > 1e-9 * grid.resolution_m:
        raise ValueError(f"entity {entity.id!r} is on a {g.resolution_m} m grid, expected "
                         f"{grid.resolution_m} m: build all entities of a relation on one grid")
    sx = (g.origin_x_m - grid.origin_x_m) / grid.resolution_m
    sy = (g.origin_y_m - grid.origin_y_m) / grid.resolution_m
    if abs(sx - round(sx)) > 1e-6 or abs(sy - round(sy)) > 1e-6:
        raise ValueError(f"entity {entity.id!r} is on a grid whose origin is not a whole number "
                         "of cells from the others: build all entities on one grid")
    return np.asarray(entity.cells).reshape(-1, 2) + np.array([round(sy), round(sx)])


def dir_srv(reference, described, viewer_heading_rad: float | None = None,
            directions: int = DEFAULT_DIRECTIONS, pair: tuple[str, str] | None = None,
            histogram: np.ndarray | None = None) -> DirSRV | None:
    """The DIR-SRV of ``described`` with respect to ``reference`` (both
    :class:`~assistant.world.Entity`), or None when the reference has no front and there is
    no viewer. ``histogram`` may pass a precomputed :func:`split_histogram`."""
    frame = direction_word_angles(reference.orientation_rad, viewer_heading_rad)
    if frame is None:
        return None
    if histogram is None:
        histogram = split_histogram(aligned_cells(described, reference.grid),
                                    np.asarray(reference.cells).reshape(-1, 2), directions)
    values = fold_directions(histogram, frame[1])
    return DirSRV(pair or (reference.id, described.id), values, frame=frame[0], histogram=histogram)


def dist_srv(reference, described, pair: tuple[str, str] | None = None) -> DistSRV:
    """The DIST-SRV of ``described`` with respect to ``reference`` (equations 5-5 … 5-7)."""
    d_cells = aligned_cells(described, reference.grid)
    r_cells = np.asarray(reference.cells).reshape(-1, 2)
    if not len(d_cells) or not len(r_cells):
        raise ValueError("both entities need at least one cell for a distance SRV")
    dist_m = nearest_distances_cells(d_cells, r_cells) * reference.grid.resolution_m
    hist = distance_histogram(dist_m)
    return DistSRV(pair or (reference.id, described.id), hist @ DIST_MEMBERSHIPS, histogram=hist)


def rot_srv(current_heading_rad: float, original_heading_rad: float,
            pair: tuple[str, str] = ("OR", "CR")) -> RotSRV:
    """The ROT-SRV: rotation from the original to the current heading, in [-π, π)."""
    return RotSRV(pair, np.array([wrap_angle(current_heading_rad - original_heading_rad)]))

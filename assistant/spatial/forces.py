"""Histograms of forces (Matsakis & Wendling 1999; dissertation 5.4.2, Figure 5.4).

Convention
----------
For two crisp objects on a floor grid, the *argument* ``A`` and the *referent* ``R``, the value
at angle ``θ`` (radians, counter-clockwise from +x of the world frame) weighs how much the
argument lies in direction ``θ`` of the referent: a square directly east of the referent puts
its weight at ``θ = 0``, one to the north at ``θ = π/2``. The angles are ``2πk/K``,
``k = 0 … K-1`` (``K = 180`` gives 2° steps).

What is computed (exactness)
----------------------------
Each cell is a unit square (not a point), so an object is a union of squares, and the
histogram is Matsakis' line-integral definition evaluated *exactly* for that union:

    F_r(θ) = ∫_0^∞ C(ρ·u_θ) ρ^{-r} dρ,       u_θ = (cos θ, sin θ),

where ``C(d)`` is the area of ``R ∩ (A − d)`` (how much of the argument, moved back by ``d``,
covers the referent): summing the force ``1/ρ^r`` over every pair of points ``a ∈ A``,
``b ∈ R`` on a common line of direction ``θ`` with ``a − b = ρ·u_θ`` gives exactly this
ray integral. For unions of unit squares ``C`` is the bilinear interpolation of the integer
count of cell pairs per lattice displacement (the overlap of two unit squares is a 2D tent),
and that count array is one 2D cross-correlation of the two masks (the pair differences
counted with ``np.bincount`` for small objects, ``scipy.signal.correlate`` by FFT for large
ones). Along a ray a bilinear function is a quadratic between the grid lines it
crosses, so the integral is taken piece by piece in closed form: ``∫(A + Bt + Qt²)dt`` for
``r = 0``, the primitive of ``(a + bρ + cρ²)/ρ²`` for ``r = 2``. Nothing is sampled or
binned; the only error is floating point (the tests check it against dense numerical
integration and against an independent point-pair estimate). Costs: one correlation plus,
per angle whose ray meets the correlation's support, one evaluation per grid line crossed;
no Python loop over cells or angles.

Why not cells as points: binning the vectors ``a − b`` between cell centres by angle gives
a spiky histogram at short range (only lattice directions occur) and, to agree with the line
integral above, must weigh a pair by ``1/d^(r+1)`` (the polar Jacobian), not ``1/d^r``. The
cell-area form is smooth, agrees with Matsakis' definition for the objects the grid
describes, and refining the grid does not change it.

Units: distances are in cells (the grid has equal cell sizes), so raw values are in
cells³ for ``F0`` (area × length) and cells for ``F2``. With ``normalize=True`` (default) a
histogram sums to 1; the shape of a normalized histogram does not change when both objects
are scaled together (the same shapes described with cells a third of the size give the same
numbers, to rounding).

Forces
------
``constant`` (``r = 0``): every pair counts the same; defined for any objects, also
overlapping ones. ``gravitational`` (``r = 2``): near parts weigh more than far ones; infinite
when the objects overlap or share a cell edge, so it raises there (a shared corner alone
counts as touching too, to keep the rule simple).
``hybrid`` (``F02``): ``F2`` when the objects are apart, ``F0`` when they touch or overlap.
Pairs at distance 0 (a cell shared by both objects) add nothing to ``F0`` beyond their
continuous neighbourhood; the inside/outside split of :mod:`assistant.spatial.srv` is where
overlap is made explicit.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import signal

FORCES = ("constant", "gravitational", "hybrid")
DEFAULT_DIRECTIONS = 180


class Correlation:
    """Count of cell pairs ``(a, b)``, ``a`` in the argument and ``b`` in the referent, per
    lattice displacement ``a − b`` (in cells): ``counts[i, j]`` is the count for the
    displacement ``(dx, dy) = (j + offset_x, i + offset_y)``."""

    __slots__ = ("counts", "offset_y", "offset_x")

    def __init__(self, counts: np.ndarray, offset_y: int, offset_x: int):
        self.counts = counts
        self.offset_y = int(offset_y)
        self.offset_x = int(offset_x)

    @classmethod
    def of_cells(cls, argument_cells: np.ndarray, referent_cells: np.ndarray) -> "Correlation":
        """From two (N, 2) integer arrays of ``(iy, ix)`` cells on the same grid."""
        a = np.asarray(argument_cells, dtype=np.int64).reshape(-1, 2)
        r = np.asarray(referent_cells, dtype=np.int64).reshape(-1, 2)
        a_lo, a_hi = a.min(axis=0), a.max(axis=0)
        r_lo, r_hi = r.min(axis=0), r.max(axis=0)
        off = a_lo - r_hi
        h, w = (a_hi - a_lo) + (r_hi - r_lo) + 1
        if len(a) * len(r) <= 60_000:  # few cells: count the pair differences directly
            idx = ((a[:, None, 0] - r[None, :, 0] - off[0]) * w
                   + (a[:, None, 1] - r[None, :, 1] - off[1]))
            counts = np.bincount(idx.ravel(), minlength=h * w).reshape(h, w).astype(float)
        else:  # many cells: FFT correlation of the cropped masks, rounded back to counts
            a_mask, _ = _crop(a)
            r_mask, _ = _crop(r)
            counts = np.rint(signal.correlate(a_mask.astype(float), r_mask.astype(float),
                                              mode="full", method="fft"))
            counts = np.maximum(counts, 0.0)
        return cls(counts, off[0], off[1])

    def count_at(self, dy: int, dx: int) -> float:
        i, j = dy - self.offset_y, dx - self.offset_x
        if 0 <= i < self.counts.shape[0] and 0 <= j < self.counts.shape[1]:
            return float(self.counts[i, j])
        return 0.0

    def apart(self) -> bool:
        """True when no argument cell shares a cell, an edge or a corner with a referent cell."""
        i0, j0 = -1 - self.offset_y, -1 - self.offset_x
        h, w = self.counts.shape
        block = self.counts[max(i0, 0):max(min(i0 + 3, h), 0), max(j0, 0):max(min(j0 + 3, w), 0)]
        return not np.any(block)

    def reversed(self) -> "Correlation":
        """The correlation with argument and referent swapped (displacements negated)."""
        h, w = self.counts.shape
        return Correlation(self.counts[::-1, ::-1], -(self.offset_y + h - 1), -(self.offset_x + w - 1))


def _crop(cells: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    cells = np.asarray(cells).reshape(-1, 2)
    lo = cells.min(axis=0)
    hi = cells.max(axis=0)
    mask = np.zeros(tuple(hi - lo + 1), dtype=np.int64)
    mask[cells[:, 0] - lo[0], cells[:, 1] - lo[1]] = 1
    return mask, lo


def direction_angles(directions: int = DEFAULT_DIRECTIONS) -> np.ndarray:
    """The angles (radians) of a K-direction histogram: ``2πk/K``."""
    return 2.0 * np.pi * np.arange(directions) / directions


_TRIG_CACHE: dict[int, tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]] = {}
_HUGE = 1e200  # stands for 1/0: finite, so products never give nan


def _trig(directions: int) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """cos, sin and their reciprocals (``_HUGE`` where the cosine/sine is 0) per angle."""
    if directions not in _TRIG_CACHE:
        theta = direction_angles(directions)
        c, s = np.cos(theta), np.sin(theta)
        c[np.abs(c) < 1e-15] = 0.0
        s[np.abs(s) < 1e-15] = 0.0
        inv_c = np.where(c == 0, _HUGE, 1.0 / np.where(c == 0, 1.0, c))
        inv_s = np.where(s == 0, _HUGE, 1.0 / np.where(s == 0, 1.0, s))
        _TRIG_CACHE[directions] = (c, s, inv_c, inv_s)
    return _TRIG_CACHE[directions]


def ray_integrals(corr: Correlation, directions: int = DEFAULT_DIRECTIONS,
                  powers: tuple[int, ...] = (0, 2)) -> dict[int, np.ndarray]:
    """``{r: F_r}`` with ``F_r[k] = ∫_0^∞ C(ρ·u_θk) ρ^{-r} dρ`` for ``r`` in ``powers`` (0, 2).

    Exact for the piecewise-bilinear ``C`` of a cell correlation (see the module docstring).
    ``F_2`` assumes the objects are apart (:meth:`Correlation.apart`); where ``C`` does not
    vanish around the origin it is infinite and the value returned is meaningless.
    """
    return ray_integrals_batch([corr], directions, powers)[0]


def ray_integrals_batch(corrs: list[Correlation], directions: int = DEFAULT_DIRECTIONS,
                        powers: tuple[int, ...] = (0, 2)) -> list[dict[int, np.ndarray]]:
    """:func:`ray_integrals` of several correlations in one vectorised pass (the rays of all
    of them are stacked, so small pairs share the fixed cost of the numpy calls)."""
    for r in powers:
        if r not in (0, 2):
            raise ValueError(f"force power must be 0 or 2, got {r}")
    n = len(corrs)
    outs = [{r: np.zeros(directions) for r in powers} for _ in range(n)]
    if not n:
        return outs
    # The full correlation of two bounding-box-cropped masks has a non-zero entry in every
    # row and column, so its lattice box is the support. C is 0 outside it ± 1 cell; each
    # field gets two zero cells of padding and each box half a cell more than the support,
    # so that a box side is never on the ray origin.
    shapes = np.array([cr.counts.shape for cr in corrs])  # (n, 2): h, w
    widths = shapes[:, 1] + 4
    sizes = (shapes[:, 0] + 4) * widths
    bases = np.concatenate([[0], np.cumsum(sizes)[:-1]])
    flat = np.zeros(int(sizes.sum()))
    for cr, base, w in zip(corrs, bases, widths):
        h = cr.counts.shape[0]
        flat[base:base + (h + 4) * w].reshape(h + 4, w)[2:-2, 2:-2] = cr.counts
    off = np.array([(cr.offset_x, cr.offset_y) for cr in corrs], dtype=float)  # (n, 2)
    xlo, xhi = off[:, 0] - 1.5, off[:, 0] + shapes[:, 1] + 0.5
    ylo, yhi = off[:, 1] - 1.5, off[:, 1] + shapes[:, 0] + 0.5
    c, s, inv_c, inv_s = _trig(directions)
    ax, bx = xlo[:, None] * inv_c, xhi[:, None] * inv_c  # (n, K)
    ay, by = ylo[:, None] * inv_s, yhi[:, None] * inv_s
    rin = np.maximum(np.maximum(np.minimum(ax, bx), np.minimum(ay, by)), 0.0)
    rout = np.minimum(np.maximum(ax, bx), np.maximum(ay, by))
    pair, ang = np.nonzero(rout > rin)
    if not len(pair):
        return outs
    c, s, inv_c, inv_s = c[ang, None], s[ang, None], inv_c[ang, None], inv_s[ang, None]
    rin, rout = rin[pair, ang][:, None], rout[pair, ang][:, None]
    # the grid lines of each box (padded to the largest box: extra lines lie outside the box
    # and clip to empty pieces); a ray crosses each line at most once
    nx, ny = int(shapes[:, 1].max()) + 2, int(shapes[:, 0].max()) + 2
    px = ((xlo + 0.5)[pair, None] + np.arange(nx)) * inv_c
    py = ((ylo + 0.5)[pair, None] + np.arange(ny)) * inv_s
    breaks = np.concatenate([rin, rout, px, py], axis=1)
    np.clip(breaks, rin, rout, out=breaks)
    breaks.sort(axis=1)
    length = breaks[:, 1:] - breaks[:, :-1]
    rho_mid = breaks[:, :-1] + 0.5 * length
    # Each piece lies in one lattice cell, where C is bilinear: along the ray, with t the
    # distance from the piece's midpoint, C = A + B·t + Q·t².
    fx = rho_mid * c - (off[pair, 0] - 2.0)[:, None]  # column in the padded field
    fy = rho_mid * s - (off[pair, 1] - 2.0)[:, None]
    w = widths[pair][:, None]
    ix = fx.astype(np.intp)  # positive: truncation is floor
    iy = fy.astype(np.intp)
    tx = fx - ix
    ty = fy - iy
    k = bases[pair][:, None] + iy * w + ix
    f00 = flat[k]
    e = flat[k + 1] - f00
    g = flat[k + w] - f00
    d = flat[k + w + 1] - f00 - e - g
    dtx = d * tx
    big_a = f00 + e * tx + (g + dtx) * ty
    big_q = d * (c * s)
    results = {}
    if 0 in powers:
        results[0] = np.einsum("ij,ij->i", length, big_a + big_q * (length * length) / 12.0)
    if 2 in powers:
        big_b = (e + d * ty) * c + (g + dtx) * s
        results[2] = _gravitational_pieces(breaks[:, :-1], length, rho_mid, big_a, big_b, big_q)
    for r, values in results.items():
        table = np.zeros((n, directions))
        table[pair, ang] = values
        for i in range(n):
            outs[i][r] = table[i]
    return outs


def _gravitational_pieces(r0, length, rm, big_a, big_b, big_q) -> np.ndarray:
    """Σ over pieces of ∫ q(ρ)/ρ² dρ over ``[r0, r0 + length]`` with q = A + B·t + Q·t²,
    t = ρ − rm: writing q = a + bρ + Qρ², the primitive is −a/ρ + b·ln ρ + Qρ.

    For objects that are apart, q vanishes on every piece that starts at the origin, so those
    pieces (and empty ones) add exactly 0; ``r0`` is kept off 0 only to avoid 0/0.
    """
    r0 = np.maximum(r0, 1e-9)
    b = big_b - 2.0 * big_q * rm
    a = big_a - rm * (big_b - big_q * rm)
    term = a * length / (r0 * (r0 + length)) + b * np.log1p(length / r0) + big_q * length
    return term.sum(axis=1)


def _check_masks(argument, referent) -> tuple[np.ndarray, np.ndarray]:
    a = np.asarray(argument)
    r = np.asarray(referent)
    if a.ndim != 2 or r.ndim != 2:
        raise ValueError(f"argument and referent must be 2D masks indexed [iy, ix], got shapes {a.shape} and {r.shape}")
    if a.shape != r.shape:
        raise ValueError(f"argument and referent must have the same shape, got {a.shape} and {r.shape}")
    a = a.astype(bool)
    r = r.astype(bool)
    if not a.any():
        raise ValueError("the argument mask is empty: a histogram of forces needs at least one cell")
    if not r.any():
        raise ValueError("the referent mask is empty: a histogram of forces needs at least one cell")
    return np.argwhere(a), np.argwhere(r)


def _check_directions(directions: int) -> int:
    if int(directions) != directions or directions < 4:
        raise ValueError(f"directions must be an integer ≥ 4, got {directions}")
    return int(directions)


def histogram_from_cells(argument_cells: np.ndarray, referent_cells: np.ndarray,
                         directions: int = DEFAULT_DIRECTIONS, force: str = "constant",
                         normalize: bool = True) -> np.ndarray:
    """:func:`histogram_of_forces` for (N, 2) ``(iy, ix)`` cell arrays on one grid."""
    directions = _check_directions(directions)
    if force not in FORCES:
        raise ValueError(f"unknown force {force!r}; known: {', '.join(FORCES)}")
    corr = Correlation.of_cells(argument_cells, referent_cells)
    return histogram_from_correlation(corr, directions, force, normalize)


def histogram_from_correlation(corr: Correlation, directions: int, force: str,
                               normalize: bool = True) -> np.ndarray:
    if force == "hybrid":
        force = "gravitational" if corr.apart() else "constant"
    elif force == "gravitational" and not corr.apart():
        raise ValueError("the objects touch or overlap, where the gravitational histogram is "
                         "infinite; use force='hybrid' (F02) or force='constant'")
    power = 2 if force == "gravitational" else 0
    hist = ray_integrals(corr, directions, (power,))[power]
    if normalize:
        total = hist.sum()
        if total > 0:
            hist = hist / total
    return hist


def histogram_of_forces(argument, referent, directions: int = DEFAULT_DIRECTIONS,
                        force: str = "constant", normalize: bool = True) -> np.ndarray:
    """Histogram of forces of ``argument`` with respect to ``referent``.

    ``argument`` and ``referent``: boolean arrays of one shape indexed ``[iy, ix]`` (column
    index grows with +x, row index with +y, square cells). ``force``: ``"constant"`` (F0),
    ``"gravitational"`` (F2; raises ``ValueError`` when the objects touch or overlap) or
    ``"hybrid"`` (F02: F2 when apart, F0 otherwise). Returns ``directions`` values for the
    angles ``2πk/directions``; the value at θ weighs how much the argument lies in direction θ
    of the referent. Normalized to sum 1 unless ``normalize=False`` (then cells³ for F0, cells
    for F2). Exact for crisp objects made of square cells; see the module docstring.
    """
    a_cells, r_cells = _check_masks(argument, referent)
    return histogram_from_cells(a_cells, r_cells, directions, force, normalize)


def force_histograms(argument, referent, directions: int = DEFAULT_DIRECTIONS,
                     normalize: bool = True) -> dict[str, np.ndarray]:
    """Both histograms from one correlation: ``{"constant": F0, "gravitational": F2,
    "hybrid": F02}``. ``gravitational`` is all ``inf`` when the objects touch or overlap."""
    directions = _check_directions(directions)
    a_cells, r_cells = _check_masks(argument, referent)
    corr = Correlation.of_cells(a_cells, r_cells)
    apart = corr.apart()
    raw = ray_integrals(corr, directions, (0, 2) if apart else (0,))
    f0 = raw[0]
    f2 = raw[2] if apart else np.full(directions, math.inf)
    if normalize:
        f0 = f0 / f0.sum() if f0.sum() > 0 else f0
        if apart:
            f2 = f2 / f2.sum() if f2.sum() > 0 else f2
    return {"constant": f0, "gravitational": f2, "hybrid": f2 if apart else f0}

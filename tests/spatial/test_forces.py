"""Histogram of forces: convention, exactness, invariances, speed-independent behaviour."""

import numpy as np
import pytest

from assistant.spatial import direction_angles, force_histograms, histogram_of_forces
from assistant.spatial.forces import Correlation, ray_integrals

K = 180


def box(shape, y0, y1, x0, x1):
    m = np.zeros(shape, dtype=bool)
    m[y0:y1, x0:x1] = True
    return m


SHAPE = (40, 50)
REF = box(SHAPE, 15, 21, 10, 16)


def test_square_east_peaks_at_zero_and_north_at_ninety():
    east = box(SHAPE, 15, 21, 30, 36)
    north = box(SHAPE, 30, 36, 10, 16)
    for force in ("constant", "gravitational", "hybrid"):
        assert np.argmax(histogram_of_forces(east, REF, force=force)) == 0
        assert np.argmax(histogram_of_forces(north, REF, force=force)) == K // 4
    # and the reverse relation points the other way (referent west of argument)
    assert np.argmax(histogram_of_forces(REF, east)) == K // 2


def test_histogram_is_normalized_and_non_negative():
    arg = box(SHAPE, 2, 9, 30, 45)
    h = histogram_of_forces(arg, REF, force="constant")
    assert h.shape == (K,) and np.all(h >= 0) and h.sum() == pytest.approx(1.0)
    h12 = histogram_of_forces(arg, REF, directions=12)
    assert h12.shape == (12,)


def _irregular():
    rng = np.random.default_rng(3)
    a = np.zeros(SHAPE, dtype=bool)
    a[5:12, 25:40] = True
    a[rng.integers(0, 40, 30), rng.integers(30, 50, 30)] = True
    r = np.zeros(SHAPE, dtype=bool)
    r[18:30, 5:14] = True
    r[25, 14:20] = True
    return a, r


def test_mirrored_layout_gives_mirrored_histogram():
    a, r = _irregular()
    h = histogram_of_forces(a, r, force="hybrid")
    hm = histogram_of_forces(a[:, ::-1], r[:, ::-1], force="hybrid")  # mirror x → -x
    # θ ↦ π − θ: index k ↦ K/2 − k (mod K)
    mirrored = h[(K // 2 - np.arange(K)) % K]
    np.testing.assert_allclose(hm, mirrored, atol=1e-12)
    hv = histogram_of_forces(a[::-1, :], r[::-1, :], force="hybrid")  # mirror y → -y
    np.testing.assert_allclose(hv, h[(-np.arange(K)) % K], atol=1e-12)


def test_translation_changes_nothing():
    a, r = _irregular()
    big_a = np.zeros((60, 80), dtype=bool)
    big_r = np.zeros((60, 80), dtype=bool)
    big_a[13:53, 7:57] = a
    big_r[13:53, 7:57] = r
    for force in ("constant", "gravitational"):
        np.testing.assert_allclose(histogram_of_forces(big_a, big_r, force=force, normalize=False),
                                   histogram_of_forces(a, r, force=force, normalize=False), rtol=1e-12)


@pytest.mark.parametrize("force", ["constant", "gravitational"])
def test_uniform_scaling_keeps_the_normalized_histogram(force):
    a, r = _irregular()
    up = np.ones((3, 3), dtype=bool)
    h1 = histogram_of_forces(a, r, force=force)
    h3 = histogram_of_forces(np.kron(a, up), np.kron(r, up), force=force)
    np.testing.assert_allclose(h3, h1, atol=1e-12)
    # raw values scale as s^(3−r): cells³ for F0, cells for F2
    raw1 = histogram_of_forces(a, r, force=force, normalize=False).sum()
    raw3 = histogram_of_forces(np.kron(a, up), np.kron(r, up), force=force, normalize=False).sum()
    assert raw3 / raw1 == pytest.approx(3.0 ** (3 if force == "constant" else 1), rel=1e-9)


def test_gravitational_weighs_near_parts_more():
    # one blob close to the east, an equal blob far to the north
    arg = box((80, 80), 20, 26, 28, 34) | box((80, 80), 60, 66, 20, 26)
    ref = box((80, 80), 20, 26, 20, 26)
    f0 = histogram_of_forces(arg, ref, force="constant")
    f2 = histogram_of_forces(arg, ref, force="gravitational")
    east = slice(0, 23)
    north = slice(K // 4 - 22, K // 4 + 23)
    assert f2[east].sum() / f2[north].sum() > 3 * (f0[east].sum() / f0[north].sum())
    assert f2[east].sum() > f2[north].sum()


def test_gravitational_refuses_touching_objects_and_hybrid_falls_back_to_constant():
    ref = box(SHAPE, 10, 20, 10, 20)
    touching = box(SHAPE, 10, 20, 20, 25)
    with pytest.raises(ValueError, match="touch or overlap"):
        histogram_of_forces(touching, ref, force="gravitational")
    np.testing.assert_allclose(histogram_of_forces(touching, ref, force="hybrid"),
                               histogram_of_forces(touching, ref, force="constant"))
    both = force_histograms(touching, ref)
    assert np.all(np.isinf(both["gravitational"]))
    apart = box(SHAPE, 10, 20, 22, 25)
    both = force_histograms(apart, ref)
    np.testing.assert_allclose(both["hybrid"], both["gravitational"])
    np.testing.assert_allclose(both["gravitational"], histogram_of_forces(apart, ref, force="gravitational"))


def test_inside_object_spreads_all_round():
    ref = box(SHAPE, 5, 35, 5, 45)
    inner = box(SHAPE, 18, 22, 23, 27)  # centred
    h = histogram_of_forces(inner, ref)
    assert np.all(h > 0)
    # centred: opposite directions balance
    np.testing.assert_allclose(h, h[(np.arange(K) + K // 2) % K], atol=1e-12)


def _pair_sampled(a, r, power, sub=4, k=36):
    """Independent check: Matsakis' F_r equals the sum over point pairs of |a−b|^-(r+1) per
    direction (the polar Jacobian), so sample each cell with sub×sub points and bin."""
    offs = (np.arange(sub) + 0.5) / sub - 0.5
    oy, ox = np.meshgrid(offs, offs, indexing="ij")
    def points(m):
        c = np.argwhere(m).astype(float)
        return np.stack([(c[:, 1, None] + ox.ravel()).ravel(), (c[:, 0, None] + oy.ravel()).ravel()], axis=1)
    pa, pr = points(a), points(r)
    d = pa[:, None, :] - pr[None, :, :]
    dist = np.hypot(d[..., 0], d[..., 1]).ravel()
    ang = np.arctan2(d[..., 1], d[..., 0]).ravel() % (2 * np.pi)
    bins = np.floor(ang / (2 * np.pi / k) + 0.5).astype(int) % k
    h = np.bincount(bins, weights=dist ** -(power + 1.0), minlength=k)
    return h / h.sum()


@pytest.mark.parametrize("force,power", [("constant", 0), ("gravitational", 2)])
def test_agrees_with_an_independent_point_pair_estimate(force, power):
    a = box((20, 24), 3, 7, 14, 20)
    r = box((20, 24), 9, 14, 2, 8)
    exact = histogram_of_forces(a, r, directions=720, force=force)
    # integrate the exact curve over 10° bins centred on multiples of 10°
    binned = np.roll(exact, 10).reshape(36, 20).sum(axis=1)
    sampled = _pair_sampled(a, r, power)
    assert np.abs(binned - sampled).max() < 0.02
    assert np.corrcoef(binned, sampled)[0, 1] > 0.995


def test_ray_integrals_match_dense_numerical_integration():
    a, r = _irregular()
    corr = Correlation.of_cells(np.argwhere(a), np.argwhere(r))
    exact = ray_integrals(corr, 36, (0,))[0]
    from scipy.ndimage import map_coordinates
    field = np.pad(corr.counts, 1)
    step = 0.005
    rho = np.arange(step / 2, 90, step)
    numeric = []
    for t in direction_angles(36):
        x, y = rho * np.cos(t), rho * np.sin(t)
        v = map_coordinates(field, [y - corr.offset_y + 1, x - corr.offset_x + 1], order=1, cval=0.0)
        numeric.append(v.sum() * step)
    np.testing.assert_allclose(exact, numeric, rtol=1e-4, atol=1e-3)


def test_correlation_counts_pairs_per_displacement():
    a, r = _irregular()
    ac, rc = np.argwhere(a), np.argwhere(r)
    corr = Correlation.of_cells(ac, rc)
    d = (ac[:, None, :] - rc[None, :, :]).reshape(-1, 2)
    for dy, dx in [(0, 0), (-15, 20), (-10, 25), (5, -3)]:
        assert corr.count_at(dy, dx) == np.sum((d[:, 0] == dy) & (d[:, 1] == dx))
    rev = corr.reversed()
    assert rev.count_at(15, -20) == corr.count_at(-15, 20)


def test_bad_input_is_explained():
    with pytest.raises(ValueError, match="same shape"):
        histogram_of_forces(np.ones((3, 3), bool), np.ones((4, 3), bool))
    with pytest.raises(ValueError, match="argument mask is empty"):
        histogram_of_forces(np.zeros((3, 3), bool), np.ones((3, 3), bool))
    with pytest.raises(ValueError, match="unknown force"):
        histogram_of_forces(REF, box(SHAPE, 0, 2, 0, 2), force="magnetic")

"""Issue 20's cues and regrouping on synthetic point sets (floor frame, metres): the near side
of a bed is closed, a desk's is open; a bed cut by its footboard's shadow is joined back when
the classifier reads the join as a bed; a night stand sticking out of a bed's side is split off
when the classifier reads it as a small table."""

from __future__ import annotations

import math

import numpy as np

from assistant.perception.features import side_cues
from assistant.perception.regroup import range_cut, regroup, shadow_candidates, side_candidates
from assistant.perception.samples import FurnitureSample


def _box_surface(x0, x1, y0, y1, z0, z1, step=0.05, faces=("top", "near")):
    """Points on a box's top and its side facing the camera at the origin (−x side)."""
    xs, ys, zs = (np.arange(a, b + 1e-9, step) for a, b in ((x0, x1), (y0, y1), (z0, z1)))
    out = []
    if "top" in faces:
        out += [(x, y, z1) for x in xs for y in ys]
    if "near" in faces:
        out += [(x0, y, z) for y in ys for z in zs]
    return np.array(out, dtype=float)


def _sample(points, grid=0.05):
    cells = np.unique(np.floor(points[:, :2] / grid), axis=0) * grid + grid / 2
    return FurnitureSample(points, cells, float(np.percentile(points[:, 2], 99)))


def test_a_beds_near_side_is_solid_and_a_desks_is_open():
    bed = _box_surface(2.0, 4.0, -0.8, 0.8, 0.1, 0.55)
    solid, open_ = side_cues(bed, 0.55)
    assert solid > 0.8 and open_ < 0.1
    top = _box_surface(2.0, 2.8, -0.9, 0.9, 0.7, 0.72, faces=("top",))
    legs = np.array([(x, y, z) for x in (2.05, 2.75) for y in (-0.85, 0.85) for z in np.arange(0.1, 0.7, 0.05)])
    back_panel = _box_surface(2.8, 2.8, -0.9, 0.9, 0.3, 0.7, faces=("near",))
    solid, open_ = side_cues(np.vstack([top, legs, back_panel]), 0.72)
    assert solid < 0.2 and open_ > 0.7  # the back panel is seen through the knee space …
    solid, open_ = side_cues(np.vstack([top, legs]), 0.72)
    assert solid < 0.2 and open_ > 0.7  # … or nothing is under the top at all
    assert side_cues(bed, 0.2) == (0.0, 0.0)  # no surface to speak of


def _classify_as(mapping):
    """A stand-in classifier: the subclass named by the first rule whose test the sample passes."""
    def classify(parts):
        out = []
        for s in parts:
            for test, label in mapping:
                if test(s):
                    out.append((label, 0.9))
                    break
        return out
    return classify


def test_a_bed_cut_by_its_footboards_shadow_is_joined_and_the_bench_kept_apart():
    camera = np.array([0.0, 0.0, 1.23])
    bench = _box_surface(2.2, 2.75, -0.8, 0.8, 0.1, 0.55)
    board = _box_surface(2.85, 2.95, -0.9, 0.9, 0.1, 0.95)
    strip = _box_surface(3.6, 3.9, -0.9, 0.9, 0.86, 0.86, faces=("top",))
    samples = [_sample(np.vstack([bench, board])), _sample(strip)]
    found = shadow_candidates(samples, camera, [0.55, 0.86])
    assert len(found) == 1
    ia, ib, join, near = found[0]
    assert (ia, ib) == (0, 1) and near is not None
    assert join.points[:, 0].min() > 2.8 and near.points[:, 0].max() < 2.8
    long_ = lambda s: np.ptp(s.points[:, 0]) > 0.8  # noqa: E731
    out, labels, notes = regroup(samples, [("couch+side", 0.9), ("large table", 0.9)], [0.55, 0.86],
                                 camera, _classify_as([(long_, "bed+front"), (lambda s: True, "other")]))
    assert notes == ["joined across a shadow"]
    assert sorted(lab for lab, _ in labels) == ["bed+front", "other"]
    # a classifier that does not read the join as a bed leaves the samples as they were
    out, labels, notes = regroup(samples, [("couch+side", 0.9), ("large table", 0.9)], [0.55, 0.86],
                                 camera, _classify_as([(lambda s: True, "large table")]))
    assert notes == [] and len(out) == 2
    # a deep item behind (a whole bed, not a strip) is never joined
    deep = _box_surface(3.6, 5.0, -0.9, 0.9, 0.1, 0.86)
    assert shadow_candidates([samples[0], _sample(deep)], camera, [0.55, 0.86]) == []


def test_a_night_stand_beside_a_bed_is_split_off():
    bed = _box_surface(2.0, 4.0, -0.8, 0.8, 0.1, 0.55)
    stand = _box_surface(3.5, 3.95, -1.35, -0.85, 0.1, 0.6)
    sample = _sample(np.vstack([bed, stand]))
    rest, piece = side_candidates(sample)
    assert piece.points[:, 1].max() < -0.8 and np.ptp(piece.points[:, 0]) < 0.6
    assert np.mean(rest.points[:, 1] > -0.9) > 0.97  # points on cell borders may go either way
    small = lambda s: np.ptp(s.points[:, 0]) < 0.6  # noqa: E731
    out, labels, notes = regroup([sample], [("bed+front", 0.95)], [0.55], np.array([0.0, 0.0, 1.2]),
                                 _classify_as([(small, "small table"), (lambda s: True, "bed+front")]))
    assert notes == ["split off a bed's side"] and [lab for lab, _ in labels] == ["bed+front", "small table"]
    assert side_candidates(_sample(bed)) is None  # a plain bed has nothing sticking out


def test_an_item_reaching_the_end_of_the_range_is_cut_by_it():
    assert range_cut(_sample(_box_surface(3.6, 3.95, -0.9, 0.9, 0.86, 0.86, faces=("top",))), 4.0)
    assert not range_cut(_sample(_box_surface(2.0, 3.0, -0.9, 0.9, 0.5, 0.5, faces=("top",))), 4.0)


def test_a_closed_box_beside_a_bed_is_a_night_stand_and_one_far_from_it_stays_other():
    from assistant.perception.detector import night_stands
    from assistant.perception.features import shape_descriptor

    bed = _sample(_box_surface(2.0, 4.0, -0.8, 0.8, 0.1, 0.55))
    near = _sample(_box_surface(3.5, 3.95, -1.5, -1.1, 0.1, 0.6))
    far = _sample(_box_surface(3.5, 3.95, 2.0, 2.4, 0.1, 0.6))
    for s in (bed, near, far):
        normals = np.tile([0.0, 0.0, 1.0], (len(s.points), 1))
        normals[s.points[:, 2] < s.points[:, 2].max() - 0.01] = [-1.0, 0.0, 0.0]
        s.info["shape"] = shape_descriptor(s.points, normals)
    labels = night_stands([bed, near, far], [("bed+front", 0.9), ("other", 0.8), ("other", 0.8)])
    assert [lab for lab, _ in labels] == ["bed+front", "small table", "other"]
    assert night_stands([near], [("other", 0.8)]) == [("other", 0.8)]  # no bed, no night stand


def _foot_end(joined: bool):
    """A footboard and, across its shadow, a strip of mattress reaching the end of the 4 m range
    — as the regrouping leaves SUN 000001's bed — classified as a couch, checked as a table."""
    from assistant.perception.features import shape_descriptor

    board = _box_surface(2.85, 2.95, -0.9, 0.9, 0.1, 0.95)
    strip = _box_surface(3.5, 3.95, -0.9, 0.9, 0.86, 0.86, faces=("top",))
    sample = _sample(np.vstack([board, strip]))
    normals = np.tile([0.0, 0.0, 1.0], (len(sample.points), 1))
    sample.info.update(shape=shape_descriptor(sample.points, normals), checked="large table", bed_probability=0.12)
    if joined:
        sample.info["joined"] = "shadow"
    return sample


def test_a_beds_foot_end_joined_across_its_shadow_and_cut_by_the_range_is_an_unsure_partial_bed(tiny_models):
    """Issue 20: a bed mostly beyond the range, its mattress hidden behind its footboard, is
    reported as a partial bed with what was seen — unsure, with the classifiers' bed probability
    — not as an unknown thing; the same shape not joined across a shadow stays disputed."""
    from assistant.perception.detector import FurnitureDetector

    detector = FurnitureDetector(tiny_models)
    camera = np.array([0.0, 0.0, 1.23])
    found, unknown = detector._detections([_foot_end(True)], [("couch+side", 0.88)], camera, None)
    assert unknown == [] and len(found) == 1
    bed = found[0]
    assert (bed.category, bed.unsure, bed.beyond_range, bed.facing) == ("bed", True, True, None)
    assert bed.confidence == 0.12
    found, unknown = detector._detections([_foot_end(False)], [("couch+side", 0.88)], camera, None)
    assert found == [] and [u.why for u in unknown] == ["disputed"]


def test_the_gap_between_cell_sets_is_the_least_pairwise_distance():
    """``detector._gap_m`` (the night-stand rule's distance from a stand's cells to a bed's) is
    the least Euclidean distance of all pairs, bit for bit as ``np.linalg.norm`` gives it, and
    ``inf`` when the bounding boxes lie farther apart than asked."""
    from assistant.perception.detector import _gap_m

    rng = np.random.default_rng(5)
    for _ in range(50):
        a = rng.normal(0, 1, (int(rng.integers(1, 400)), 2))
        b = rng.normal(0.5, 1, (int(rng.integers(1, 40)), 2))
        want = float(np.min(np.linalg.norm(a[:, None, :] - b[None, :, :], axis=2)))
        assert _gap_m(a, b, 100.0) == want
    assert _gap_m(np.zeros((3, 2)), np.full((2, 2), 5.0), 1.0) == math.inf

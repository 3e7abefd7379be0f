"""DIR / DIST / ROT spatial relation variables."""

import math

import numpy as np
import pytest

from assistant.geometry import GridMap, Pose2D, rectangle
from assistant.spatial import DIR_LABELS, DIST_LABELS, dir_srv, dist_srv, rot_srv, split_histogram
from assistant.spatial.srv import DIST_MEMBERSHIPS, direction_word_angles, distance_histogram
from assistant.world import Entity, EntityKind

GRID = GridMap(0.1, -5.0, -5.0, 100, 100)


def thing(name, x, y, length, width, yaw=0.0, facing=None, grid=GRID):
    poly = rectangle(Pose2D(x, y, yaw), length, width)
    return Entity.from_polygon(name, name, EntityKind.SHORT_TERM, poly, grid, facing)


def couch(facing):
    # a couch 2 m wide, 0.8 m deep, at the origin, its seat facing `facing`
    return thing("couch", 0.0, 0.0, 0.8, 2.0, yaw=facing, facing=facing)


def test_inside_and_outside_parts_sum_to_one():
    big = thing("rug", 0, 0, 3.0, 3.0)
    inner = thing("box", 0.5, 0.5, 0.6, 0.6)
    half = thing("half", 1.5, 0.0, 1.0, 1.0)  # straddles the rug's east edge
    h = split_histogram(inner.cells, big.cells)
    assert h.shape == (360,) and h[:180].sum() == 0 and h.sum() == pytest.approx(1.0)
    h = split_histogram(half.cells, big.cells)
    n_in = 0.5
    assert h[180:].sum() == pytest.approx(n_in, abs=0.06)
    assert h.sum() == pytest.approx(1.0)


def test_object_inside_puts_all_weight_in_the_inner_half():
    big = thing("bed", 0, 0, 2.0, 2.0, facing=0.0)
    pillow = thing("pillow", 0.6, 0.0, 0.4, 0.4)  # in the front part of the bed (+x)
    d = dir_srv(big, pillow)
    assert sum(d.values[:4]) == 0
    assert sum(d.values[4:]) == pytest.approx(1.0)
    assert d.strongest()[0] == "inner-front"


def test_table_in_front_of_a_couch_facing_it():
    table = thing("table", 0.0, 1.2, 0.7, 0.7)  # north of the couch
    facing_table = dir_srv(couch(math.pi / 2), table)
    assert facing_table.frame == "intrinsic"
    assert facing_table.strongest()[0] == "front" and facing_table["front"] > 0.7
    turned_away = dir_srv(couch(-math.pi / 2), table)
    assert turned_away.strongest()[0] == "back" and turned_away["front"] < 0.05
    side_on = dir_srv(couch(0.0), table)  # couch faces east: the table is on its left
    assert side_on.strongest()[0] == "left"


def test_dir_weights_sum_to_one_and_have_the_eight_labels():
    d = dir_srv(couch(0.3), thing("t", 2.0, -1.5, 0.5, 0.5))
    assert tuple(d.as_dict()) == DIR_LABELS
    assert d.values.sum() == pytest.approx(1.0)
    assert np.all(d.values >= 0)


def test_front_less_reference_uses_the_viewer_or_is_absent():
    table = thing("table", 0.0, 0.0, 0.8, 0.8)
    chair = thing("chair", 0.0, -1.0, 0.5, 0.5)  # south of the table
    assert dir_srv(table, chair, viewer_heading_rad=None) is None
    # viewer stands south looking north: the chair is on the viewer's side → "front"
    d = dir_srv(table, chair, viewer_heading_rad=math.pi / 2)
    assert d.frame == "viewer" and d.strongest()[0] == "front"
    # viewer looking north: east is the viewer's right, west the left
    east = thing("e", 1.2, 0.0, 0.5, 0.5)
    assert dir_srv(table, east, viewer_heading_rad=math.pi / 2).strongest()[0] == "right"
    assert dir_srv(table, east, viewer_heading_rad=-math.pi / 2).strongest()[0] == "left"
    assert dir_srv(table, chair, viewer_heading_rad=-math.pi / 2).strongest()[0] == "back"


def test_intrinsic_frame_ignores_the_viewer():
    table = thing("table", 0.0, 1.2, 0.7, 0.7)
    a = dir_srv(couch(math.pi / 2), table, viewer_heading_rad=0.0)
    b = dir_srv(couch(math.pi / 2), table, viewer_heading_rad=2.0)
    np.testing.assert_allclose(a.values, b.values)


def test_word_angles():
    frame, ang = direction_word_angles(0.0, None)
    assert frame == "intrinsic"
    np.testing.assert_allclose(ang, [0, math.pi / 2, math.pi, -math.pi / 2])
    frame, ang = direction_word_angles(None, 0.0)
    assert frame == "viewer"  # front faces the viewer, left is the viewer's left
    np.testing.assert_allclose(ang, [math.pi, math.pi / 2, 0.0, -math.pi / 2])


def test_distance_words_follow_distance():
    ref = thing("ref", 0.0, 0.0, 1.0, 1.0)
    words = []
    for gap in (0.0, 0.3, 1.3, 4.0):
        other = thing("o", 0.5 + gap + 0.15, 0.0, 0.3, 0.3)
        words.append(dist_srv(ref, other).strongest()[0])
    assert words == ["near", "near", "middle", "far"]
    inside = thing("in", 0.0, 0.0, 0.4, 0.4)
    assert dist_srv(ref, inside).strongest() == ("superposition", pytest.approx(1.0, abs=0.02))


def test_distance_vector_changes_smoothly():
    ref = thing("ref", 0.0, 0.0, 1.0, 1.0)
    prev = None
    for step in range(40):
        other = thing("o", 0.9 + 0.1 * step, 0.0, 0.3, 0.3)
        v = dist_srv(ref, other).values
        assert v.sum() == pytest.approx(1.0) and np.all(v > 0)
        if prev is not None:
            assert np.abs(v - prev).max() < 0.3
        prev = v


def test_distance_memberships_overlap_and_partition():
    assert DIST_MEMBERSHIPS.shape == (100, 4)
    assert np.all(DIST_MEMBERSHIPS > 0)
    np.testing.assert_allclose(DIST_MEMBERSHIPS.sum(axis=1), 1.0)
    assert np.abs(np.diff(DIST_MEMBERSHIPS[1:], axis=0)).max() < 0.3  # adjacent 0.1 m bins
    h = distance_histogram(np.array([0.0, 0.05, 0.1, 9.9, 25.0]))
    assert h[0] == pytest.approx(0.4) and h[1] == pytest.approx(0.2) and h[99] == pytest.approx(0.4)
    assert tuple(dist_srv(thing("a", 0, 0, 1, 1), thing("b", 2, 0, 1, 1)).as_dict()) == DIST_LABELS


def test_dist_is_directional():
    big = thing("big", 0.0, 0.0, 3.0, 3.0)
    small = thing("small", 2.0, 0.0, 0.4, 0.4)
    # every cell of the small item is near the big one; most of the big one is not near the small one
    assert dist_srv(big, small)["near"] > dist_srv(small, big)["near"]


def test_rotation():
    assert rot_srv(0.5, 0.2)["rotation"] == pytest.approx(0.3)
    assert rot_srv(-3.0, 3.0)["rotation"] == pytest.approx(2 * math.pi - 6.0)
    assert rot_srv(math.pi, 0.0)["rotation"] == pytest.approx(-math.pi)


def test_entities_on_shifted_grids_line_up_and_other_resolutions_are_refused():
    other_grid = GridMap(0.1, -3.0, -4.0, 80, 80)
    table = thing("table", 0.013, 1.237, 0.66, 0.66, grid=other_grid)
    same = thing("table", 0.013, 1.237, 0.66, 0.66)
    np.testing.assert_allclose(dir_srv(couch(1.0), table).values, dir_srv(couch(1.0), same).values)
    coarse = thing("table", 0.0, 1.2, 0.7, 0.7, grid=GridMap(0.2, -5.0, -5.0, 50, 50))
    with pytest.raises(ValueError, match="one grid"):
        dir_srv(couch(1.0), coarse)

import math

import numpy as np
import pytest

from assistant.geometry import GridMap, Pose2D, angle_difference, wrap_angle


@pytest.mark.parametrize("theta,expected", [(0, 0), (math.pi, -math.pi), (3 * math.pi / 2, -math.pi / 2),
                                            (-3 * math.pi / 2, math.pi / 2), (7.0, 7.0 - 2 * math.pi)])
def test_wrap_angle(theta, expected):
    assert wrap_angle(theta) == pytest.approx(expected)


def test_angle_difference_takes_the_short_way():
    assert angle_difference(math.radians(179), math.radians(-179)) == pytest.approx(math.radians(-2))


def test_compose_and_inverse():
    a = Pose2D(1.0, 2.0, math.pi / 2)
    b = Pose2D(1.0, 0.0, 0.0)
    c = a.compose(b)
    assert (c.x, c.y) == pytest.approx((1.0, 3.0))
    assert c.theta == pytest.approx(math.pi / 2)
    identity = a.compose(a.inverse())
    assert identity.as_tuple() == pytest.approx((0, 0, 0), abs=1e-12)
    assert c.relative_to(a).as_tuple() == pytest.approx(b.as_tuple())


def test_transform_points_roundtrip():
    pose = Pose2D(-3.0, 0.5, 2.0)
    pts = np.array([[1.0, 0.0], [0.0, 2.0], [-1.0, -1.0]])
    assert pose.to_local(pose.transform_points(pts)) == pytest.approx(pts)
    # a point one metre ahead of a robot facing +y lies at +y in the world
    assert Pose2D(0, 0, math.pi / 2).transform_points([[1.0, 0.0]])[0] == pytest.approx([0.0, 1.0])


def test_gridmap_world_cell_roundtrip():
    grid = GridMap(0.1, -1.0, 2.0, 30, 20)
    assert grid.shape == (20, 30)
    cells = grid.world_to_cell([[-0.95, 2.05], [1.95, 3.95]])
    assert cells.tolist() == [[0, 0], [19, 29]]
    assert grid.cell_to_world(cells) == pytest.approx(np.array([[-0.95, 2.05], [1.95, 3.95]]))
    assert grid.contains_cells([[20, 0], [0, -1], [5, 5]]).tolist() == [False, False, True]


def test_gridmap_covering_snaps_to_resolution():
    grid = GridMap.covering(-0.33, 0.12, 1.01, 0.5, resolution_m=0.1)
    assert grid.origin_x_m == pytest.approx(-0.4)
    assert grid.origin_y_m == pytest.approx(0.1)
    xmin, ymin, xmax, ymax = grid.extent
    assert xmax >= 1.01 and ymax >= 0.5


def test_rasterize_polygon_area_and_tiny_objects():
    grid = GridMap(0.1, 0.0, 0.0, 50, 50)
    square = np.array([[1.0, 1.0], [2.0, 1.0], [2.0, 2.0], [1.0, 2.0]])
    assert grid.rasterize_polygon(square).sum() == 100
    tiny = np.array([[3.01, 3.01], [3.03, 3.01], [3.03, 3.03]])
    assert grid.rasterize_polygon(tiny).sum() >= 1


def test_bad_grid_is_refused():
    with pytest.raises(ValueError, match="resolution"):
        GridMap(0.0, 0, 0, 10, 10)

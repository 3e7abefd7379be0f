"""Shapes on the floor: lattices of points inside room polygons."""

import numpy as np


def test_polygon_lattice_keeps_the_points_inside_on_half_step_offsets():
    from assistant.geometry import polygon_lattice

    square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    pts = polygon_lattice(square, 0.5)
    assert sorted(map(tuple, pts)) == [(0.25, 0.25), (0.25, 0.75), (0.75, 0.25), (0.75, 0.75)]
    ell = np.array([[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]])
    pts = polygon_lattice(ell, 0.5, offset_m=0.5)
    assert (1.5, 1.5) not in set(map(tuple, pts)) and (0.5, 1.5) in set(map(tuple, pts))

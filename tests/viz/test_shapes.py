"""Mesh builders of the scene view: triangulation, slabs, ribbons, arrows, cells."""

from __future__ import annotations

import numpy as np
import pytest

from assistant.viz import shapes


def _triangle_areas(corners: np.ndarray, tris: np.ndarray) -> np.ndarray:
    a, b, c = corners[tris[:, 0]], corners[tris[:, 1]], corners[tris[:, 2]]
    return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))


@pytest.mark.parametrize("polygon", [
    [(0, 0), (4, 0), (4, 3), (0, 3)],  # rectangle
    [(0, 0), (4, 0), (4, 1), (1, 1), (1, 3), (0, 3)],  # L-shaped (one reflex corner)
    [(0, 0), (0, 3), (1, 3), (1, 1), (4, 1), (4, 0)],  # the same L, clockwise
    [(0, 0), (5, 0), (5, 4), (3, 4), (3, 1), (2, 1), (2, 4), (0, 4)],  # U-shaped
    [(0, 0), (2, 0), (4, 0), (4, 2), (0, 2), (0, 0)],  # collinear corner, repeated first corner
])
def test_triangulation_covers_the_polygon_exactly(polygon):
    corners, tris = shapes.triangulate_polygon(polygon)
    areas = _triangle_areas(corners, tris)
    assert (areas > 0).all(), "every triangle is counter-clockwise and not degenerate"
    assert areas.sum() == pytest.approx(abs(shapes.polygon_area(np.asarray(polygon, float))))
    # Every triangle's centroid lies inside the polygon: none spans a notch.
    from assistant.geometry import point_in_polygon

    centroids = corners[tris].mean(axis=1)
    assert point_in_polygon(centroids, corners).all()


def test_degenerate_polygon_is_refused():
    with pytest.raises(ValueError, match="at least 3 corners"):
        shapes.triangulate_polygon([(0, 0), (1, 1), (2, 2)])


def test_slab_is_a_closed_prism_between_its_heights():
    vertices, faces = shapes.slab_mesh([(0, 0), (2, 0), (2, 1), (0, 1)], 0.0, 0.01)
    assert vertices.shape == (8, 3) and faces.shape == (2 + 2 + 8, 3)
    assert set(np.round(vertices[:, 2], 6)) == {0.0, 0.01}
    # Closed surface: every edge is shared by exactly two faces.
    edges = {}
    for f in faces:
        for i, j in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0])):
            key = (min(i, j), max(i, j))
            edges[key] = edges.get(key, 0) + 1
    assert set(edges.values()) == {2}


def test_ribbon_has_a_quad_per_segment_of_the_given_width():
    vertices, faces = shapes.ribbon_mesh([(0, 0), (1, 0), (1, 0), (1, 2)], 0.1, 0.03)
    assert faces.shape == (4, 3)  # the zero-length segment is skipped
    first = vertices[:4]
    assert np.ptp(first[:, 1]) == pytest.approx(0.1)
    assert np.allclose(vertices[:, 2], 0.03)


def test_arrows_point_along_their_heading_with_their_length_and_colour():
    poses = np.array([[0.0, 0.0, 0.0], [1.0, 1.0, np.pi / 2]])
    vertices, faces, colours = shapes.arrows_mesh(poses, [0.2, 0.5], [(1, 0, 0), (0, 1, 0)])
    assert vertices.shape == (14, 3) and faces.shape == (6, 3) and colours.shape == (14, 3)
    tip0, tip1 = vertices[5], vertices[7 + 5]
    assert tip0[:2] == pytest.approx([0.2, 0.0])
    assert tip1[:2] == pytest.approx([1.0, 1.5])
    assert np.allclose(colours[:7], [1, 0, 0]) and np.allclose(colours[7:], [0, 1, 0])
    with pytest.raises(ValueError, match="one of each"):
        shapes.arrows_mesh(poses, [0.2], [(1, 0, 0), (0, 1, 0)])


def test_cells_mesh_has_two_triangles_per_cell():
    vertices, faces = shapes.cells_mesh([(0, 0), (0.05, 0)], 0.05, 0.02)
    assert vertices.shape == (8, 3) and faces.shape == (4, 3)
    assert vertices[:, 0].min() == pytest.approx(-0.025) and vertices[:, 0].max() == pytest.approx(0.075)


def test_mesh_arrays_reads_an_open3d_mesh():
    o3d = pytest.importorskip("open3d")
    box = o3d.geometry.TriangleMesh.create_box(1.0, 2.0, 3.0)
    vertices, faces, colours = shapes.mesh_arrays(box)
    assert vertices.shape == (8, 3) and faces.shape == (12, 3) and colours is None
    box.paint_uniform_color((0.2, 0.4, 0.6))
    assert np.allclose(shapes.mesh_arrays(box)[2], (0.2, 0.4, 0.6))

"""Procedural meshes: catalogue sizes, recognisable parts on the right sides, world placement."""

from __future__ import annotations

import math

import numpy as np
import pytest

from assistant.errors import UnknownNameError
from assistant.sim import furniture_mesh, object_mesh, scene_meshes, wall_mesh
from assistant.world import load_catalogue


def _bounds(mesh):
    v = np.asarray(mesh.vertices)
    return v.min(axis=0), v.max(axis=0)


@pytest.mark.parametrize("model", sorted(load_catalogue().models))
def test_furniture_mesh_matches_catalogue_size(model):
    spec = load_catalogue().model(model)
    lo, hi = _bounds(furniture_mesh(model))
    size = hi - lo
    assert size == pytest.approx([spec.length_m, spec.width_m, spec.height_m], abs=0.005)
    assert lo[2] == pytest.approx(0.0, abs=1e-9)  # stands on the floor
    assert (lo[:2] + hi[:2]) / 2 == pytest.approx([0.0, 0.0], abs=0.005)  # centred


@pytest.mark.parametrize("name", sorted(load_catalogue().objects))
def test_object_mesh_matches_catalogue_size(name):
    spec = load_catalogue().object(name)
    lo, hi = _bounds(object_mesh(name))
    assert hi - lo == pytest.approx([spec.length_m, spec.width_m, spec.height_m], abs=0.02)
    assert lo[2] == pytest.approx(0.0, abs=1e-9)


def _high_vertices(model, above_fraction):
    mesh = furniture_mesh(model)
    v = np.asarray(mesh.vertices)
    return v[v[:, 2] > above_fraction * load_catalogue().model(model).height_m]


@pytest.mark.parametrize("model", ["wood chair", "blue chair", "couch", "bed"])
def test_back_or_headboard_is_opposite_the_front(model):
    """What rises above the seat/mattress sits on the side opposite the functional front."""
    spec = load_catalogue().model(model)
    high = _high_vertices(model, 0.8)
    assert len(high)
    front = np.array([math.cos(spec.front_offset_rad), math.sin(spec.front_offset_rad)])
    assert np.all(high[:, :2] @ front < 0), f"{model}: the tall part is not behind its front"


@pytest.mark.parametrize("model", ["round table", "coffee table", "hexagon table", "dinner table"])
def test_tables_have_a_top_over_legs(model):
    spec = load_catalogue().model(model)
    v = np.asarray(furniture_mesh(model).vertices)
    low = v[v[:, 2] < spec.height_m * 0.5]  # only the legs reach below the top
    extent = low[:, :2].max(axis=0) - low[:, :2].min(axis=0)
    # four separate legs: nothing at the centre of the footprint below the top
    assert not np.any(np.hypot(low[:, 0], low[:, 1]) < 0.05)
    assert np.all(extent > 0.2)


def test_unknown_names_are_listed():
    with pytest.raises(UnknownNameError, match="coffee table"):
        furniture_mesh("coffe table")
    with pytest.raises(UnknownNameError, match="mug"):
        object_mesh("cup")


def test_meshes_are_copies():
    a = furniture_mesh("couch")
    a.translate((10.0, 0.0, 0.0))
    lo, _ = _bounds(furniture_mesh("couch"))
    assert lo[0] < 0


def test_walls_are_two_metres_high(apartment):
    lo, hi = _bounds(wall_mesh(apartment.floorplan.walls[0]))
    assert hi[2] - lo[2] == pytest.approx(2.0)
    w = apartment.floorplan.walls[0]
    assert lo[:2] == pytest.approx([w.xmin, w.ymin]) and hi[:2] == pytest.approx([w.xmax, w.ymax])


@pytest.mark.parametrize("scene", ["original", "modified"])
def test_scene_meshes_place_everything_in_the_world(all_worlds, scene):
    for world in all_worlds.values():
        sc = world.scene(scene)
        meshes = scene_meshes(world, scene)
        ids = [m.id for m in meshes]
        assert len(ids) == len(set(ids))
        kinds = {m.kind for m in meshes}
        assert kinds <= {"floor", "wall", "furniture", "object"} and "floor" in kinds
        assert sum(m.kind == "wall" for m in meshes) == len(world.floorplan.walls)
        by_id = {m.id: m for m in meshes}
        for item in sc.furniture:
            lo, hi = _bounds(by_id[item.id].mesh)
            assert (lo[:2] + hi[:2]) / 2 == pytest.approx([item.x, item.y], abs=0.05)
            assert hi[2] == pytest.approx(item.height_m, abs=1e-6)
            assert by_id[item.id].name == item.model
        for obj in sc.objects:
            lo, hi = _bounds(by_id[obj.name].mesh)
            assert lo[2] == pytest.approx(sc.object_height_m(obj), abs=1e-6)  # on its furniture
            assert (lo[:2] + hi[:2]) / 2 == pytest.approx([obj.x, obj.y], abs=0.1)

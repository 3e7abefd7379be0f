import numpy as np

from assistant.perception.database import (
    GRID_DIRECTIONS_DEG,
    GRID_DISTANCES_M,
    Database,
    ViewPlan,
    cached_database,
    other_items,
    render_database,
    study_items,
)
from assistant.perception.instances import instance_mesh, load_instances


def test_tiny_database_is_labelled(tiny_database):
    db = tiny_database
    assert len(db) >= 28  # 4 items × 8 views, a few may be missed
    assert db.X.shape[1] == 800 and db.S.shape[1] == 49 and db.Q.shape == db.X.shape
    assert set(db.category) == {"chair", "couch", "small table", "bed"}
    tables = db.category == "small table"
    assert np.isnan(db.facing[tables]).all() and np.isfinite(db.facing[~tables]).all()


def test_rendering_is_deterministic_and_cached():
    items = [i for i in study_items() if i.name == "round table"]
    plan = ViewPlan(grid=False, random_per_item=2, seed=11)
    a = render_database(items, plan)
    b = render_database(items, plan)
    assert np.array_equal(a.X, b.X)
    c = cached_database("unit", items, plan)
    d = cached_database("unit", items, plan)  # from the cache file
    assert np.array_equal(c.X, d.X) and np.array_equal(a.X, c.X)
    assert Database.from_bytes(c.to_bytes()).category.tolist() == c.category.tolist()


def test_grid_plan_and_other_instances():
    assert len(GRID_DIRECTIONS_DEG) * len(GRID_DISTANCES_M) == 24
    instances = load_instances()
    assert {i.category for i in instances.values()} == {"chair", "couch", "bed", "small table", "large table"}
    assert {i.name for i in other_items()}.isdisjoint({i.name for i in study_items()})
    mesh = instance_mesh("slat chair")
    extent = mesh.get_axis_aligned_bounding_box().get_extent()
    assert extent == __import__("pytest").approx([0.48, 0.50, 0.95], abs=0.01)

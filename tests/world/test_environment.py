import math

import numpy as np
import pytest

from assistant.geometry import Pose2D, rectangle
from assistant.world.entity import Entity, EntityKind
from assistant.world.environment import EnvironmentModel


def seen(model, x, y, length, width, category, facing=None, confidence=0.9):
    poly = rectangle(Pose2D(x, y, 0.0), length, width)
    return Entity.from_polygon("d", category, EntityKind.SHORT_TERM, poly, model.grid, facing,
                               category=category, confidence=confidence)


def test_detections_fuse_into_entities_with_the_floor_plan(apartment):
    model = EnvironmentModel(apartment)
    model.update([seen(model, 4.5, 3.0, 2.0, 0.7, "couch", 1.5), seen(model, 4.5, 4.0, 0.7, 0.7, "small table")])
    model.update([seen(model, 4.55, 3.05, 2.0, 0.7, "couch", 1.6), seen(model, 4.45, 4.0, 0.7, 0.7, "small table")])
    furniture = model.furniture()
    assert len(furniture) == 2
    couch = next(e for e in furniture if e.category == "couch")
    assert couch.name == "couch" and couch.room == "living room"
    assert couch.orientation_rad == pytest.approx(1.55, abs=0.01)
    assert couch.centroid_m == pytest.approx([4.5, 3.0], abs=0.1)
    assert couch.attributes["seen"] == 2
    table = next(e for e in furniture if e.category == "small table")
    assert table.name == "table" and table.orientation_rad is None
    kinds = {e.name for e in model.entities()}
    assert {"room", "wall", "door", "couch", "table"} <= kinds


def test_category_votes_and_moved_furniture_is_forgotten(apartment):
    model = EnvironmentModel(apartment)
    model.update([seen(model, 4.5, 5.0, 0.6, 0.6, "chair", 0.0, 0.9)])
    model.update([seen(model, 4.5, 5.0, 0.6, 0.6, "small table", None, 0.4)])
    assert [e.category for e in model.furniture()] == ["chair"]
    robot = Pose2D(2.3, 5.0, 0.0)  # 2.2 m away, looking straight at it
    for _ in range(3):
        model.update([], robot)
    assert model.furniture() == []


def test_a_detection_on_another_grid_is_regridded(apartment):
    from assistant.geometry import GridMap

    model = EnvironmentModel(apartment)
    other = GridMap.covering(3.0, 2.0, 6.0, 5.0, resolution_m=0.1)
    det = Entity.from_polygon("d", "couch", EntityKind.SHORT_TERM,
                              rectangle(Pose2D(4.5, 3.0, 0.0), 2.0, 0.7), other, 1.57, category="couch")
    model.update([det])
    assert model.furniture()[0].centroid_m == pytest.approx([4.5, 3.0], abs=0.1)
    assert model.furniture()[0].grid == model.grid

import numpy as np
import pytest

from assistant.geometry import Pose2D
from assistant.world import Entity, EntityKind, floorplan_entities, furniture_entities, world_grid


def test_furniture_entities_cover_their_footprints(apartment):
    grid = world_grid(apartment, 0.05)
    entities = {e.id: e for e in furniture_entities(apartment, "original", grid)}
    couch = entities["couch_1"]
    assert couch.name == "couch" and couch.kind is EntityKind.SHORT_TERM
    assert couch.area_m2 == pytest.approx(0.73 * 2.06, rel=0.1)
    assert couch.centroid_m == pytest.approx([4.5, 3.0], abs=0.05)
    assert couch.orientation_rad == pytest.approx(1.571)
    assert entities["coffeetable_1"].orientation_rad is None
    assert entities["coffeetable_1"].name == "table"


def test_floorplan_entities_and_robot(apartment):
    grid = world_grid(apartment, 0.1)
    kinds = {e.name for e in floorplan_entities(apartment, grid)}
    assert kinds == {"room", "wall", "door"}
    robot = Entity.robot(Pose2D(5.0, 0.0, np.pi), grid)
    assert robot.area_m2 == pytest.approx(np.pi * 0.25 ** 2, rel=0.35)
    assert robot.mask().sum() == len(robot.cells)

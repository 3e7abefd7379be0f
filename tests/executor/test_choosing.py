"""How the fetch task surveys a room and judges what it can see (which furniture fits an RDT is
:func:`assistant.spatial.resolve`, tested in ``tests/spatial/test_resolve.py``)."""

from __future__ import annotations

import math

import pytest

from assistant.executor.fetch import FetchTask
from assistant.executor.sensing import OracleFurniture
from assistant.geometry import Pose2D


@pytest.fixture
def studio(all_worlds):
    world = all_worlds["hk-studio"]
    task = FetchTask(world, OracleFurniture(world, "original"))
    task._support, task._descriptors = "desk", ()
    return task


#: at the studio door, looking in (north)
DOOR = Pose2D(-2.1, 0.8, math.pi / 2)


def test_a_large_room_seen_from_its_door_is_surveyed(studio, all_worlds):
    studio._looked_from = [Pose2D(-2.1, 0.3, math.pi / 2)]
    points = studio._room_points("studio")
    assert studio._unseen(points).mean() > studio.max_unseen_share  # most of the studio is far
    bedroom = FetchTask(all_worlds["one-bedroom-house"], OracleFurniture(all_worlds["one-bedroom-house"], "original"))
    bedroom._looked_from = [Pose2D(3.1, 5.7, math.pi / 2)]
    assert bedroom._unseen(bedroom._room_points("bedroom")).mean() <= bedroom.max_unseen_share


def test_other_furniture_on_the_line_of_sight_hides_the_target(all_worlds):
    world = all_worlds["apartment"]
    task = FetchTask(world, OracleFurniture(world, "original"))
    table = next(e for e in task._in_room("living room", "table") if e.id == "roundtable_1")  # (4.0, 2.0)
    # from the couch's far side (couch_1 spans x 3.47–5.53 at y ≈ 3), the couch is in the way
    assert not task._clear_sight(table, 4.0, 3.9)
    # from the south-west, over open floor, nothing is
    assert task._clear_sight(table, 2.8, 1.6)
    assert not task._in_view(table, Pose2D(4.0, 3.9, -math.pi / 2))
    assert task._in_view(table, Pose2D(2.8, 1.6, math.atan2(0.4, 1.2)))

"""How a static node picks its target among perceived furniture (no robot needed: the choice
reads only perception and the pose the command was said from)."""

from __future__ import annotations

import math

import pytest

from assistant.executor.fetch import FetchTask
from assistant.executor.sensing import OracleFurniture
from assistant.geometry import Pose2D
from assistant.grounding import RDT


@pytest.fixture
def studio(all_worlds):
    world = all_worlds["hk-studio"]
    task = FetchTask(world, OracleFurniture(world, "original"))
    task._support, task._descriptors = "desk", ()
    return task


#: at the studio door, looking in (north)
DOOR = Pose2D(-2.1, 0.8, math.pi / 2)


def test_against_the_left_wall_is_the_desk_at_the_west_wall(studio):
    # desk_1 is nearer and on the left too, but it stands off the west wall; desk_2 is against it
    ref, target, _ = studio._choose_pair(RDT("wall", "left", "table"), "studio", DOOR)
    assert ref is None and target.id == "desk_2"


def test_room_sides_are_seen_from_the_robot(studio):
    desks = {e.id: e for e in studio._in_room("studio", "table")}
    back = {k: studio._room_side_fit(e, DOOR, "back") for k, e in desks.items()}
    left = {k: studio._room_side_fit(e, DOOR, "left") for k, e in desks.items()}
    assert back["desk_2"] > back["desk_1"]  # the far end
    assert left["desk_1"] > left["hexagontable_1"] and left["desk_2"] > left["hexagontable_1"]


def test_every_pair_of_the_node_counts(studio):
    # "the desk next to the wooden chair at the back on the left": both desks have a chair
    beside = RDT("chair", "beside", "table")
    others = [RDT("room", "left", "table"), RDT("room", "back", "table")]
    assert studio._choose_pair(beside, "studio", DOOR, others)[1].id == "desk_2"
    agreement = studio._agreement(others, "studio", studio._in_room("studio", "table"), DOOR)
    assert agreement["desk_2"] == 1.0 and 0.3 <= agreement["desk_1"] < 1.0


def test_a_large_room_seen_from_its_door_is_surveyed(studio, all_worlds):
    studio._looked_from = [Pose2D(-2.1, 0.3, math.pi / 2)]
    points = studio._room_points("studio")
    assert studio._unseen(points).mean() > studio.max_unseen_share  # most of the studio is far
    bedroom = FetchTask(all_worlds["one-bedroom-house"], OracleFurniture(all_worlds["one-bedroom-house"], "original"))
    bedroom._looked_from = [Pose2D(3.1, 5.7, math.pi / 2)]
    assert bedroom._unseen(bedroom._room_points("bedroom")).mean() <= bedroom.max_unseen_share


def test_the_back_wall_is_the_far_wall_as_one_enters(all_worlds):
    # the apartment's living room seen from its door (south side, looking north): the dinner
    # table stands near the far (north) wall, the round table near the door's own wall
    world = all_worlds["apartment"]
    task = FetchTask(world, OracleFurniture(world, "original"))
    task._support, task._descriptors = None, ()
    door = Pose2D(4.5, 1.8, math.pi / 2)
    _, target, _ = task._choose_pair(RDT("wall", "back", "table"), "living room", door)
    assert target.id == "dinnertable_1"


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

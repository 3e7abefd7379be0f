import math

import pytest

from assistant.errors import UnknownNameError
from assistant.executor import RoomGraph, room_entry_waypoints, room_of
from assistant.world import load_world, parse_world


def test_room_graph_of_the_apartment(apartment):
    graph = RoomGraph(apartment)
    assert set(graph.rooms) == {"hallway", "living room", "bedroom"}
    assert graph.room_route("living room", "bedroom") == ["living room", "hallway", "bedroom"]
    assert [d.name for d in graph.doors_between("hallway", "bedroom")] == ["bedroom door"]
    assert "outside" not in graph.graph  # the robot never leaves the home


@pytest.mark.parametrize("world_name", ["apartment", "training-home"])
def test_entry_waypoints_go_through_the_door_into_the_room(world_name):
    world = load_world(world_name)
    poses = room_entry_waypoints(world, "hallway", "living room")
    assert len(poses) == 2
    centre, inside = poses
    living_door = next(d for d in world.floorplan.doors if "living room" in d.connects)
    assert (centre.x, centre.y) == pytest.approx(living_door.centre)
    assert world.floorplan.room("living room").contains(inside.x, inside.y)
    assert 0.6 <= math.dist((centre.x, centre.y), (inside.x, inside.y)) <= 0.8
    # headed into the room
    assert math.cos(inside.theta) * (inside.x - centre.x) + math.sin(inside.theta) * (inside.y - centre.y) > 0.5


def test_entry_waypoints_across_the_hallway():
    world = load_world("training-home")
    poses = room_entry_waypoints(world, "living room", "bedroom")
    assert len(poses) == 4  # out through the living room door, in through the bedroom door
    assert world.floorplan.room("hallway").contains(poses[1].x, poses[1].y)
    assert world.floorplan.room("bedroom").contains(poses[3].x, poses[3].y)
    assert room_entry_waypoints(world, "bedroom", "bedroom") == []


def test_unknown_and_unconnected_rooms():
    world = load_world("apartment")
    with pytest.raises(UnknownNameError) as caught:
        room_entry_waypoints(world, "hallway", "kitchen")
    assert "living room" in str(caught.value)
    lonely = parse_world("""
name: two-cells
start: {x: 1.0, y: 1.0, heading: 0.0}
rooms:
- {name: a, polygon: [[0, 0], [2, 0], [2, 2], [0, 2]]}
- {name: b, polygon: [[2.1, 0], [4, 0], [4, 2], [2.1, 2]]}
walls:
- [2.0, 0.0, 2.1, 2.0]
scenes:
  original: {furniture: []}
""")
    assert room_entry_waypoints(lonely, "a", "b") is None


def test_room_of_a_doorway_is_the_nearest_room(apartment):
    assert room_of(apartment, apartment.start) == "hallway"
    assert room_of(apartment, (2.633, 1.283)) in {"hallway", "living room"}
    assert room_of(apartment, (50.0, 50.0)) is None

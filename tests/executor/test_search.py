"""The robot's search for an object (room by room, sensed perception, the object detector)."""

from __future__ import annotations

import pytest

from assistant.executor.outcome import ExecutionStatus
from assistant.executor.context import TaskContext
from assistant.executor.search import SEARCH_BUDGET_S, SearchTask, room_order
from assistant.executor.sensing import SensedFurniture
from assistant.perception.objects import SimObjectDetector
from assistant.perception.objects import Sighting
from assistant.world import load_world


@pytest.fixture(scope="module")
def furniture_detector():
    from assistant.perception import FurnitureDetector

    return FurnitureDetector()


def search_for(name, world, scene, furniture_detector, on_event=None, **params):
    """The search task with the simulator (odometry noise on), sensed furniture and the
    simulator's object detector, from the world's start."""
    from assistant.sim import OdometryNoise, SimRobot

    world = load_world(world) if isinstance(world, str) else world
    with SimRobot(world, scene, seed=0, odometry_noise=OdometryNoise()) as robot:
        ctx = TaskContext.start(world, robot, SensedFurniture(world, detector=furniture_detector),
                                max_sim_seconds=SEARCH_BUDGET_S, on_event=on_event)
        return SearchTask(SimObjectDetector.for_scene(world.scene(scene)), **params).run(ctx, name)


@pytest.fixture(scope="module")
def describer():
    from assistant.generation import Describer

    return Describer()


def test_rooms_are_ordered_from_the_start_room_then_nearest():
    world = load_world("apartment")
    order = room_order(world, "hallway")
    assert sorted(order) == sorted(world.floorplan.room_names)
    # the bedroom's door is nearer the hallway than the living room's far side
    assert order == ["hallway", "bedroom", "living room"]
    # from the bedroom the living room is reached through the hallway: the hallway comes next
    assert room_order(world, "bedroom") == ["bedroom", "hallway", "living room"]
    # no start room: the room whose centre is nearest the start point
    assert room_order(world, None, (4.0, 4.0))[0] == "living room"


def test_search_finds_the_object_and_reports_what_it_sees(furniture_detector):
    events = []
    result = search_for("laptop", "hk-studio", "original", furniture_detector=furniture_detector,
                        on_event=lambda name, data: events.append((name, data)))
    assert result.found and result.status is ExecutionStatus.SUCCESS
    assert result.sighting.room == "meeting room"
    assert abs(result.sighting.x_m - -4.0) < 0.3 and abs(result.sighting.y_m - -2.9) < 0.3
    assert result.sighting.furniture_category in ("large table", "small table")
    assert any(e.name == "table" for e in result.furniture)  # the environment model it built
    seen = [d for n, d in events if n == "objects_seen"]
    assert seen and all(isinstance(p, Sighting) and p.room for d in seen for p in d["seen"])
    assert all("pose" in d for d in seen)
    assert "laptop" in result.seen
    assert result.sim_seconds > 0 and result.wall_seconds > 0 and result.frames >= 1


def test_an_object_that_is_nowhere_gets_an_honest_answer_after_the_search(furniture_detector, describer):
    world = load_world("apartment")
    result = search_for("stapler", world, "original", furniture_detector=furniture_detector,
                        max_vantages=0)  # entry look-arounds only: a short test
    assert not result.found and result.status is ExecutionStatus.NOT_FOUND
    assert sorted(result.rooms_searched) == sorted(world.floorplan.room_names)
    answer = describer.describe_search(result, world.floorplan)
    assert not answer.found and answer.search == "sensed"
    assert answer.description == ("I looked in the " + ", the ".join(result.rooms_searched[:-1])
                                  + f" and the {result.rooms_searched[-1]} and did not find a stapler.")


def test_the_description_is_composed_from_the_perceived_furniture(furniture_detector, describer):
    world = load_world("hk-studio")
    result = search_for("laptop", world, "original", furniture_detector=furniture_detector)
    answer = describer.describe_search(result, world.floorplan)
    assert answer.found and answer.search == "sensed" and answer.environment == "perceived"
    support = next(n for n in answer.selected if n.kind == "support")
    assert support.reference_id.startswith("furniture:")  # a track of the environment model
    assert answer.search_report["rooms_searched"] == result.rooms_searched
    assert answer.composition_seconds < 1.0

"""Commands as people say them, in the executor: no room named, counted moves, turns, passing."""

from __future__ import annotations

import math

import pytest

from assistant.executor.spoken import amount_goal, passing_goal, room_from_here, said_side
from assistant.geometry import Pose2D
from assistant.grounding.types import GroundingPlan, RDTNode
from assistant.world import load_world


def plan_of(*pairs, target="table"):
    return GroundingPlan(nodes=[RDTNode(target, tuple(pairs))])


def test_the_side_said_picks_the_room_faced_from_the_hallway():
    world = load_world("apartment")  # start in the hallway: bedroom on the left, living room on the right
    start = world.start
    assert world.floorplan.room_at(start.x, start.y).name == "hallway"
    assert said_side(plan_of(("robot", "left"))) == "left"
    assert room_from_here(world, start, plan_of(("robot", "left"))) == "bedroom"
    assert room_from_here(world, start, plan_of(("robot", "right"))) == "living room"


def test_a_room_that_is_not_a_passage_is_where_the_command_is_carried_out():
    world = load_world("apartment")
    inside = Pose2D(4.0, 3.0, 0.0)
    room = world.floorplan.room_at(inside.x, inside.y).name
    assert room != "hallway"
    assert room_from_here(world, inside, plan_of(("chair", "beside"))) == room


def test_ahead_when_no_side_is_said():
    world = load_world("hk-studio")  # the studio is straight ahead of the start
    assert room_from_here(world, world.start, plan_of(("chair", "beside"))) == "studio"


def test_counted_moves_and_turns():
    pose = Pose2D(0.0, 0.0, 0.0)
    ahead = amount_goal(pose, "front", 1.2, None)
    assert (ahead.x, ahead.y, ahead.theta) == pytest.approx((1.2, 0.0, 0.0))
    side = amount_goal(pose, "left", 1.2, None)  # a side step keeps the heading
    assert (side.x, side.y, side.theta) == pytest.approx((0.0, 1.2, 0.0), abs=1e-9)
    turn = amount_goal(pose, "right", None, 90)
    assert (turn.x, turn.y, turn.theta) == pytest.approx((0.0, 0.0, -math.pi / 2))


def test_passing_goes_beyond_the_far_edge():
    goal = passing_goal(Pose2D(0.0, 0.0, 0.0), (2.0, 0.0), 2.0)
    assert goal.x == pytest.approx(2.0 + 1.0 + 0.6) and goal.y == pytest.approx(0.0)

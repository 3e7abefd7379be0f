"""The scripted teacher's rules."""

from __future__ import annotations

import math

import numpy as np
import pytest

from assistant.geometry import Pose2D, angle_difference
from assistant.policy.demonstration import environment_from_world
from assistant.policy.freespace import FreeSpace
from assistant.policy.rdt import TABLE_RDTS
from assistant.policy.teacher import NoInstanceError, sample_start, teacher_goal


@pytest.fixture(scope="module")
def home():
    from assistant.world import load_world

    env = environment_from_world(load_world("training-home"), "original")
    return env, FreeSpace(env)


def test_every_rdt_has_a_goal_in_the_training_home(home):
    env, free = home
    rng = np.random.default_rng(0)
    for rdt in TABLE_RDTS:
        start, goal = sample_start(rdt, env, free, rng)
        assert free.is_free(goal.goal.x, goal.goal.y, 0.25), rdt


def test_couch_front_table(home):
    env, free = home
    goal = teacher_goal("couch-front-table", env, Pose2D(5.8, 2.5, 1.57), free)
    assert (goal.reference_id, goal.target_id) == ("couch_1", "coffeetable_1")
    # in front of the couch (it faces -y at y = 4.45), beyond the coffee table, facing them
    assert goal.goal.y < 3.0 and abs(goal.goal.x - 2.2) < 0.3
    assert abs(angle_difference(goal.goal.theta, math.pi / 2)) < 0.1


def test_left_and_right_of_the_couch_are_its_own(home):
    env, free = home
    start = Pose2D(5.8, 2.5, 1.57)
    assert teacher_goal("couch-left-table", env, start, free).target_id == "roundtable_1"   # east
    assert teacher_goal("couch-right-table", env, start, free).target_id == "roundtable_2"  # west
    assert teacher_goal("bed-left-table", env, start, free).target_id == "roundtable_3"
    assert teacher_goal("bed-right-table", env, start, free).target_id == "coffeetable_2"


def test_robot_relative_moves(home):
    env, free = home
    start = Pose2D(2.5, 2.2, 0.0)
    front = teacher_goal("move-front-non", env, start, free).goal
    assert math.isclose(front.x, 3.5, abs_tol=1e-6) and math.isclose(front.y, 2.2, abs_tol=1e-6)
    left = teacher_goal("move-left-non", env, start, free).goal
    assert abs(angle_difference(left.theta, math.pi / 2)) < 1e-6 and 2.5 < left.y <= 2.7 and left.x == start.x
    left_table = teacher_goal("robot-left-table", env, Pose2D(4.5, 3.0, math.pi), free)
    assert left_table.target_id == "hexagontable_1"


def test_wall_and_room(home):
    env, free = home
    wall = teacher_goal("wall-front-non", env, Pose2D(2.5, 2.5, -math.pi / 2), free)
    assert wall.reference_id == "wall:0:living room"
    assert math.isclose(wall.goal.y, 0.7, abs_tol=0.05)
    centre = teacher_goal("room-center-non", env, Pose2D(9.0, 1.0, 0.0), free)
    assert centre.reference_id == "room:bedroom" and math.hypot(centre.goal.x - 9.35, centre.goal.y - 2.5) < 0.3
    with pytest.raises(NoInstanceError):
        teacher_goal("couch-behind-table", env, Pose2D(5.8, 2.5, 0.0), free)

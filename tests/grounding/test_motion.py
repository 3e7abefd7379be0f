"""Moves said to the robot itself: read into counted move and turn nodes, or left alone."""

from __future__ import annotations

import pytest

from assistant.grounding.motion import (DEFAULT_MOVE_M, DEFAULT_REVERSE_M, SMALL_MOVE_M, SMALL_TURN_DEG,
                                        describe_motion, is_motion_plan, read_motion, reverses)
from assistant.grounding.types import GroundingPlan, RDTNode


def moves(text: str):
    nodes = read_motion(text.replace(",", " , ").split())
    return None if nodes is None else [(str(n), n.distance_m, n.degrees) for n in nodes]


@pytest.mark.parametrize("text, expected", [
    ("turn left", [("move-left-non", None, 90.0)]),
    ("Turn right please", [("move-right-non", None, 90.0)]),
    ("turn around", [("move-left-non", None, 180.0)]),
    ("spin round", [("move-left-non", None, 180.0)]),
    ("turn back", [("move-left-non", None, 180.0)]),
    ("take a left", [("move-left-non", None, 90.0)]),
    ("make a right", [("move-right-non", None, 90.0)]),
    ("face right", [("move-right-non", None, 90.0)]),
    ("turn to your left", [("move-left-non", None, 90.0)]),
    ("turn left 45 degrees", [("move-left-non", None, 45.0)]),
    ("rotate 90 degrees to the right", [("move-right-non", None, 90.0)]),
    ("turn slightly to the right", [("move-right-non", None, SMALL_TURN_DEG)]),
    ("go forward", [("move-front-non", DEFAULT_MOVE_M, None)]),
    ("keep going", [("move-front-non", DEFAULT_MOVE_M, None)]),
    ("move forward a little bit", [("move-front-non", SMALL_MOVE_M, None)]),
    ("go straight ahead for about 3 meters", [("move-front-non", 3.0, None)]),
    ("go forward about 5 feet", [("move-front-non", pytest.approx(1.524), None)]),
    ("take two steps forward", [("move-front-non", pytest.approx(1.2), None)]),
    ("back up", [("move-back-non", DEFAULT_REVERSE_M, None)]),
    ("back up a little", [("move-back-non", SMALL_MOVE_M, None)]),
    ("reverse a bit", [("move-back-non", SMALL_MOVE_M, None)]),
    ("move back one meter", [("move-back-non", 1.0, None)]),
    ("take two steps left", [("move-left-non", pytest.approx(1.2), None)]),
    ("move left a bit", [("move-left-non", SMALL_MOVE_M, None)]),
    ("go forward two meters and then turn right",
     [("move-front-non", 2.0, None), ("move-right-non", None, 90.0)]),
    ("okay robot, turn left, then go forward", [("move-left-non", None, 90.0), ("move-front-non", 1.0, None)]),
    ("um turn around and uh back up a bit", [("move-left-non", None, 180.0), ("move-back-non", 0.5, None)]),
])
def test_moves_said_to_the_robot_are_read(text, expected):
    assert moves(text) == expected


@pytest.mark.parametrize("text", [
    "turn left at the door",                      # a landmark: the grounders' business
    "turn left into the bedroom",
    "turn right and go to the couch",
    "the mug is on the table to your left",
    "take two steps forward and the keys are on the table to your left",
    "come back",                                  # to the person, not a move back
    "come here",
    "turn",                                       # no direction
    "go",
    "stop",
    "look around",
    "",
])
def test_anything_else_is_left_to_the_grounders(text):
    assert moves(text) is None


def test_the_reply_says_what_the_robot_does_and_did():
    nodes = read_motion("turn around then go forward 2 meters and back up".split())
    assert describe_motion(nodes) == "turning around, then moving forward 2 m, then backing up 0.5 m"
    assert describe_motion(nodes, done=True) == "turned around, then moved forward 2 m, then backed up 0.5 m"
    assert describe_motion(read_motion("turn right 45 degrees".split())) == "turning right 45°"
    assert describe_motion(read_motion("take three steps back".split())) == "turning around and moving 1.8 m"


def test_only_short_moves_back_reverse():
    assert reverses(RDTNode("non", (("move", "back"),), distance_m=0.5))
    assert not reverses(RDTNode("non", (("move", "back"),), distance_m=2.0))  # turns round and drives
    assert not reverses(RDTNode("non", (("move", "front"),), distance_m=0.5))


def test_a_motion_plan_has_nothing_but_counted_moves():
    turn = RDTNode("non", (("move", "left"),), degrees=90.0)
    assert is_motion_plan(GroundingPlan(nodes=[turn], kind="dynamic"))
    assert not is_motion_plan(GroundingPlan(room="bedroom", nodes=[turn]))
    assert not is_motion_plan(GroundingPlan(nodes=[turn], object="mug"))
    assert not is_motion_plan(GroundingPlan(nodes=[RDTNode("non", (("move", "front"),))]))  # no amount
    assert not is_motion_plan(GroundingPlan(nodes=[turn, RDTNode("table", (("couch", "front"),))]))
    assert not is_motion_plan(GroundingPlan())


@pytest.mark.parametrize("words, metres", [
    ("go half a meter forward", 0.5), ("two and a half meters ahead", 2.5), ("drive 1.5 m", 1.5),
    ("move forward 50 cm", 0.5), ("walk 3 meters", 3.0), ("go 1.5m ahead", 1.5),
    ("go straight down the hallway about 5 metres then stop", 5.0),
])
def test_distances_as_people_write_them(words, metres):
    """"half a meter" had been 1 m, "2 m" an object called "m", "walk 3 meters" no move."""
    (node,) = read_motion(words.split())
    assert node.pairs == (("move", "front"),) and node.distance_m == pytest.approx(metres)


def test_a_hallway_without_a_distance_is_left_to_the_grounders():
    assert read_motion("go down the hall".split()) is None

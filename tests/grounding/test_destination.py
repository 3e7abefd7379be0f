"""A piece of furniture said as the place to go."""

from __future__ import annotations

import pytest

from assistant.grounding.destination import said_destination

ROOMS = ["living room", "bedroom", "office"]


@pytest.mark.parametrize("text, rdt, support, descriptors", [
    ("go to the couch", "room-center-couch", "couch", ()),
    ("Go to the sofa please", "room-center-couch", "couch", ()),
    ("walk over to the desk in the office", "room-center-table", "desk", ()),
    ("take me to the coffee table", "room-center-table", "table", ("coffee",)),
    ("could you go to the little round table", "room-center-table", "table", ("small", "round")),
    ("go back to the bed", "room-center-bed", "bed", ()),
])
def test_furniture_said_as_the_place_to_go(text, rdt, support, descriptors):
    node = said_destination(text.split(), ROOMS)
    assert node is not None and str(node) == rdt and node.support == support and node.descriptors == descriptors


@pytest.mark.parametrize("text", [
    "go to the table to the right of the bed",   # a reference: the grounders read it
    "go to the mug",                               # not furniture
    "go to the living room",
    "the mug is on the couch",
    "go to the couch and turn left",
])
def test_anything_else_is_left_to_the_grounders(text):
    assert said_destination(text.split(), ROOMS) is None

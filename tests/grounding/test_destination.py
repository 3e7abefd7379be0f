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
    # told by another piece or a wall, as the chat's questions offer them
    ("go to the couch by the table in the living room", "table-beside-couch", "couch", ()),
    ("go to the table to the right of the bed", "bed-right-table", "table", ()),
    ("could you go to the chair that is near the bed", "bed-beside-chair", "chair", ()),
    ("go to the couch against the left wall", "wall-left-couch", "couch", ()),
    ("walk over to the sofa in front of the tv stand", None, None, None),
    ("go to the round table behind the sofa", "couch-back-table", "table", ("round",)),
])
def test_furniture_said_as_the_place_to_go(text, rdt, support, descriptors):
    node = said_destination(text.split(), ROOMS)
    if rdt is None:  # a landmark it does not know ("tv stand"): the grounders read it
        assert node is None
        return
    assert node is not None and str(node) == rdt and node.support == support and node.descriptors == descriptors


@pytest.mark.parametrize("text", [
    "go to the table to the right of the table",  # itself as its landmark
    "go to the couch by the mug",                  # a thing, not furniture, as the landmark
    "go to the mug",                               # not furniture
    "go to the living room",
    "the mug is on the couch",
    "go to the couch and turn left",
])
def test_anything_else_is_left_to_the_grounders(text):
    assert said_destination(text.split(), ROOMS) is None


@pytest.mark.parametrize("text, rdt", [
    ("go to the couch by the table", "table-beside-couch"),        # the grounders read the table
    ("go to the couch next to the table", "table-beside-couch"),
    ("go to the couch", "room-center-couch"),
    ("go to the table by the couch", "couch-beside-table"),
])
def test_the_parser_goes_to_the_furniture_said_first(text, rdt):
    from assistant.grounding.parser import CommandParser
    from assistant.world import load_world

    plan = CommandParser.load(world=load_world("two-bedrooms-house")).parse(text).plan
    assert [str(n) for n in plan.nodes] == [rdt] and plan.object is None

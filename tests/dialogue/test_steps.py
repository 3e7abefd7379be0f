"""Errands of several steps: each part sends the robot to another room."""

from __future__ import annotations

import re

import pytest

from assistant.dialogue.steps import split_steps

ROOMS = ("living room", "bedroom", "hallway", "inner hall", "small room")


def room_of(part: str):
    named = [r for r in ROOMS if re.search(rf"\b{r}\b", part)]
    return named[-1] if named else None


@pytest.mark.parametrize("text, steps", [
    ("go to the living room then go to the bedroom", ["go to the living room", "go to the bedroom"]),
    ("go to the living room, then after that go to the bedroom", ["go to the living room", "go to the bedroom"]),
    ("go to the bedroom. after that, come back to the hallway", ["go to the bedroom", "come back to the hallway"]),
    ("go to the bedroom and then the living room", ["go to the bedroom", "go to the living room"]),
    ("go through the living room into the inner hall then into the small room",
     ["go through the living room into the inner hall", "go into the small room"]),
    # numbered steps, a capital "Then": the numbering words are not said back
    ("First, go to the end of the living room. Then go through the door into the inner hall. Finally take the "
     "door straight ahead into the small room", ["go to the end of the living room",
                                                 "go through the door into the inner hall",
                                                 "take the door straight ahead into the small room"]),
    ("step 1 go to the bedroom. step 2 go to the living room", ["go to the bedroom", "go to the living room"]),
])
def test_an_errand_is_split_into_its_steps(text, steps):
    assert split_steps(text, room_of) == steps


@pytest.mark.parametrize("text", [
    "go out the door, turn left, then go into the living room",      # a route to one room
    "go to the bedroom, then turn right, the mug is on the table",
    "go to the table next to the couch in the bedroom",
    "go to the bedroom then stay in the bedroom",                      # the same room twice
    "go to the living room",
])
def test_one_command_stays_one(text):
    assert split_steps(text, room_of) == [text]


def test_steps_to_furniture_and_what_is_said_of_them():
    from assistant.dialogue.steps import step_place

    furniture_rooms = {"bed": "bedroom", "dinner table": "living room"}

    def room_or_furniture(part):
        return room_of(part) or next((r for f, r in furniture_rooms.items() if f in part), None)

    assert split_steps("go to the dinner table and then to the bed", room_or_furniture) == \
        ["go to the dinner table", "go to the bed"]
    assert split_steps("go to the living room, then to the dinner table, then to the bed", room_or_furniture) == \
        ["go to the living room", "go to the dinner table", "go to the bed"]
    assert step_place("go to the bed") == "the bed" and step_place("come back to the hallway") == "the hallway"
    assert step_place("turn left") == "turn left"

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
     ["go through the living room into the inner hall", "into the small room"]),
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

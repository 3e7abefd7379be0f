"""Questions about the home's furniture: read, and answered from the furniture the robot knows."""

from __future__ import annotations

from dataclasses import dataclass

import pytest

from assistant.dialogue.intents import classify
from assistant.dialogue.inventory import furniture_answer, furniture_asked


@dataclass(frozen=True)
class Piece:
    model: str
    word: str
    room: str


HOME = [Piece("bed", "bed", "bedroom"), Piece("round table", "table", "bedroom"),
        Piece("round table", "table", "living room"), Piece("coffee table", "table", "living room"),
        Piece("couch", "couch", "living room"), Piece("blue chair", "chair", "living room"),
        Piece("wood chair", "chair", "living room")]
ROOMS = ["hallway", "living room", "bedroom"]


@pytest.mark.parametrize("said, kind, what", [
    ("What's in the bedroom?", "list", ""),
    ("what furniture is in the living room", "list", ""),
    ("is there anything in the hallway", "list", "anything"),
    ("Is there a couch in the living room?", "yes_no", "couch"),
    ("are there any tables in the hallway", "yes_no", "tables"),
    ("is there a sofa here", "yes_no", "sofa"),
    ("how many chairs are there in the living room", "count", "chairs"),
    ("How many beds do we have?", "count", "beds"),
])
def test_furniture_questions_are_read(said, kind, what):
    intent = classify(said)
    assert intent.name == "furniture" and furniture_asked(intent.text) == (kind, what)


@pytest.mark.parametrize("said", ["where is my mug", "bring me the mug from the table in the bedroom",
                                  "what is the time", "go to the living room", "is it in the bedroom"])
def test_other_turns_are_not_furniture_questions(said):
    assert classify(said).name != "furniture"


@pytest.mark.parametrize("kind, what, room, reply", [
    ("list", "", "bedroom", "In the bedroom I know of a bed and a round table."),
    ("list", "", "hallway", "I don't know of any furniture in the hallway."),
    ("list", "", None, "In the living room I know of a round table, a coffee table, a couch"),
    ("yes_no", "couch", "living room", "Yes — there is a couch in the living room."),
    ("yes_no", "sofa", None, "Yes — there is a couch here."),
    ("yes_no", "tables", "hallway",
     "No — I don't know of any table in the hallway. There are some in the living room and the bedroom."),
    ("yes_no", "desk", "living room",
     "I don't know of a desk in the living room, but there are a round table and a coffee table."),
    ("count", "chairs", "living room", "There are two chairs in the living room: a blue chair and a wood chair."),
    ("count", "beds", None, "There is just one bed here."),
    ("count", "couches", "bedroom", "No — I don't know of any couches in the bedroom. There is one in the living room."),
])
def test_answers_come_from_the_furniture_known(kind, what, room, reply):
    answer = furniture_answer(HOME, ROOMS, kind, what, room)
    assert answer.startswith(reply) if room is None and kind == "list" else answer == reply

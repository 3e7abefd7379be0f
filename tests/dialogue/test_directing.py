"""Directing the robot the way people do (the 3 Dec evening tester's findings): answers to its
room question that name no room, "not X, Y", corrections while it drives, "it" for the piece of
furniture just visited, "check the couch", "… then come back", and what it saw at a piece."""

import sys
from pathlib import Path

import pytest

from assistant.dialogue import DialogueManager, ObjectMemory
from assistant.dialogue.intents import classify

sys.path.insert(0, str(Path(__file__).parent))
from standins import RecordingFetcher  # noqa: E402


def make(services, tmp_path, fetcher=None):
    fetcher = fetcher or RecordingFetcher()
    m = DialogueManager("apartment", services=services.using(fetcher=fetcher), memory=ObjectMemory(tmp_path / "m.json"))
    m.fetcher = fetcher
    return m


def test_the_room_question_answered_by_pointing_is_no_turn(services, tmp_path):
    m = make(services, tmp_path)
    assert m.handle("go to the table").reply.startswith("Which room is the table in")
    left = m.handle("the left one")
    assert left.action == "clarify" and "Left or right as seen from where?" in left.reply and m.fetcher.texts == []
    kind = m.handle("the round one")
    assert kind.reply.startswith("Which room is the round table in") and m.fetcher.texts == []


def test_the_room_question_answered_with_you_choose_takes_the_nearest(services, tmp_path):
    m = make(services, tmp_path)
    m.handle("go to the table")
    turn = m.handle("you choose")
    m.wait(10)
    assert turn.reply.startswith("I'll take the nearest, the round table in the living room.")
    assert m.fetcher.texts == ["go to the round table in the living room"]


def test_not_one_place_but_another(services, tmp_path):
    m = make(services, tmp_path)
    turn = m.handle("not the bedroom, the living room")
    m.wait(10)
    assert turn.reply == "Going to the living room." and m.fetcher.texts == ["the living room"]


def test_a_correction_while_driving_goes_there_at_once(services, tmp_path):
    m = make(services, tmp_path, RecordingFetcher(hold=True))
    m.handle("go to the bedroom")
    assert m.busy
    turn = m.handle("no no the living room")
    assert turn.action == "fetch" and turn.reply == "Going to the living room."
    m.wait(10)
    assert m.fetcher.texts[-1] == "no no the living room" and len(m.fetcher.texts) == 2
    m.close()


def test_wrong_room_stops_and_asks(services, tmp_path):
    m = make(services, tmp_path, RecordingFetcher(hold=True))
    m.handle("go to the bedroom")
    turn = m.handle("wrong room")
    assert turn.reply.startswith("Sorry — which room then:") and turn.action == "clarify"
    m.wait(10)
    assert not m.busy
    m.close()


def test_it_is_the_piece_just_visited(services, tmp_path):
    m = make(services, tmp_path)  # the stand-in ends every fetch at the couch
    m.handle("go to the couch")
    m.wait(10)
    m.handle("now go to the table in front of it")
    m.wait(10)
    assert m.fetcher.texts[-1] == "now go to the table in front of the couch in the living room"


def test_anything_on_it_after_a_visit(services, tmp_path):
    m = make(services, tmp_path, RecordingFetcher(furniture="coffeetable_1"))
    m.handle("go to the coffee table in the living room")
    m.wait(10)
    m.memory.remember("apartment", "glasses case", "living room", "coffeetable_1", "table", "on the coffee table")
    turn = m.handle("is there anything on it?")
    assert turn.intent == "on_furniture" and "glasses case" in turn.reply


def test_check_a_piece_of_furniture_and_come_back(services, tmp_path):
    m = make(services, tmp_path)
    assert m.handle("check the couch").action == "fetch"
    m.wait(10)
    assert m.fetcher.texts == ["go to the couch in the living room"]
    errand = m.handle("first check the couch, then come back")
    assert errand.reply == "Going to the living room. After that, the hallway."
    m.close()


def test_what_lies_on_the_piece_reached_is_said():
    from assistant.dialogue.replies import _things_on

    class Piece:
        id, x, y = "coffeetable_1", 4.5, 4.0

    summary = {"places": {"glasses case": {"furniture": "furniture:9", "x_m": 4.51, "y_m": 3.99},
                          "mug": {"furniture": "furniture:3", "x_m": -1.2, "y_m": -5.0},
                          "remote": {"furniture": "coffeetable_1", "x_m": None, "y_m": None}}}
    assert _things_on(summary, Piece(), {}) == ["glasses case", "remote"]


@pytest.mark.parametrize("said, intent", [("bring me a glass of water", "out_of_scope"),
                                          ("could you get me something to drink", "out_of_scope")])
def test_drinks_are_not_things_to_find(said, intent):
    assert classify(said).name == intent


def test_a_misspelt_thing_is_nobodys():
    from assistant.dialogue.clarify import owner_phrase

    assert owner_phrase("where is my glases case") is None and owner_phrase("where is marys keys") == "Mary's"

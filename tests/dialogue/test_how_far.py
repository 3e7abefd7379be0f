"""How far a place is from the robot: the question's shapes, the distance along the floor, and
the conversation around it ("is it far?", "which is closer …?", "shall I go there?")."""

import math
import sys
from pathlib import Path

import pytest

from assistant.dialogue import DialogueManager, ObjectMemory
from assistant.dialogue.distances import floor_distance_m, how_far_question, spoken_distance
from assistant.dialogue.intents import classify

sys.path.insert(0, str(Path(__file__).parent))
from standins import RecordingFetcher  # noqa: E402


@pytest.mark.parametrize("said, places", [
    ("how far is the bedroom from here?", ("the bedroom",)),
    ("How far away is my mug", ("my mug",)),
    ("um how far is it to the living room", ("the living room",)),
    ("how far do I have to walk to get to the couch", ("the couch",)),
    ("how many steps to the hallway", ("the hallway",)),
    ("is the bed far?", ("the bed",)),
    ("are my keys far away", ("my keys",)),
    ("is it far from here", ("it",)),
    ("how far are you from the dinner table", ("the dinner table",)),
    ("how far is that", ("that",)),
    ("which is closer, the couch or the bed?", ("the couch", "the bed")),
])
def test_how_far_questions_are_read(said, places):
    assert classify(said).name == "how_far"
    assert how_far_question(classify(said).text).places == places


@pytest.mark.parametrize("said", ["is my mug near the bed?", "how do I get to the bedroom?",
                                  "go far into the bedroom", "the bed is far too soft", "where is the couch"])
def test_other_sentences_are_not_distance_questions(said):
    assert classify(said).name != "how_far"


def test_further_asks_for_the_further_one():
    assert how_far_question("which is further the couch or the bed").nearer is False
    assert how_far_question("which one is nearer to you the bed or the couch").nearer is True


def test_distances_are_said_as_people_say_them():
    assert [spoken_distance(d) for d in (0.3, 1.2, 3.6, 11.4)] == [
        "less than a metre", "about a metre", "about 4 metres", "about 11 metres"]


@pytest.fixture
def manager(services, tmp_path):
    fetcher = RecordingFetcher()
    m = DialogueManager("apartment", services=services.using(fetcher=fetcher),
                        memory=ObjectMemory(tmp_path / "memory.json"))
    m.fetcher = fetcher
    return m


def test_a_room_is_as_far_as_the_route_there_and_the_robot_offers_to_go(manager):
    turn = manager.handle("how far is the bedroom?")
    start = (manager.world.start.x, manager.world.start.y)
    centre = manager.world.floorplan.room("bedroom").centre
    along_floor, found = floor_distance_m(manager._walls_map, start, centre)
    assert found and along_floor >= math.dist(start, centre) - 1e-6  # round the walls, never through them
    assert turn.intent == "how_far" and turn.data["distance_m"] == pytest.approx(along_floor, abs=0.01)
    assert f"{spoken_distance(along_floor)} from me" in turn.reply and turn.reply.endswith("Shall I go there?")
    manager.handle("yes")
    manager.wait(10)
    assert manager.fetcher.texts == ["go to the bedroom"]


def test_the_room_the_robot_is_in(manager):
    here = manager.robot_room()[0]
    assert manager.handle(f"how far is the {here}").reply == f"I'm in the {here} now."


def test_a_comparison_names_the_nearer_place_first(manager):
    start = (manager.world.start.x, manager.world.start.y)
    furniture = {f.model: f for f in manager.world.scene("original").furniture}
    d = {name: floor_distance_m(manager._walls_map, start, (furniture[name].x, furniture[name].y))[0]
         for name in ("couch", "dinner table")}
    nearer, further = sorted(d, key=d.get)
    turn = manager.handle(f"which is closer, the {further} or the {nearer}?")
    if abs(d[nearer] - d[further]) >= 1.0:
        assert turn.reply.startswith(f"The {nearer} is closer")
    assert turn.data["distances_m"] == [pytest.approx(d[further], abs=0.01), pytest.approx(d[nearer], abs=0.01)]
    assert manager.handle(f"which is further, the {nearer} or the {further}?").reply.startswith(
        f"The {further} is further") or abs(d[nearer] - d[further]) < 1.0


def test_it_is_the_place_just_asked_about(manager):
    first = manager.handle("how far is the table")
    assert "nearest of the six tables" in first.reply
    again = manager.handle("is it far?")
    assert again.data["distance_m"] == first.data["distance_m"] and again.data["place"] == first.data["place"]


def test_a_table_in_a_named_room(manager):
    turn = manager.handle("how far is the table in the bedroom")
    assert turn.data["room"] == "bedroom" and "in the bedroom" in turn.reply


def test_a_thing_where_the_robot_saw_it_and_one_it_does_not_know_the_place_of(manager):
    manager.memory.remember("apartment", "mug", "bedroom", None, "table", "on the table by the bed",
                            x_m=manager.world.floorplan.room("bedroom").centre[0],
                            y_m=manager.world.floorplan.room("bedroom").centre[1])
    turn = manager.handle("how far away is my mug?")
    assert turn.data["object"] == "mug" and "Your mug is about" in turn.reply and "in the bedroom" in turn.reply
    keys = manager.handle("are my keys far away?")  # not seen, not told; the search is the robot's own
    assert keys.outcome == "not_understood" and "I don't know where your keys are yet" in keys.reply


def test_a_room_the_home_does_not_have(manager):
    assert manager.handle("how far is the kitchen").reply.startswith("There is no kitchen here")


def test_how_far_one_place_is_from_another(manager):
    assert how_far_question("how far is the couch from the bed").origin == "the bed"
    assert how_far_question("how far is the couch from here").origin is None
    furniture = {f.model: f for f in manager.world.scene("original").furniture}
    couch, bed = furniture["couch"], furniture["bed"]
    metres, _ = floor_distance_m(manager._walls_map, (bed.x, bed.y), (couch.x, couch.y))
    turn = manager.handle("how far is the couch from the bed?")
    assert turn.reply == f"The couch is {spoken_distance(metres)} from the bed." and manager.pending is None

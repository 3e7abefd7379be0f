"""Object memory of everything seen during a task: the recorder on its own (real sightings
placed by the executor's function, the real describer), then through the manager with
stand-in tasks that report ``objects_seen`` events the way the fetch and the search do."""

import json
import sys
import time
from pathlib import Path

import pytest

from assistant.dialogue import DialogueManager, ObjectMemory, Services
from assistant.dialogue.seen import SeenRecorder
from assistant.executor.sightings import place_sightings
from assistant.geometry import Pose2D
from assistant.perception.objects import Sighting
from assistant.world import furniture_entities, load_world, world_grid

sys.path.insert(0, str(Path(__file__).parent))
from standins import fetch_result  # noqa: E402  (the dialogue tests' shared stand-in)


@pytest.fixture(scope="module")
def apartment_world():
    return load_world("apartment")


@pytest.fixture(scope="module")
def furniture(apartment_world):
    return furniture_entities(apartment_world, "original", world_grid(apartment_world, 0.05))


@pytest.fixture(scope="module")
def services(apartment_world):
    s = Services(perception="oracle")
    s.warm_up(apartment_world, background=False)
    return s


def placed(world, furniture, name, x, y, z=0.6):
    return place_sightings(world, furniture, [Sighting(name, x, y, z, 2.0, 400, 1.0)])[0]


def test_first_sighting_is_written_at_once_and_finish_composes_the_phrase(tmp_path, apartment_world, furniture,
                                                                         services):
    path = tmp_path / "memory.json"
    memory = ObjectMemory(path)
    rec = SeenRecorder(memory, "apartment", source="fetch")
    fork = placed(apartment_world, furniture, "fork", 4.0, 2.0)
    assert rec.on_event("objects_seen", {"seen": [fork], "pose": Pose2D(2.0, 2.0, 0.0)}) == ["fork"]
    on_disk = json.loads(path.read_text())["sightings"][0]
    assert (on_disk["object"], on_disk["room"], on_disk["furniture"], on_disk["phrase"]) == \
        ("fork", "living room", "roundtable_1", "on the table")
    assert rec.on_event("objects_seen", {"seen": [fork], "pose": Pose2D(2.0, 2.0, 0.0)}) == []
    summary = rec.finish(furniture, services.describer, apartment_world.floorplan)
    assert summary["seen"] == ["fork"] and summary["moved"] == []
    again = ObjectMemory(path).recall("apartment", "fork")  # reloaded from the file
    assert again.phrase.startswith("on the table ") and len(again.phrase) > len("on the table ")
    assert again.source == "fetch" and abs(again.x_m - 4.0) < 1e-6


def test_an_object_seen_elsewhere_counts_as_moved(tmp_path, apartment_world, furniture):
    memory = ObjectMemory(tmp_path / "m.json")
    memory.remember("apartment", "mug", "living room", "coffeetable_1", "table", "on the table", x_m=4.5, y_m=4.0)
    rec = SeenRecorder(memory, "apartment", source="search")
    rec.add([placed(apartment_world, furniture, "mug", -1.2, -5.0)])
    assert memory.recall("apartment", "mug").room == "bedroom"  # written at once
    summary = rec.finish(None)
    assert summary["moved"] == ["mug"] and memory.recall("apartment", "mug").source == "search"


def test_version_1_memory_files_still_load(tmp_path):
    path = tmp_path / "old.json"
    path.write_text(json.dumps({"version": 1, "sightings": [
        {"object": "mug", "world": "apartment", "room": "bedroom", "furniture": "hexagontable_1",
         "furniture_word": "table", "phrase": "on the table", "time_s": 5.0, "source": "fetch"}]}))
    memory = ObjectMemory(path)
    assert memory.load_problem is None and memory.recall("apartment", "mug").x_m is None


class SeeingFetcher:
    """Reports ``objects_seen`` on the way (real placed sightings) and ends with a chosen result."""

    def __init__(self, world, furniture, seen_on_way, target_in_view, target_furniture):
        self.world, self.furniture = world, furniture
        self.seen_on_way, self.target_in_view, self.target_furniture = seen_on_way, target_in_view, target_furniture
        self.texts = []

    def __call__(self, text, world, scene, on_event):
        self.texts.append(text)
        for name, x, y in self.seen_on_way:
            on_event("objects_seen", {"seen": [placed(self.world, self.furniture, name, x, y)],
                                      "pose": Pose2D(0.0, 0.0, 0.0)})
        return fetch_result(self.target_in_view, self.target_furniture, perceived=self.furniture)


class StandInSearcher:
    """Returns a real SearchResult for a found or missing object after reporting sightings."""

    def __init__(self, world, furniture, where=None, rooms=("hallway", "living room", "bedroom")):
        self.world, self.furniture, self.where, self.rooms = world, furniture, where, list(rooms)
        self.names = []

    def __call__(self, name, world, scene, on_event):
        import dataclasses

        from assistant.executor.outcome import ExecutionStatus
        from assistant.executor.search import SearchResult

        self.names.append(name)
        for room in self.rooms:
            on_event("search_room", {"room": room})
        if self.where is None:
            return SearchResult(name, False, ExecutionStatus.NOT_FOUND, "not seen", furniture=self.furniture,
                                rooms_searched=self.rooms)
        p = placed(self.world, self.furniture, name, *self.where)
        on_event("objects_seen", {"seen": [p], "pose": Pose2D(0.0, -5.0, 0.0)})
        return SearchResult(name, True, ExecutionStatus.SUCCESS, "seen",
                            dataclasses.replace(p, seen_from=Pose2D(0.0, -5.0, 0.0)), self.furniture,
                            rooms_searched=self.rooms, wall_seconds=0.1)


def manager(services, tmp_path, fetcher=None, searcher=None, said=None):
    services = services.using(fetcher=fetcher, searcher=searcher)
    services.search_mode = "sensed"
    return DialogueManager("apartment", services=services, memory=ObjectMemory(tmp_path / "memory.json"),
                           say=(said.append if said is not None else None))


def test_objects_seen_during_a_fetch_answer_where_later(services, tmp_path, apartment_world, furniture):
    fetcher = SeeingFetcher(apartment_world, furniture, [("fork", 4.0, 2.0), ("laptop", 4.5, 7.0)], True,
                            "dinnertable_1")
    m = manager(services, tmp_path, fetcher)
    m.handle("bring me the laptop from the table against the left wall in the living room")
    final = m.wait(10)
    assert final.outcome == "success" and "fork" in final.data["seen"]
    turn = m.handle("where is my fork?")
    assert turn.data["source"] == "memory" and turn.reply.startswith("I saw your fork just now on the table")
    assert "living room" in turn.reply and turn.reply.endswith("Shall I go and check?")
    go = m.handle("yes")
    assert go.action == "fetch" and go.reply == "Going to the living room." and "fork" in go.data["command"]
    m.wait(10)


def test_never_seen_object_is_searched_for_and_remembered(services, tmp_path, apartment_world, furniture):
    said = []
    searcher = StandInSearcher(apartment_world, furniture, where=(-1.2, -5.0))
    m = manager(services, tmp_path, searcher=searcher, said=said)
    turn = m.handle("where is my mug")
    assert (turn.action, turn.outcome) == ("search", "started") and "look for it" in turn.reply
    final = m.wait(10)
    assert final.outcome == "success" and final.reply.startswith("Found it: the mug is")
    assert "bedroom" in final.reply and "Looking in the bedroom." in said
    assert m.memory.recall("apartment", "mug").room == "bedroom"
    again = m.handle("where is my mug")
    assert again.data["source"] == "memory"


def test_search_that_finds_nothing_says_where_it_looked(services, tmp_path, apartment_world, furniture):
    m = manager(services, tmp_path, searcher=StandInSearcher(apartment_world, furniture, where=None))
    m.handle("have you seen my statue?")
    final = m.wait(10)
    assert final.outcome == "failed"
    assert final.reply == "I looked in the hallway, the living room and the bedroom and did not find a statue."


def test_stale_memory_is_forgotten_and_a_search_offered(services, tmp_path, apartment_world, furniture):
    fetcher = SeeingFetcher(apartment_world, furniture, [], False, "coffeetable_1")
    searcher = StandInSearcher(apartment_world, furniture, where=(-1.2, -5.0))
    m = manager(services, tmp_path, fetcher, searcher)
    m.memory.remember("apartment", "mug", "living room", "coffeetable_1", "table", "on the table",
                      time_s=time.time() - 1800, x_m=4.5, y_m=4.0)
    reply = m.handle("where is my mug").reply
    # made before this memory was opened: said as from an earlier session (calendar words)
    assert "earlier today" in reply or "yesterday" in reply, reply
    m.handle("yes")
    final = m.wait(10)
    assert final.outcome == "failed" and "Shall I look for it?" in final.reply
    assert m.memory.recall("apartment", "mug") is None
    look = m.handle("yes")
    assert look.action == "search" and look.outcome == "started"
    assert m.wait(10).outcome == "success" and m.memory.recall("apartment", "mug").room == "bedroom"


def test_target_seen_elsewhere_on_the_way_updates_memory(services, tmp_path, apartment_world, furniture):
    fetcher = SeeingFetcher(apartment_world, furniture, [("mug", -1.2, -5.0)], False, "coffeetable_1")
    m = manager(services, tmp_path, fetcher)
    m.memory.remember("apartment", "mug", "living room", "coffeetable_1", "table", "on the table", x_m=4.5, y_m=4.0)
    m.handle("bring me the mug from the table in front of the couch in the living room")
    final = m.wait(10)
    assert final.outcome == "failed" and "I did see it on the table" in final.reply and "bedroom" in final.reply
    assert m.memory.recall("apartment", "mug").room == "bedroom"


def test_furniture_words_named_back_or_picked(services, tmp_path, apartment_world):
    from assistant.dialogue.clarify import distinct_phrases, furniture_mentions

    found = furniture_mentions("the mug from the dresser by the hexagon table".split(),
                               "DT NN IN DT FUR IN DT NN FUR".split(), apartment_world, "original")
    assert [(m.said, m.category, m.here, m.models) for m in found] == [
        ("dresser", "table", False, ()), ("hexagon table", "table", True, ("hexagon table",))]
    chairs = [f for f in apartment_world.scene("original").furniture if f.word == "chair" and f.room == "living room"]
    phrases = distinct_phrases(apartment_world, "original", chairs)
    assert len(set(phrases)) == len(chairs)
    m = manager(services, tmp_path, SeeingFetcher(apartment_world, [], [], True, "hexagontable_1"))
    ask = m.handle("bring me the mug from the dresser in the bedroom")
    assert ask.reply == "I don't know which of the furniture here is the dresser — is it a table?"
    which = m.handle("yes")
    assert which.reply.startswith("There are three tables in the bedroom")
    assert m.handle("the one by the chair").data["chosen"] == "hexagontable_1"
    m.wait(10)
    direct = m.handle("bring me the mug from the hexagon table in the bedroom")
    assert direct.action == "fetch" and direct.data["chosen"] == "hexagontable_1"
    m.wait(10)

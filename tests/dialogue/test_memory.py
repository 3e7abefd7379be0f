import json

import pytest

from assistant.dialogue.memory import ObjectMemory, age_phrase


def test_remember_save_and_reload(tmp_path):
    path = tmp_path / "sub" / "memory.json"
    clock = [1000.0]
    memory = ObjectMemory(path, clock=lambda: clock[0])
    memory.remember("apartment", "mug", "bedroom", "hexagontable_1", "table", "on the table by the chair")
    assert path.exists()
    clock[0] += 180
    again = ObjectMemory(path, clock=lambda: clock[0])
    seen = again.recall("apartment", "mug")
    assert seen.room == "bedroom" and seen.furniture == "hexagontable_1"
    assert again.age(seen) == "3 minutes ago"
    assert again.recall("hk-studio", "mug") is None  # homes are kept apart
    again.forget("apartment", "mug")
    assert ObjectMemory(path).recall("apartment", "mug") is None
    assert not list(path.parent.glob(".*.tmp"))  # atomic write leaves no temporary file


def test_newer_sighting_replaces_older(tmp_path):
    memory = ObjectMemory(tmp_path / "m.json")
    memory.remember("apartment", "mug", "living room", "coffeetable_1", time_s=1)
    memory.remember("apartment", "mug", "bedroom", "hexagontable_1", time_s=2)
    assert [s.room for s in memory.sightings("apartment")] == ["bedroom"]


def test_corrupt_file_is_reported_not_fatal(tmp_path):
    path = tmp_path / "memory.json"
    path.write_text("{not json")
    memory = ObjectMemory(path)
    assert memory.recall("apartment", "mug") is None
    assert "memory.json" in memory.load_problem
    path.write_text(json.dumps({"version": 1, "sightings": [{"object": "mug", "bogus": 1}]}))
    assert "sightings[0]" in ObjectMemory(path).load_problem


def test_age_phrase():
    assert age_phrase(10) == "just now"
    assert age_phrase(60) == "a minute ago"
    assert age_phrase(7200) == "2 hours ago"
    assert age_phrase(86400) == "yesterday"
    assert age_phrase(3 * 86400) == "3 days ago"


@pytest.mark.parametrize("content", [
    {"version": 2, "sightings": None},
    {"version": 2, "sightings": [{"object": "mug", "world": "apartment", "room": "bedroom", "x_m": "left"}]},
])
def test_a_malformed_memory_file_is_kept_aside_not_overwritten(tmp_path, content):
    path = tmp_path / "memory.json"
    path.write_text(json.dumps(content))
    memory = ObjectMemory(path)
    assert memory.load_problem and "empty memory" in memory.load_problem
    kept = list(tmp_path.glob("memory.json.unreadable-*"))
    assert len(kept) == 1 and json.loads(kept[0].read_text()) == content
    assert str(kept[0]) in memory.load_problem
    memory.remember("apartment", "fork", "living room", time_s=1)  # the new memory saves beside it
    assert json.loads(kept[0].read_text()) == content
    assert ObjectMemory(path).recall("apartment", "fork") is not None

import datetime
import json
import stat
import subprocess
import sys
import time

import pytest

from assistant.dialogue.memory import ObjectMemory, age_phrase


def test_remember_save_and_reload(tmp_path):
    path = tmp_path / "sub" / "memory.json"
    clock = [1000.0]
    memory = ObjectMemory(path, clock=lambda: clock[0])
    memory.remember("apartment", "mug", "bedroom", "hexagontable_1", "table", "on the table by the chair")
    assert path.exists()
    clock[0] += 180
    assert memory.age(memory.recall("apartment", "mug")) == "3 minutes ago"  # this session
    again = ObjectMemory(path, clock=lambda: clock[0])
    seen = again.recall("apartment", "mug")
    assert seen.room == "bedroom" and seen.furniture == "hexagontable_1"
    assert again.age(seen) == "earlier today"  # a new session says the sighting is not its own
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
    [1, 2],
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


GOOD = {"object": "keys", "world": "apartment", "room": "bedroom", "time_s": 5.0}


@pytest.mark.parametrize("bad", [
    {"object": ["mug"], "world": "apartment", "room": "bedroom"},
    {"object": "mug", "world": "apartment", "room": "bedroom", "x_m": "left"},
    {"object": "mug", "world": "apartment", "room": 3},
    {"object": "mug", "world": "apartment", "room": None, "time_s": 1e400},
    {"object": "", "world": "apartment", "room": None},
    "mug",
])
def test_one_malformed_entry_is_reported_and_skipped_the_rest_loads(tmp_path, bad):
    path = tmp_path / "memory.json"
    path.write_text(json.dumps({"version": 2, "sightings": [bad, GOOD]}).replace("Infinity", "1e400"))
    memory = ObjectMemory(path)
    assert "sightings[0]" in memory.load_problem and "skipped" in memory.load_problem
    assert memory.recall("apartment", "keys").room == "bedroom"
    kept = list(tmp_path.glob("memory.json.unreadable-*"))
    assert len(kept) == 1 and "sightings" in kept[0].read_text()  # nothing is lost
    memory.remember("apartment", "mug", "kitchen")
    assert {s.object for s in ObjectMemory(path).sightings()} == {"keys", "mug"}


def test_files_are_private(tmp_path):
    path = tmp_path / "data" / "memory.json"
    ObjectMemory(path).remember("apartment", "mug", "kitchen")
    assert stat.S_IMODE(path.stat().st_mode) == 0o600
    assert stat.S_IMODE(path.parent.stat().st_mode) == 0o700


def test_two_sessions_on_one_file_keep_each_others_sightings_and_forgetting(tmp_path):
    path = tmp_path / "memory.json"
    first, second = ObjectMemory(path), ObjectMemory(path)
    first.remember("apartment", "mug", "kitchen")
    second.remember("apartment", "keys", "bedroom")
    first.remember("apartment", "book", "living room")
    assert {s.object for s in ObjectMemory(path).sightings()} == {"mug", "keys", "book"}
    second.forget("apartment", "mug")
    first.remember("apartment", "cup", "kitchen")
    assert {s.object for s in ObjectMemory(path).sightings()} == {"keys", "book", "cup"}


def test_an_earlier_sessions_sighting_says_when(tmp_path):
    now = time.time()
    memory = ObjectMemory(tmp_path / "m.json", clock=lambda: now)
    yesterday = memory.remember("apartment", "mug", "kitchen", time_s=now - 86400)
    long_ago = memory.remember("apartment", "keys", "kitchen", time_s=now - 40 * 86400)
    assert memory.age(yesterday) == "yesterday"
    then = datetime.datetime.fromtimestamp(now - 40 * 86400)
    assert memory.age(long_ago).startswith(f"on {then.day} {then:%B}")


SESSION = """
import sys
from assistant.dialogue.memory import ObjectMemory
memory = ObjectMemory(sys.argv[1])
for i in range(int(sys.argv[3])):
    memory.remember("apartment", f"{sys.argv[2]}-{i}", "kitchen")
"""


def test_concurrent_sessions_lose_nothing(tmp_path):
    path = tmp_path / "memory.json"
    runs = [subprocess.Popen([sys.executable, "-c", SESSION, str(path), name, "15"])
            for name in ("a", "b", "c")]
    assert [run.wait(timeout=120) for run in runs] == [0, 0, 0]
    names = {s.object for s in ObjectMemory(path).sightings()}
    assert names == {f"{n}-{i}" for n in "abc" for i in range(15)}
    assert not [p for p in tmp_path.iterdir() if p.name.endswith(".tmp")]


def test_a_folder_given_as_the_memory_file_is_refused_and_left_alone(tmp_path):
    """`chat --memory DIR` had moved the whole folder aside as an "unreadable memory file"."""
    from assistant.errors import AssistantError

    folder = tmp_path / "work"
    folder.mkdir()
    (folder / "notes.txt").write_text("mine")
    with pytest.raises(AssistantError, match="is a folder.*--memory .*memory.json"):
        ObjectMemory(folder)
    assert (folder / "notes.txt").read_text() == "mine" and sorted(p.name for p in tmp_path.iterdir()) == ["work"]

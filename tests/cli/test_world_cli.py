"""``assistant world`` through the console entry point, as a user runs it."""

import json
import subprocess
import sys

from assistant.cli import main


def test_world_json_follows_the_contract(capsys):
    assert main(["world", "apartment", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert set(data) >= {"start", "rooms", "doors", "furniture", "objects"}
    assert data["start"] == {"x": 5.0, "y": 0.0, "heading": 3.142}
    couch = next(f for f in data["furniture"] if f["id"] == "couch_1")
    assert couch | {} == couch and {k: couch[k] for k in ("model", "category", "x", "y", "facing")} == {
        "model": "couch", "category": "couch", "x": 4.5, "y": 3.0, "facing": 1.571}
    glasses = next(o for o in data["objects"] if o["name"] == "glasses case")
    assert (glasses["on"], glasses["x"], glasses["y"], glasses["room"]) == ("coffeetable_1", 4.5, 4.0, "living room")
    assert {r["name"] for r in data["rooms"]} == {"hallway", "living room", "bedroom"}


def test_modified_scene_and_check(capsys):
    assert main(["world", "hk-studio", "--scene", "modified", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert next(o for o in data["objects"] if o["name"] == "mug")["y"] == -3.8
    assert main(["world", "two-bedrooms-house", "--check"]) == 0
    assert "no problems" in capsys.readouterr().out


def test_misspelt_world_and_scene_are_named_with_the_known_ones(capsys):
    assert main(["world", "apartmnt", "--json"]) == 2
    err = capsys.readouterr().err
    assert "unknown world 'apartmnt'" in err and "hk-studio" in err
    assert main(["world", "apartment", "--scene", "moddified"]) == 2
    assert "unknown scene 'moddified'; known: lived-in, modified, original" in capsys.readouterr().err


def test_console_script_runs_as_a_process():
    out = subprocess.run([sys.executable, "-m", "assistant", "world", "apartment"],
                         capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    assert "living room" in out.stdout and "couch_1" in out.stdout

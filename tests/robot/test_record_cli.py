"""``assistant record``, ``assistant perceive --replay``, ``assistant fetch --robot replay:…`` and
the recordings in ``sample_scans/``."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from assistant.cli import main

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = ROOT / "sample_scans"


def _json(capsys, argv) -> dict:
    assert main(argv) == 0
    return json.loads(capsys.readouterr().out)


@pytest.fixture(scope="module")
def looked_around(tmp_path_factory):
    path = tmp_path_factory.mktemp("cli") / "look.mcap"
    assert main(["record", "--robot", "sim:hk-studio", "--step-deg", "120", "--json", str(path)]) == 0
    return path


def test_record_looks_around_and_summarises(looked_around, capsys):
    capsys.readouterr()
    from assistant.robot.recording import recording_summary

    summary = recording_summary(looked_around)
    assert summary["frames"] == 4 and summary["odometry"] == 4  # 3 steps of 120°, and the last view
    assert summary["commands"] == 5  # three turns, the stop, the stop on closing
    assert summary["seconds"] == pytest.approx(2 * 3.14159265 / 0.4, abs=1e-3)
    assert summary["metadata"]["world"] == "hk-studio" and not summary["truncated"]


def test_record_refuses_to_overwrite_and_bad_specs(looked_around, capsys):
    assert main(["record", "--robot", "sim:hk-studio", str(looked_around)]) == 2
    assert "exists" in capsys.readouterr().err
    assert main(["record", "--robot", "moon:1", str(looked_around.with_name("x.mcap"))]) == 2
    assert "unknown robot kind" in capsys.readouterr().err
    assert main(["record", "--robot", "sim", "--step-deg", "0", str(looked_around.with_name("y.mcap"))]) == 2


class _FloorOnlyDetector:
    """Stands in for the trained detector (its own tests cover it; training it here takes
    minutes): reports the frame's time and pose as the one 'detection'."""

    def analyse(self, frame, use_mount=True):
        class Result:
            def to_dict(self):
                pose = frame.robot_pose
                return {"detections": [{"category": "seen", "x": pose.x, "y": pose.y, "t": frame.timestamp_s}],
                        "floor": None, "samples": 0, "frame": "world"}

        return Result()


def test_perceive_replay_every_frame_or_one(looked_around, capsys, monkeypatch):
    from assistant.cli import perceive

    monkeypatch.setattr(perceive, "_detector", lambda args: _FloorOnlyDetector())
    every = _json(capsys, ["perceive", "--replay", str(looked_around), "--json"])
    assert [f["index"] for f in every["frames"]] == [0, 1, 2, 3]
    assert all("detections" in f and "floor" in f for f in every["frames"])
    one = _json(capsys, ["perceive", "--replay", str(looked_around), "--frame", "2", "--json"])
    assert one["index"] == 2 and one["detections"] == every["frames"][2]["detections"]
    at = _json(capsys, ["perceive", "--replay", str(looked_around), "--at", "5.3", "--json"])
    assert at["t"] == pytest.approx(every["frames"][1]["t"])  # the frame in view 5.3 s in
    assert main(["perceive", "--replay", str(looked_around), "--frame", "9"]) == 2
    assert "no frame 9" in capsys.readouterr().err
    assert main(["perceive", "--replay", str(looked_around.with_name("none.mcap"))]) == 2
    assert "no recording at" in capsys.readouterr().err


# ---------------------------------------------------------------------------- sample_scans/
def test_sample_scans_are_small_listed_and_replayable():
    import importlib.util

    from assistant.robot.recording import recording_summary

    spec = importlib.util.spec_from_file_location("make_sample_scans", ROOT / "tools" / "make_sample_scans.py")
    tool = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tool)
    files = sorted(p.name for p in SAMPLES.glob("*.mcap"))
    assert files == sorted(tool.SESSIONS), "sample_scans/ and tools/make_sample_scans.py disagree"
    assert sum((SAMPLES / f).stat().st_size for f in files) < 20e6
    readme = (SAMPLES / "README.md").read_text()
    for name in files:
        assert f"`{name}`" in readme, f"{name} has no line in sample_scans/README.md"
        summary = recording_summary(SAMPLES / name)
        assert summary["frames"] > 0 and not summary["truncated"]
        assert summary["metadata"]["world"] in name


@pytest.mark.slow
def test_fetch_on_the_recorded_fetch_makes_the_recorded_commands(capsys):
    """The product's whole fetch, on a replay of its own recorded fetch: the same decisions."""
    sample = SAMPLES / "apartment_fetch.mcap"
    from assistant.robot.recording import McapSource

    text = McapSource(sample).metadata["fetch"]
    data = _json(capsys, ["fetch", text, "--robot", f"replay:{sample}", "--json"])
    assert data["world"] == "apartment" and data["success"]
    report = data["replay"]
    assert report["issued"] == report["recorded"] == report["matched"] > 0
    assert data["final_pose"] == [3.309, 5.774, 0.8294]


def test_another_command_on_a_replay_says_the_recording_differs(capsys):
    """It had said only "FAILED: collision" (the replayed robot drives as recorded)."""
    from assistant.cli import main

    main(["fetch", "go to the bedroom", "--robot", f"replay:{SAMPLES / 'apartment_fetch.mcap'}"])
    out = capsys.readouterr().out
    assert "note: the recording's commands differ from this run's from 0.0 s on" in out
    assert "give the recorded command" in out


@pytest.mark.slow
def test_perceive_on_a_sample_scan_finds_the_dinner_table(capsys):
    """The real detector on the last frame of the recorded fetch: the robot faces the dinner table."""
    data = _json(capsys, ["perceive", "--replay", str(SAMPLES / "apartment_fetch.mcap"), "--frame", "62", "--json"])
    assert data["index"] == 62 and data["frame"] == "world"
    tables = [d for d in data["detections"] if d["category"] == "large table"]
    assert tables and abs(tables[0]["x"] - 4.2) < 0.3 and abs(tables[0]["y"] - 7.1) < 0.3

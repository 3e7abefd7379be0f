"""Demonstration files: round trip, atomic writes, validation messages, the keyboard."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from assistant.errors import DataFileError
from assistant.geometry import Pose2D
from assistant.policy.demonstration import Demonstration, environment_from_world, load_demonstrations
from assistant.policy.keyboard import KeyboardSession, normalise_key

CORPUS = Path(__file__).resolve().parents[2] / "corpus" / "demonstrations"


@pytest.fixture(scope="module")
def recorded():
    from assistant.sim import SimRobot
    from assistant.world import load_world

    world = load_world("training-home")
    robot = SimRobot(world, "original", start=Pose2D(5.8, 2.5, 1.571), seed=0)
    robot.connect()
    session = KeyboardSession(robot)
    session.press("w", 4)
    session.press("a", 3)
    session.settle(0.5)
    robot.close()
    env = environment_from_world(world, "original")
    return session.demonstration("move-left-non", "training-home", "original", env, None, None,
                                 Pose2D(5.8, 2.5, 3.14), "scripted-keyboard")


def test_keys_move_the_robot_and_are_recorded(recorded):
    keys = [f.key for f in recorded.frames]
    assert keys[:8] == [None, "w", "w", "w", "w", "a", "a", "a"]
    assert recorded.frames[4].pose.y > recorded.frames[0].pose.y + 0.02  # forward = +y here
    assert recorded.last_pose.theta > recorded.first_pose.theta + 0.3     # turned left
    assert all(b.t > a.t for a, b in zip(recorded.frames, recorded.frames[1:]))


def test_round_trip_is_exact(recorded, tmp_path):
    path = recorded.save(tmp_path / "sub" / "demo.json")
    loaded = Demonstration.load(path)
    assert loaded.to_dict() == recorded.to_dict() or json.loads(loaded.to_json()) == json.loads(recorded.to_json())
    again = Demonstration.load(loaded.save(tmp_path / "again.json"))
    assert again.to_json() == loaded.to_json()
    assert [p.name for p in (tmp_path / "sub").iterdir()] == ["demo.json"]  # no temporary left
    assert loaded.entity("couch_1").category == "couch"
    assert any(e.id.startswith("wall:") for e in loaded.environment)


def _write(tmp_path, data) -> Path:
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(data) if not isinstance(data, str) else data)
    return path


@pytest.mark.parametrize("mutate, where", [
    (lambda d: d.pop("rdt"), "rdt"),
    (lambda d: d.update(rdt="couch"), "rdt"),
    (lambda d: d["frames"][1].update(pose=[1, "north", 0]), "frames[1].pose"),
    (lambda d: d["frames"][2].update(t=-5), "frames[2].t"),
    (lambda d: d.update(frames=[]), "frames"),
    (lambda d: d["environment"][0].update(polygon=[[0, 0]]), "environment[0].polygon"),
    (lambda d: d.update(target_id="no_such_table"), "target_id"),
    (lambda d: d.update(goal=[1, 2]), "goal"),
])
def test_loader_names_file_and_key(recorded, tmp_path, mutate, where):
    data = recorded.to_dict()
    mutate(data)
    path = _write(tmp_path, data)
    with pytest.raises(DataFileError) as info:
        Demonstration.load(path)
    assert str(path) in str(info.value) and where in str(info.value)


def test_loader_rejects_broken_json(tmp_path):
    path = _write(tmp_path, "{not json")
    with pytest.raises(DataFileError, match="bad.json: line 1"):
        Demonstration.load(path)


def test_key_spellings():
    assert [normalise_key(k) for k in ("w", "UP", "forward", "left", " ", "stop", "Esc", "q", "z")] == \
        ["w", "w", "w", "a", "x", "x", "esc", "q", None]


def test_training_corpus_covers_table_5_1():
    from assistant.policy.rdt import TABLE_RDTS

    demos = load_demonstrations(CORPUS)
    for rdt in TABLE_RDTS:
        mine = [d for d in demos if d.rdt == rdt]
        assert len(mine) >= 5, rdt
        assert {d.world for d in mine} == {"training-home"}  # not a study home
        starts = {(round(d.first_pose.x, 2), round(d.first_pose.y, 2)) for d in mine}
        assert len(starts) == len(mine)  # different starting poses
        for d in mine:  # the teacher got where it meant to go
            assert d.goal is not None and (d.last_pose.x - d.goal.x) ** 2 + (d.last_pose.y - d.goal.y) ** 2 < 0.2 ** 2

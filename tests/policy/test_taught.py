"""What a user teaches: in the user's data folder, private, checked, listable, removable."""

from __future__ import annotations

import dataclasses
import json
import os
import stat
import subprocess
import sys
from pathlib import Path

import pytest

from assistant.cli import main
from assistant.geometry import Pose2D
from assistant.policy.demonstration import Frame, load_demonstrations
from assistant.policy.library import DEFAULT_DIRECTORY
from assistant.policy.taught import check_outlier, list_taught, taught_directory

ROOT = Path(__file__).resolve().parents[2]
TEACH = ["teach", "couch-front-table", "--world", "training-home", "--start", "3.5,1.8,3.14"]


@pytest.fixture
def data(tmp_path, monkeypatch):
    monkeypatch.setenv("ASSISTANT_DATA", str(tmp_path / "data"))
    return tmp_path / "data"


def _teach(args, keys, monkeypatch, capsys):
    import io

    monkeypatch.setattr(sys, "stdin", io.StringIO(keys))
    code = main(args)
    return code, capsys.readouterr()


def test_teaching_goes_to_the_users_folder_not_the_corpus(data, monkeypatch, capsys):
    before = sorted(DEFAULT_DIRECTORY.rglob("*.json"))
    code, out = _teach(TEACH + ["--json"], "w 3\nq\n", monkeypatch, capsys)
    assert code == 0, out.err
    saved = Path(json.loads(out.out)["saved"])
    assert saved.parent == data / "demonstrations" / "couch-front-table"
    assert stat.S_IMODE(saved.stat().st_mode) == 0o600
    assert sorted(DEFAULT_DIRECTORY.rglob("*.json")) == before
    code, out = _teach(["teach", "--list", "--json"], "", monkeypatch, capsys)
    (row,) = json.loads(out.out)["demonstrations"]
    assert row["name"] == f"couch-front-table/{saved.stem}" and not row["held"]
    code, out = _teach(["teach", "--forget", saved.stem], "", monkeypatch, capsys)
    assert code == 0 and not saved.exists() and "forgot" in out.out
    code, out = _teach(["teach", "--forget", "nothing-like-it"], "", monkeypatch, capsys)
    assert code == 2 and "unknown taught demonstration" in out.err


def test_an_outlier_that_moves_the_place_by_metres_is_flagged():
    shipped = load_demonstrations(DEFAULT_DIRECTORY, "couch-front-table")
    demo = shipped[0]
    assert not check_outlier(demo, shipped[1:]).outlier
    last = demo.frames[-1]
    moved = Pose2D(last.pose.x + 3.5, last.pose.y, last.pose.theta)
    sloppy = dataclasses.replace(demo, frames=demo.frames[:-1] + (Frame(last.t, moved, last.key),))
    check = check_outlier(sloppy, shipped[1:])
    assert check.outlier and check.distance_m > 2.5
    assert "m from where the" in check.describe("couch-front-table")


def test_an_outlier_is_held_back_until_accepted(data, monkeypatch, capsys):
    code, out = _teach(TEACH, "d 16\nw 60\nq\n", monkeypatch, capsys)  # drives far from the table
    assert code == 0 and "held back" in out.out and "--accept" in out.out
    (item,) = list_taught()
    assert item.held and not taught_directory().exists()
    code, out = _teach(["teach", "--accept", item.name], "", monkeypatch, capsys)
    assert code == 0 and "accepted" in out.out
    (item,) = list_taught()
    assert not item.held


def test_huge_key_repeats_and_folder_outputs_are_refused(data, monkeypatch, capsys, tmp_path):
    code, out = _teach(TEACH + ["--json"], "w 100000000000\nq\n", monkeypatch, capsys)
    # refused, so the robot was never driven: nothing is saved (3 Dec: an undriven teaching saves nothing)
    assert code == 1 and "at most" in out.err and json.loads(out.out)["presses"] == 0
    for bad in (f"{tmp_path}/", str(tmp_path)):
        code, out = _teach(TEACH + ["--out", bad], "q\n", monkeypatch, capsys)
        assert code == 2 and "is a folder" in out.err


def test_three_teach_runs_at_once_keep_three_files(data):
    env = dict(os.environ, ASSISTANT_DATA=str(data), PYTHONPATH=str(ROOT), PYTHONWARNINGS="ignore")
    runs = [subprocess.Popen([sys.executable, "-m", "assistant", *TEACH, "--json"], stdin=subprocess.PIPE,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
            for _ in range(3)]
    outs = [run.communicate("w 2\nq\n", timeout=240) for run in runs]
    assert [run.returncode for run in runs] == [0, 0, 0], [err for _, err in outs]
    saved = {json.loads(out)["saved"] for out, _ in outs}
    assert len(saved) == 3 and all(Path(p).is_file() for p in saved)
    assert len(list((data / "demonstrations" / "couch-front-table").glob("*.json"))) == 3


def test_a_held_demonstration_and_a_confirmed_one_never_share_a_name(data, monkeypatch, capsys):
    """A held-back first try, then a good one: both had been "…-keyboard-01", and neither
    --accept nor --forget could tell them apart ("names 2 demonstrations …; give RDT/NAME")."""
    _teach(TEACH, "d 16\nw 60\nq\n", monkeypatch, capsys)  # held back (far from the table)
    _teach(TEACH, "w 8\nq\n", monkeypatch, capsys)
    names = [t.name for t in list_taught()]
    assert len(set(names)) == 2, names


def test_two_demonstrations_of_one_name_from_an_earlier_version_can_each_be_named(data, monkeypatch, capsys):
    _teach(TEACH, "d 16\nw 60\nq\n", monkeypatch, capsys)
    (held,) = list_taught()
    used = taught_directory() / held.path.parent.name / held.path.name  # as an earlier version saved it
    used.parent.mkdir(parents=True)
    used.write_text(held.path.read_text())
    code, out = _teach(["teach", "--forget", held.name], "", monkeypatch, capsys)
    assert code == 2 and f"held:{held.name}" in out.err
    code, out = _teach(["teach", "--accept", held.name], "", monkeypatch, capsys)  # the held one, plainly
    assert code == 0 and "accepted" in out.out
    assert [t.held for t in list_taught()] == [False, False]

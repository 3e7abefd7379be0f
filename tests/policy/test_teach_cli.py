"""``assistant teach`` driven through a pipe, and ``assistant eval policy`` on one RDT."""

from __future__ import annotations

import json
import sys
from pathlib import Path

from assistant.policy.demonstration import Demonstration

ROOT = Path(__file__).resolve().parents[2]


def _teach_direct(args, keys: str, capsys):
    """Runs the command module in this process (the lead registers it in COMMAND_MODULES)."""
    import argparse
    import io

    from assistant.cli import teach

    parser = argparse.ArgumentParser()
    teach.register(parser.add_subparsers())
    ns = parser.parse_args(["teach", *args])
    old = sys.stdin
    sys.stdin = io.StringIO(keys)
    try:
        code = ns.handler(ns)
    finally:
        sys.stdin = old
    return code, capsys.readouterr()


def test_pipe_records_a_demonstration(tmp_path, capsys):
    out = tmp_path / "demo.json"
    code, captured = _teach_direct(["couch-front-table", "--world", "training-home", "--start", "3.5,1.8,3.14",
                                    "--out", str(out), "--json"], "w 3\nleft\nnonsense\na 2\nq\n", capsys)
    assert code == 0
    summary = json.loads(captured.out)
    assert summary["saved"] == str(out) and summary["presses"] == 6 and summary["ignored"] == ["nonsense"]
    assert "not a key" in captured.err
    demo = Demonstration.load(out)
    assert (demo.reference_id, demo.target_id, demo.teacher) == ("couch_1", "coffeetable_1", "keyboard")
    assert [f.key for f in demo.frames[1:7]] == ["w", "w", "w", "a", "a", "a"]
    assert demo.last_pose.x < 3.5  # drove forward, west


def test_escape_aborts_without_saving(tmp_path, capsys):
    out = tmp_path / "demo.json"
    code, captured = _teach_direct(["move-left-non", "--world", "training-home", "--out", str(out)],
                                   "a 4\nesc\nq\n", capsys)
    assert code == 1 and not out.exists() and "nothing saved" in captured.out


def test_eval_policy_one_rdt(capsys):
    from assistant.cli import main

    assert main(["eval", "policy", "--layout", "training-home:modified", "--rdt", "move-front-non",
                 "--trials", "2", "--json"]) == 0
    result = json.loads(capsys.readouterr().out)
    (row,) = result["rows"]
    assert row["rdt"] == "move-front-non" and len(row["trials"]) == 2 and row["T_total"] is None
    assert result["mean_d"] == row["d_mean"] < 0.3


def test_words_end_a_teaching_and_nothing_driven_is_not_saved(tmp_path, capsys):
    """In a piped chat a person types words, not keys: "never mind" stops the teaching, and a
    teaching in which the robot was not driven ("done" at once) saves nothing (it used to save
    an empty demonstration and thank the person for it)."""
    out = tmp_path / "demo.json"
    code, captured = _teach_direct(["move-left-non", "--world", "training-home", "--out", str(out)],
                                   "what should I do now?\nnever mind\n", capsys)
    assert code == 1 and not out.exists() and "you are teaching me a place now" in captured.err
    code, captured = _teach_direct(["move-left-non", "--world", "training-home", "--out", str(out)],
                                   "done\n", capsys)
    assert code == 1 and not out.exists()
    code, captured = _teach_direct(["move-left-non", "--world", "training-home", "--out", str(out)],
                                   "a 2\ndone\n", capsys)
    assert code == 0 and out.exists()

"""The fetch dev set and the Table 5-4 summary of `assistant eval fetch` (the trials themselves
are run by the evaluation, not here)."""

from __future__ import annotations

import argparse
import json
from collections import Counter

import pytest

from assistant.eval import fetch as evaluation


def test_dev_set_covers_every_object_home_scene_and_kind(all_worlds):
    everything = evaluation.load_dev_set()
    records = [r for r in everything if r["scene"] in ("original", "modified")]
    commands = {(r["world"], r["text"]) for r in records}
    assert len(commands) >= 60  # distinct commands (issue 7), each run in both scenes
    for scene in ("original", "modified"):
        assert {(r["world"], r["text"]) for r in records if r["scene"] == scene} == commands, scene
    per_home = Counter(world for world, _ in commands)
    assert max(per_home.values()) - min(per_home.values()) <= 2, per_home  # balanced over the homes
    homes = {"apartment", "hk-studio", "one-bedroom-house", "two-bedrooms-house"}
    assert {r["world"] for r in records} == homes
    for home in homes:
        objects = {o.name for o in all_worlds[home].scene("original").objects}
        for scene in ("original", "modified"):
            said = {r["object"] for r in records if r["world"] == home and r["scene"] == scene}
            assert said == objects, (home, scene)
    assert set(Counter(r["kind"] for r in records)) == {"dynamic", "static", "mixed"}
    for r in everything:  # the object a command is about is named in it (the parser must find it)
        assert r["object"].split()[0] in r["text"].lower(), r
    lived_in = [r for r in everything if r not in records]  # issue 16's object-landmark commands
    assert lived_in and {r["scene"] for r in lived_in} == {"lived-in"}
    for r in lived_in:
        assert r["object"] in {o.name for o in all_worlds[r["world"]].scene("lived-in").objects}, r


def test_bad_dev_set_names_file_and_line(tmp_path):
    from assistant.errors import DataFileError

    path = tmp_path / "dev.jsonl"
    path.write_text(json.dumps({"text": "go", "world": "apartment"}) + "\n", encoding="utf-8")
    with pytest.raises(DataFileError, match="line 1.*missing scene, object, kind"):
        evaluation.load_dev_set(path)
    path.write_text("{not json\n", encoding="utf-8")
    with pytest.raises(DataFileError, match="line 1.*not JSON"):
        evaluation.load_dev_set(path)


def test_summary_counts_outcomes_per_home_scene_and_mode():
    trials = [
        {"perception": "oracle", "world": "apartment", "scene": "original", "success": True, "failure": None},
        {"perception": "oracle", "world": "apartment", "scene": "original", "success": False, "failure": "not_visible"},
        {"perception": "sensed", "world": "apartment", "scene": "modified", "success": False,
         "failure": "reference_not_found"},
    ]
    summary = evaluation.summarise(trials)
    first = summary["groups"][0]
    assert (first["perception"], first["success"], first["not_visible"], first["all"]) == ("oracle", 1, 1, 2)
    assert first["success_rate"] == 0.5
    assert summary["totals"]["sensed"]["reference_not_found"] == 1
    assert summary["totals"]["sensed"]["success_rate"] == 0.0


def test_arguments():
    from assistant.cli import eval_fetch

    parser = argparse.ArgumentParser()
    eval_fetch.add_arguments(parser)
    args = parser.parse_args(["--perception", "oracle", "--limit", "3", "--world", "apartment"])
    assert (args.perception, args.limit, args.world) == ("oracle", 3, "apartment")


def test_select_keeps_one_home_and_scene_then_the_first_n():
    records = [{"world": w, "scene": s, "n": i} for i, (w, s) in enumerate(
        [("apartment", "original"), ("hk-studio", "original"), ("apartment", "modified"),
         ("apartment", "original"), ("apartment", "original")])]
    assert [r["n"] for r in evaluation.select(records, "apartment", "original", 2)] == [0, 3]
    assert [r["n"] for r in evaluation.select(records, scene="modified")] == [2]
    assert evaluation.select(records, limit=-1) == []


def test_an_unwritable_trials_file_is_one_line(tmp_path, capsys):
    from assistant.cli import main

    assert main(["eval", "fetch", "--trials", str(tmp_path / "no" / "such" / "t.jsonl")]) == 2
    assert "cannot write the trials file" in capsys.readouterr().err

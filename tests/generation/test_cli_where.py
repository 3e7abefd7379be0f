"""``assistant where``: the command module (registered by the lead in COMMAND_MODULES)."""

from __future__ import annotations

import argparse
import json

import pytest

from assistant.cli import where
from assistant.errors import AssistantError


def _run(argv, capsys):
    parser = argparse.ArgumentParser(prog="assistant")
    where.register(parser.add_subparsers())
    args = parser.parse_args(["where", *argv])
    code = args.handler(args)
    return code, capsys.readouterr().out


def _run_batch(requests, tmp_path, capsys):
    """``assistant where --batch FILE --search oracle`` on these request lines: the exit
    status and one parsed JSON object per output line."""
    batch = tmp_path / "req.jsonl"
    batch.write_text("".join(line + "\n" for line in requests))
    code, out = _run(["--batch", str(batch), "--search", "oracle"], capsys)
    return code, [json.loads(x) for x in out.splitlines()]


def test_json_answer_has_the_contract_fields(capsys, generation_model):
    code, out = _run(["mug", "--world", "apartment", "--search", "oracle", "--json"], capsys)
    data = json.loads(out)
    assert code == 0
    for field in ("found", "description", "nodes", "seen_at", "selected", "tree",
                  "composition_seconds", "search_seconds"):
        assert field in data
    assert data["search"] == "oracle" and data["environment"] == "oracle"
    assert data["found"] and data["description"].startswith("The mug is")


def test_batch_goes_on_after_a_bad_line(tmp_path, capsys, generation_model):
    code, lines = _run_batch(['{"object": "fork", "world": "hk-studio", "scene": "modified"}',
                              '{"object": "mug", "world": "atlantis"}',
                              '{"object": "mug", "world": "apartment", "question": "how do I get to my mug"}'],
                             tmp_path, capsys)
    assert code == 0 and len(lines) == 3
    assert lines[0]["found"] and "fork" in lines[0]["description"]
    assert "error" in lines[1] and "apartment" in lines[1]["error"]  # the known homes are listed
    assert lines[2]["style"] == "dynamic" and lines[2]["description"].startswith("Go into the bedroom")


def test_missing_arguments_are_explained(capsys):
    with pytest.raises(AssistantError):
        _run(["mug"], capsys)


def test_sensed_search_is_the_default_and_is_labelled(capsys, generation_model):
    # the hk-studio laptop is in view of the start pose: a short search
    code, out = _run(["laptop", "--world", "hk-studio", "--json"], capsys)
    data = json.loads(out)
    assert code == 0 and data["found"]
    assert data["search"] == "sensed" and data["environment"] == "perceived"
    assert data["seen_at"]["room"] == "meeting room"
    assert abs(data["seen_at"]["x"] - -4.0) < 0.3 and abs(data["seen_at"]["y"] - -2.9) < 0.3
    report = data["search_report"]
    assert report["found"] and report["rooms_searched"] and report["furniture_perceived"] >= 1
    assert data["search_seconds"] > 0 and data["composition_seconds"] > 0
    assert data["description"].startswith("The laptop is")


def test_unknown_search_mode_is_an_error(capsys):
    with pytest.raises(SystemExit):
        _run(["mug", "--world", "apartment", "--search", "psychic"], capsys)


def test_a_bad_pose_or_miss_rate_is_a_message_not_a_traceback(tmp_path, capsys, generation_model):
    code, lines = _run_batch(['{"object": "mug", "world": "apartment", "listener": "a,b"}',
                              '{"object": "mug", "world": "apartment", "miss_rate": "often"}',
                              '{"object": "mug", "world": "apartment"}'], tmp_path, capsys)
    assert code == 0 and len(lines) == 3
    assert "X,Y,HEADING" in lines[0]["error"] and "often" in lines[1]["error"]
    assert lines[2]["found"]
    with pytest.raises(SystemExit):  # argparse's usage message, exit status 2
        _run(["mug", "--world", "apartment", "--miss-rate", "1.5"], capsys)
    assert "below 1" in capsys.readouterr().err

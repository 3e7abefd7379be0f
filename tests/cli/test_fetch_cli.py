"""``assistant fetch``: the JSON contract, batches, bad input. The language layers are replaced
by a stand-in parser (their own tests cover them; training them here would take a minute), and
oracle perception keeps the runs short."""

from __future__ import annotations

import argparse
import json

import pytest

from assistant.cli import fetch as fetch_cli
from assistant.grounding import GroundingPlan, RDTNode

CONTRACT = {"plan", "success", "failure", "final_pose", "target_visible", "sim_seconds", "wall_seconds"}


class _Parsed:
    def __init__(self, plan):
        self.plan = plan


class _StandInParser:
    """Knows two sentences; anything else grounds to nothing (like nonsense would)."""

    PLANS = {
        "the glasses case is on the table in front of the couch in the living room":
            GroundingPlan("living room", [RDTNode("table", (("couch", "front"),))], "glasses case"),
        "the mug is in the garage":
            GroundingPlan("garage", [], "mug"),
    }

    def parse(self, text):
        plan = self.PLANS.get(text)
        return _Parsed(plan if plan is not None else GroundingPlan())


@pytest.fixture(autouse=True)
def _stand_in_parser(monkeypatch):
    from assistant.app import Fetcher

    monkeypatch.setattr(Fetcher, "parser", lambda self, world: _StandInParser())


def _main(argv):
    parser = argparse.ArgumentParser(prog="assistant")
    subs = parser.add_subparsers(dest="command")
    fetch_cli.register(subs)
    args = parser.parse_args(argv)
    from assistant.errors import AssistantError

    try:
        return args.handler(args)
    except AssistantError as error:
        return f"error: {error}"


def test_json_contract_and_success(capsys):
    status = _main(["fetch", "the glasses case is on the table in front of the couch in the living room",
                    "--world", "apartment", "--perception", "oracle", "--json"])
    assert status == 0
    data = json.loads(capsys.readouterr().out)
    assert CONTRACT <= set(data)
    assert data["success"] is True and data["failure"] is None
    assert data["target_visible"]["pixels"] >= 50 and data["target_visible"]["distance"] <= 4.5
    assert len(data["final_pose"]) == 3 and data["plan"]["nodes"] == ["couch-front-table"]
    assert data["nodes"][0]["move_to"] is not None and data["nodes"][0]["score"] is not None
    assert data["sim_seconds"] > 0 and data["wall_seconds"] > 0


def test_batch_answers_every_line_with_reasons(tmp_path, capsys):
    batch = tmp_path / "requests.jsonl"
    lines = [
        {"text": "the mug is in the garage", "world": "apartment", "scene": "original", "perception": "oracle"},
        {"text": "colourless green ideas", "world": "apartment", "perception": "oracle"},
        {"text": "x", "world": "apartment", "perception": "psychic"},
        {"world": "apartment"},
        {"text": "x", "world": "atlantis", "perception": "oracle"},
    ]
    batch.write_text("\n".join(json.dumps(line) for line in lines) + "\nnot json\n", encoding="utf-8")
    assert _main(["fetch", "--batch", str(batch)]) == 0
    out = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    assert len(out) == 6
    assert out[0]["failure"] == "no_room" and out[0]["success"] is False
    assert out[1]["failure"] == "parse"
    assert "perception" in out[2]["error"]
    assert "text" in out[3]["error"]
    assert "atlantis" in out[4]["error"]
    assert "not JSON" in out[5]["error"]


def test_bad_invocations_say_what_to_do():
    assert "--world" in _main(["fetch", "the mug"])
    assert "nothing to fetch" in _main(["fetch"])

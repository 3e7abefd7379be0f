"""``assistant parse``: the JSON fields of the command-line contract, batches, bad input."""

from __future__ import annotations

import json

import pytest

from assistant.cli import main

CONTRACT_FIELDS = {"tokens", "pos", "chunk_labels", "tree", "plan", "unused", "flags"}
PLAN_FIELDS = {"room", "nodes", "object", "support", "kind"}


@pytest.fixture(scope="module", autouse=True)
def _corpus_present():
    from assistant.grounding.training import split_corpus_paths

    csvs, xmls = split_corpus_paths(None)
    if not csvs or not xmls:
        pytest.skip("corpus/ has no descriptions or chunk-grounding labels yet")


def run(capsys, *argv) -> tuple[int, str, str]:
    status = main(["parse", *argv])
    out, err = capsys.readouterr()
    return status, out, err


@pytest.mark.parametrize("grounder", ["scored", "learned", "combined"])
def test_json_has_the_contract_fields(capsys, grounder):
    status, out, _ = run(capsys, "go into the living room and turn left, the mug is on the table in front of the couch",
                         "--grounder", grounder, "--json")
    assert status == 0
    data = json.loads(out)
    assert CONTRACT_FIELDS <= set(data) and PLAN_FIELDS <= set(data["plan"])
    assert len(data["tokens"]) == len(data["pos"]) == len(data["chunk_labels"])
    assert data["plan"]["nodes"] == ["move-left-non", "couch-front-table"]
    assert data["plan"]["object"] == "mug" and data["plan"]["kind"] == "mixed"


def test_world_option_flags_an_ambiguous_table(capsys):
    status, out, _ = run(capsys, "go to the living room, the mug is on the table", "--world", "apartment", "--json")
    data = json.loads(out)
    assert status == 0 and data["plan"]["room"] == "living room"
    assert "ambiguous_target:table:3" in data["flags"]


def test_plain_text_output_names_nodes_and_notes(capsys):
    status, out, _ = run(capsys, "the mug is on the table by the flurbostat")
    assert status == 0
    # any noun can be a landmark ("by the lamp"): the unknown word is read as an object landmark
    assert "node 1: flurbostat-beside-table" in out and "note: no_room" in out
    status, out, _ = run(capsys, "the mug is on the table qqqq zzzz")
    assert "unused words:" in out


def test_batch_gives_one_json_line_per_request_and_errors_in_place(capsys, tmp_path):
    batch = tmp_path / "requests.txt"
    batch.write_text("go to the bedroom and turn right\n\n" + "go left " * 120 + "\nzzzz qqqq\n", encoding="utf-8")
    status, out, _ = run(capsys, "--batch", str(batch))
    lines = [json.loads(line) for line in out.splitlines()]
    assert status == 0 and len(lines) == 3
    assert lines[0]["plan"]["nodes"] == ["move-right-non"] and lines[0]["plan"]["room"] == "bedroom"
    assert "error" in lines[1] and "more than 200" in lines[1]["error"] and lines[1]["line"] == 3
    assert "not_understood" in lines[2]["flags"]


def test_usage_errors_are_one_line_with_status_2(capsys):
    status, _, err = run(capsys)
    assert status == 2 and "nothing to parse" in err
    status, _, err = run(capsys, "turn left", "--batch", "x.txt")
    assert status == 2 and "not both" in err
    status, _, err = run(capsys, "turn left", "--corpus", "/nonexistent/corpus.csv")
    assert status == 2 and "does not exist" in err

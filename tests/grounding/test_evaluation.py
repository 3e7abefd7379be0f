"""``assistant eval grounding`` on small label files (the full run belongs to the command)."""

from __future__ import annotations

import json

from assistant.cli import main

HEADER = "CMD#,Chunk Name,Chunk Content,target room,target object,reference,direction,target\n"


def labels_csv(tmp_path, small_labels):
    lines = [HEADER]
    for command in small_labels:
        for record, grounding in zip(command.records, command.groundings):
            values = ["N/A" if v is None else v for v in grounding.as_tuple()]
            lines.append(",".join([command.number, record.label, record.content(), *values]) + "\n")
    path = tmp_path / "labels.csv"
    path.write_text("".join(lines), encoding="utf-8")
    return path


def test_eval_json_has_both_protocols_for_both_grounders(tmp_path, small_labels, capsys):
    path = labels_csv(tmp_path, small_labels)
    status = main(["eval", "grounding", "--corpus", str(path), "--test", str(path), "--rounds", "2",
                   "--no-plans", "--json"])
    data = json.loads(capsys.readouterr().out)
    assert status == 0
    assert data["corpus"]["commands"] == len(small_labels) and data["protocol"]["rounds"] == 2
    for name in ("scored", "learned", "combined"):
        split = data["corpus_split"][name]
        assert set(split) == {"target room", "target object", "reference", "direction", "target", "whole command"}
        assert all(0.0 <= v <= 1.0 for v in split.values())
        assert data["test"]["accuracy"][name]["whole command"] == 1.0  # trained on the same file


def test_eval_table_form(tmp_path, small_labels, capsys):
    path = labels_csv(tmp_path, small_labels)
    status = main(["eval", "grounding", "--corpus", str(path), "--test", str(path), "--rounds", "1",
                   "--no-plans", "--grounder", "learned"])
    out = capsys.readouterr().out
    assert status == 0
    assert "The whole spatial command" in out and "Table 4-4 form" in out and "dissertation" in out


def test_eval_needs_enough_commands(tmp_path, capsys):
    path = tmp_path / "tiny.csv"
    path.write_text(HEADER + "1,IRMRP,VB turn DIR left,N/A,N/A,move,left,N/A\n", encoding="utf-8")
    assert main(["eval", "grounding", "--corpus", str(path), "--no-plans"]) == 2
    assert "need at least 3 labelled commands" in capsys.readouterr().err

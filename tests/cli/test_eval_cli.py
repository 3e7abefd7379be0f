"""``assistant eval NAME`` dispatch: only the chosen evaluation's module is imported."""

import sys
import types

import pytest

from assistant.cli import eval as eval_cli
from assistant.cli import main


def test_unknown_evaluation_lists_the_known_ones(capsys):
    with pytest.raises(SystemExit) as info:
        main(["eval", "nonsense"])
    assert info.value.code == 2
    assert "tagging" in capsys.readouterr().err


def test_options_go_to_the_chosen_evaluation(monkeypatch, capsys):
    fake = types.ModuleType("fake_evaluation")
    fake.add_arguments = lambda parser: parser.add_argument("--rounds", type=int, default=10)
    fake.run = lambda args: print(f"rounds={args.rounds} json={args.json}") or 0
    monkeypatch.setitem(sys.modules, "fake_evaluation", fake)
    monkeypatch.setitem(eval_cli.EVALUATIONS, "grounding", "fake_evaluation")
    assert main(["eval", "grounding", "--rounds", "3", "--json"]) == 0
    assert capsys.readouterr().out.strip() == "rounds=3 json=True"


def test_an_evaluation_not_built_says_so(monkeypatch, capsys):
    monkeypatch.setitem(eval_cli.EVALUATIONS, "dialogue", "assistant.no_such_package.evaluation")
    assert main(["eval", "dialogue"]) == 2
    assert "not built yet" in capsys.readouterr().err


def test_progress_goes_to_stderr_and_is_quiet_with_json(capsys):
    import argparse

    from assistant.cli.common import progress_for

    progress_for(argparse.Namespace(json=False))("fetch trials", 2, 8)
    progress_for(argparse.Namespace(json=False))("training")
    progress_for(argparse.Namespace(json=True))("fetch trials", 3, 8)
    captured = capsys.readouterr()
    assert captured.out == "" and captured.err == "fetch trials (2/8)\ntraining\n"

"""``assistant eval NAME`` dispatch: only the chosen evaluation's module is imported."""

import importlib
import inspect
import io
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
    fake.QUICK = ()
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


def test_quick_stands_for_the_evaluation_s_small_sample_and_says_so(monkeypatch, capsys):
    fake = types.ModuleType("fake_evaluation")
    fake.QUICK = ("--rounds", "1", "--only", "a")
    fake.add_arguments = lambda parser: (parser.add_argument("--rounds", type=int, default=10),
                                         parser.add_argument("--only", default=None))
    fake.run = lambda args: print(f"rounds={args.rounds} only={args.only}") or 0
    monkeypatch.setitem(sys.modules, "fake_evaluation", fake)
    monkeypatch.setitem(eval_cli.EVALUATIONS, "grounding", "fake_evaluation")
    assert main(["eval", "grounding", "--quick"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0] == "rounds=1 only=a" and "not the reported figures" in out[1]
    assert main(["eval", "grounding", "--quick", "--rounds", "3", "--json"]) == 0  # a given option wins
    assert capsys.readouterr().out.strip() == "rounds=3 only=a"  # --json: nothing but the report


def test_every_evaluation_has_a_quick_sample_its_parser_accepts():
    for name in eval_cli.EVALUATIONS:
        parser, module = eval_cli.build_evaluation_parser(name)
        assert module.QUICK and parser.parse_args(list(module.QUICK))


class FakeTerminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def progress_of_every_evaluation(monkeypatch, stderr, argv_tail):
    """What each ``assistant eval NAME`` writes on ``stderr`` when its evaluation reports progress.

    Every function of the evaluation's library module (``assistant.eval.NAME``) that takes a
    ``progress`` callback is replaced by one that reports a counted and an uncounted stage
    through the callback it was given, then stops the command (no real evaluation runs)."""
    class Reported(Exception):
        pass

    def reporting_instead_of(original):
        def fake(*args, **kwargs):
            report = inspect.signature(original).bind(*args, **kwargs).arguments["progress"]
            report("fetch trials", 2, 8)
            report("training")
            raise Reported
        return fake

    shown = {}
    for name in eval_cli.EVALUATIONS:
        library = importlib.import_module(f"assistant.eval.{name}")
        with monkeypatch.context() as patch:
            patch.setattr(sys, "stderr", stderr)
            for attribute, value in vars(library).items():
                if (inspect.isfunction(value) and value.__module__ == library.__name__
                        and "progress" in inspect.signature(value).parameters):
                    patch.setattr(library, attribute, reporting_instead_of(value))
            start = len(stderr.getvalue())
            with pytest.raises(Reported):
                main(["eval", name, *argv_tail])
            shown[name] = stderr.getvalue()[start:]
    return shown


def test_every_evaluation_shows_progress_on_a_terminal(monkeypatch):
    shown = progress_of_every_evaluation(monkeypatch, FakeTerminal(), [])
    for name, text in shown.items():
        assert "fetch trials" in text and "2/8" in text and "training" in text, (name, text)


@pytest.mark.parametrize("stderr, argv_tail", [(FakeTerminal, ["--json"]), (io.StringIO, [])],
                         ids=["json on a terminal", "not a terminal"])
def test_every_evaluation_is_quiet_with_json_or_off_a_terminal(monkeypatch, stderr, argv_tail):
    shown = progress_of_every_evaluation(monkeypatch, stderr(), argv_tail)
    assert shown == {name: "" for name in eval_cli.EVALUATIONS}

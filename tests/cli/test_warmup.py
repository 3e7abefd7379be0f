"""``assistant warm-up`` (make run's and make notebook's set-up step) prepares every model the chat uses."""

import json

from assistant.cli import main


def test_warm_up_prepares_each_model_and_says_so(capsys):
    assert main(["warm-up", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert [s["what"] for s in report["steps"]] == [
        "language and grounding models", "description model", "policy models", "furniture detector"]
    assert report["world"] == "apartment" and report["seconds"] >= 0


def test_the_program_leaves_what_is_alive_to_the_operating_system_at_its_end(monkeypatch):
    """The interpreter's finalization walked every model warm-up loaded (1.1 s of CPU, 4.6 s of
    silence on a loaded machine; benchmarks/bench_trust.py exit); the program freezes them first."""
    import gc

    from assistant import cli

    monkeypatch.setattr(cli, "main", lambda: 7)
    gc.unfreeze()
    try:
        assert cli.program() == 7
        assert gc.get_freeze_count() > 0
    finally:
        gc.unfreeze()  # the test process goes on collecting


def test_the_console_script_and_python_m_run_the_program():
    from pathlib import Path

    root = Path(__file__).resolve().parents[2]
    assert 'assistant = "assistant.cli:program"' in (root / "pyproject.toml").read_text()
    assert "raise SystemExit(program())" in (root / "assistant" / "__main__.py").read_text()


def test_the_program_hands_its_status_to_a_hung_synthesis_check(monkeypatch):
    """The program's end (not ``main``, which tests and notebooks call too) asks the speech
    output whether a synthesis still hangs, with the command's status."""
    import gc

    from assistant import cli
    from assistant.dialogue.speech import tts

    asked = []
    monkeypatch.setattr(cli, "main", lambda: 3)
    monkeypatch.setattr(tts, "leave_if_synthesis_hung", asked.append)
    try:
        assert cli.program() == 3
    finally:
        gc.unfreeze()
    assert asked == [3]

"""Every ``assistant`` command in README.md's code blocks works as written.

Each command is one test, run in-process (``assistant.cli.main``) in one scratch folder with a
scratch data folder, in README order (``sim render`` writes the ``frame.png`` that ``perceive
--depth`` reads, ``record`` the ``session.mcap`` that the replayed fetch reads). The interactive
ones get a scripted stdin: ``chat`` one README sentence then end of input, ``teach`` a few keys.
The README's evaluation examples are ``assistant eval NAME --quick`` (a small sample of each,
seconds to a minute once the models are trained) and run here as written; the full evaluations
behind the README's table of figures take minutes to an hour each and are run by the lead, not
by the test suite (their commands are in that table and the docs/ pages).
"""

from __future__ import annotations

import io
import re
import shlex
import sys
from pathlib import Path

import pytest

from assistant.cli import main

ROOT = Path(__file__).resolve().parents[1]
SCRIPTED_STDIN = {
    "chat": "go into the living room, the laptop is on the dinner table\n",
    "teach": "w 2\nq\n",
}


def readme_commands() -> list[list[str]]:
    """The ``assistant …`` lines of README.md's code blocks, split as a shell would."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    commands = []
    for block in re.findall(r"^```(?:sh|bash|console)?\n(.*?)^```", text, flags=re.S | re.M):
        for line in block.splitlines():
            words = shlex.split(line, comments=True)
            if words and words[0] == "assistant":
                commands.append(words[1:])
    return commands


def test_the_readme_has_the_commands_we_expect():
    commands = readme_commands()
    names = [c[0] for c in commands]
    for name in ("world", "sim", "parse", "relations", "perceive", "where", "fetch", "teach", "chat", "eval"):
        assert name in names
    from assistant.cli.eval import EVALUATIONS

    shown = {c[1] for c in commands if c[0] == "eval" and "--quick" in c}
    assert shown == set(EVALUATIONS), "the README shows every evaluation, each as eval NAME --quick"


@pytest.fixture(scope="module")
def workspace(tmp_path_factory):
    """One scratch folder for all README commands (later ones read what earlier ones wrote)."""
    return tmp_path_factory.mktemp("readme")


@pytest.mark.slow
@pytest.mark.parametrize("argv", readme_commands(), ids=lambda argv: " ".join(argv)[:60])
def test_each_readme_command_works_as_written(argv, workspace, monkeypatch, capsys):
    monkeypatch.chdir(workspace)
    monkeypatch.setenv("ASSISTANT_DATA", str(workspace / "data"))
    monkeypatch.setattr(sys, "stdin", io.StringIO(SCRIPTED_STDIN.get(argv[0], "")))
    code = main(argv)
    out = capsys.readouterr()
    ok_codes = (0, 1) if argv[0] == "doctor" else (0,)  # doctor: 1 = something to fix, said
    assert code in ok_codes and "Traceback" not in out.err, f"exit {code}: {out.err.strip()[-600:]}"
    if argv[0] == "perceive" and "--world" in argv:
        assert '"category": "couch"' in out.out, "the README's perceive pose sees the couch"
    if argv[0] == "chat":
        assert "I don't know the word" not in out.out and "laptop" in out.out, out.out
    if argv[0] == "eval":
        assert "not the reported figures" in out.out, "a quick evaluation says its figures are not the reported ones"

"""Every ``assistant`` command in README.md's code blocks works as written.

Commands run in-process (``assistant.cli.main``) in a scratch folder with a scratch data folder,
in README order (``sim render`` writes the ``frame.png`` that ``perceive --depth`` reads). The
interactive ones get a scripted stdin: ``chat`` one README sentence then end of input, ``teach``
a few keys. ``assistant eval {a,b,…}`` names every evaluation; each full evaluation takes
minutes, so here each is only checked to exist (``--help``); their own tests run them.
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


def expand(argv: list[str]) -> list[list[str]]:
    """``eval {a,b}`` → ``eval a --help``, ``eval b --help`` (see the module docstring)."""
    braces = [i for i, word in enumerate(argv) if re.fullmatch(r"\{[\w,-]+\}", word)]
    if not braces:
        return [argv]
    i = braces[0]
    return [argv[:i] + [name] + argv[i + 1:] + ["--help"] for name in argv[i][1:-1].split(",")]


def test_the_readme_has_the_commands_we_expect():
    names = [c[0] for c in readme_commands()]
    for name in ("world", "sim", "parse", "relations", "perceive", "where", "fetch", "teach", "chat", "eval"):
        assert name in names


@pytest.mark.slow
def test_every_readme_command_works_as_written(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("ASSISTANT_DATA", str(tmp_path / "data"))
    failures = []
    for command in readme_commands():
        for argv in expand(command):
            monkeypatch.setattr(sys, "stdin", io.StringIO(SCRIPTED_STDIN.get(argv[0], "")))
            try:
                code = main(argv)
            except SystemExit as exit_:  # --help
                code = exit_.code
            out = capsys.readouterr()
            ok_codes = (0, 1) if argv[0] == "doctor" else (0,)  # doctor: 1 = something to fix, said
            if code not in ok_codes or "Traceback" in out.err:
                failures.append(f"assistant {shlex.join(argv)} → {code}: {out.err.strip()[-300:]}")
            if argv[0] == "perceive" and "--world" in argv:
                assert '"category": "couch"' in out.out, "the README's perceive pose sees the couch"
            if argv[0] == "chat":
                assert "I don't know the word" not in out.out and "laptop" in out.out, out.out
    assert not failures, "\n".join(failures)

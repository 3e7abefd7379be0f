"""Progress of long work: tqdm on a terminal (a ticking clock for steps without a count), lines
in a log, nothing with --json."""

from __future__ import annotations

import io
import time

import assistant.progress as progress


class FakeTerminal(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_an_uncounted_step_keeps_ticking_on_a_terminal():
    screen = FakeTerminal()
    progress.set_hook(progress.TerminalProgress(screen))
    try:
        with progress.working("training the tagger"):
            time.sleep(0.3)
            first = screen.getvalue()
            time.sleep(1.3)  # no call in between: the ticker redraws the elapsed time
            later = screen.getvalue()
    finally:
        progress.set_hook(None)
    assert "training the tagger" in first and len(later) > len(first)
    assert "00:01" in later


def test_a_counted_stage_shows_how_far():
    screen = FakeTerminal()
    progress.set_hook(progress.TerminalProgress(screen))
    try:
        assert list(progress.counted(range(4), "policy models")) == [0, 1, 2, 3]
    finally:
        progress.set_hook(None)
    assert "policy models" in screen.getvalue() and "4/4" in screen.getvalue()


def test_json_is_quiet_and_a_log_gets_lines():
    assert progress.for_terminal(json_output=True, stream=FakeTerminal()) is progress.quiet
    log = io.StringIO()
    hook = progress.for_terminal(json_output=False, stream=log)
    hook("fetch trials", 2, 8)
    assert log.getvalue() == "fetch trials (2/8)\n"
    assert isinstance(progress.for_terminal(False, FakeTerminal()), progress.TerminalProgress)


def test_the_default_outside_a_terminal_says_nothing(capsys):
    progress.set_hook(None)
    with progress.working("something long"):
        pass
    assert capsys.readouterr().err == ""


def test_a_heartbeat_speaks_after_its_delay_and_stands_aside_for_a_progress_line():
    screen = FakeTerminal()
    beat = progress.Heartbeat("assistant fetch", delay_s=0.2, stream=screen).start()
    time.sleep(0.1)
    assert screen.getvalue() == ""  # quick commands show nothing
    time.sleep(1.0)
    assert "assistant fetch" in screen.getvalue()
    other = progress.TerminalProgress(FakeTerminal())
    other("training the tagger")
    time.sleep(0.8)
    size = len(screen.getvalue())
    time.sleep(1.0)
    assert len(screen.getvalue()) == size  # silent while the other line ticks
    other.close()
    beat.stop()

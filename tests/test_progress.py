"""Progress of long work: tqdm on a terminal (a ticking clock for steps without a count); nothing
with --json or when stderr is not a terminal."""

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


def test_a_counted_stage_keeps_ticking_while_one_step_takes_long():
    screen = FakeTerminal()
    hook = progress.TerminalProgress(screen)
    try:
        hook("fetch trials", 3, 128)
        time.sleep(0.3)
        first = screen.getvalue()
        time.sleep(1.3)  # one trial takes long: no call in between
        later = screen.getvalue()
    finally:
        hook.close()
    assert "3/128" in first and len(later) > len(first) and "00:01" in later


def test_a_counted_stage_shows_how_far():
    screen = FakeTerminal()
    progress.set_hook(progress.TerminalProgress(screen))
    try:
        assert list(progress.counted(range(4), "policy models")) == [0, 1, 2, 3]
    finally:
        progress.set_hook(None)
    assert "policy models" in screen.getvalue() and "4/4" in screen.getvalue()


def test_the_rule_shows_progress_on_a_terminal_only_and_never_with_json():
    assert isinstance(progress.hook_for(False, FakeTerminal()), progress.TerminalProgress)
    assert progress.hook_for(True, FakeTerminal()) is progress.quiet  # --json
    assert progress.hook_for(False, io.StringIO()) is progress.quiet  # a pipe or a log
    closed = io.StringIO()
    closed.close()  # isatty() raises on a closed stream
    assert progress.hook_for(False, closed) is progress.quiet


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


def test_a_heartbeat_can_count_from_an_earlier_start_such_as_the_process_s():
    screen = FakeTerminal()
    beat = progress.Heartbeat("assistant parse", delay_s=2.0, stream=screen, since=time.monotonic() - 1.9).start()
    time.sleep(0.6)
    beat.stop()
    assert "assistant parse" in screen.getvalue() and "00:02" in screen.getvalue()  # the clock counts from then
    assert 0.0 < progress.process_age() < 24 * 3600

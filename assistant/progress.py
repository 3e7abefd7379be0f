"""Progress of long work, shown to the person waiting: what is being done and how far along.

Two kinds of waits: a counted stage ("fetch trials 12/128") and a step of unknown length
("training the language models on first use"). :class:`TerminalProgress` shows both with
``tqdm`` on a terminal — a bar with a count and a rate, or the step's elapsed seconds — redrawn
every half second so a long step never looks hung; :func:`quiet` says nothing.

**The rule, kept here only** (:func:`shows_progress`, applied by :func:`hook_for`): progress is
shown when stderr is a terminal, and is quiet with ``--json`` (its stdout is read by a program)
or when stderr is not a terminal (a pipe, a log, a test: no bars or control characters in
them). The command line applies it once per command (:func:`set_hook`); every evaluation's
progress callback comes from it too (``assistant.cli.common.progress_for``); the chat's status
line applies it to the chat's output (:mod:`assistant.dialogue.statusline`). Library code reports long steps through
:func:`working` and :func:`counted`, which use the process's hook (by default the rule applied to
the process's stderr). A hook has the signature of :class:`assistant.eval.progress.Progress`:
``hook(what, done=None, total=None)``.
"""

from __future__ import annotations

import contextlib
import os
import sys
import threading
import time
from collections.abc import Callable, Iterable, Iterator
from typing import TypeVar

T = TypeVar("T")
Hook = Callable[..., None]

#: how often an uncounted step's elapsed time is redrawn on a terminal (seconds)
TICK_S = 0.5


def quiet(what: str, done: int | None = None, total: int | None = None) -> None:
    """A hook that says nothing."""


class TerminalProgress:
    """tqdm on a terminal: a bar per counted stage, a clock for an uncounted step; both redrawn
    every :data:`TICK_S` so their elapsed time ticks even while one step takes long.

    A call with a new ``what`` ends the previous stage (its bar stays on screen, finished); a
    call with the same ``what`` moves its bar. :meth:`close` ends the last one.
    """

    def __init__(self, stream=None):
        self.stream = stream
        self._bar = None
        self._what: str | None = None
        self._lock = threading.Lock()
        self._ticker: threading.Thread | None = None
        self._stop = threading.Event()

    def __call__(self, what: str, done: int | None = None, total: int | None = None) -> None:
        from tqdm import tqdm

        with self._lock:
            if what != self._what or self._bar is None or (total is not None and self._bar.total != total):
                self._end()
                self._what = what
                counted = total is not None
                self._bar = tqdm(total=total, desc=what, file=self.stream or sys.stderr, leave=True,
                                 dynamic_ncols=True, mininterval=0.2,
                                 bar_format=None if counted else "{desc} … {elapsed}")
                _count_bar(+1)
                self._start_ticker()  # a counted stage's clock ticks too: one step may take long
            if done is not None:
                self._bar.n = done
                self._bar.refresh()

    def _start_ticker(self) -> None:
        self._stop = threading.Event()
        stop, bar = self._stop, self._bar

        def tick() -> None:
            while not stop.wait(TICK_S):
                with contextlib.suppress(Exception):
                    bar.refresh()

        self._ticker = threading.Thread(target=tick, name="progress-ticker", daemon=True)
        self._ticker.start()

    def _end(self) -> None:
        self._stop.set()
        if self._ticker is not None:
            self._ticker.join(timeout=1.0)
            self._ticker = None
        if self._bar is not None:
            self._bar.close()
            self._bar = None
            _count_bar(-1)
        self._what = None

    def close(self) -> None:
        with self._lock:
            self._end()


_hook: Hook | None = None
_bars_lock = threading.Lock()


def _count_bar(change: int) -> None:
    global _open_bars
    with _bars_lock:
        _open_bars += change
_open_bars = 0  # progress lines on screen now (a heartbeat stands aside while there are any)


def set_hook(hook: Hook | None) -> None:
    """Where :func:`working` and :func:`counted` report (None: the default, see the module)."""
    global _hook
    _hook = hook


def is_terminal(stream) -> bool:
    """Whether ``stream`` is a terminal a person watches (False for a closed or replaced one)."""
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):
        return False


def shows_progress(json_output: bool = False, stream=None) -> bool:
    """The one rule for where progress goes (see the module): on ``stream`` (stderr) when it is a
    terminal, never with ``json_output``. :func:`hook_for` applies it; so does the chat's status
    line (:mod:`assistant.dialogue.statusline`), which ticks at its prompt on stdout."""
    return not json_output and is_terminal(stream or sys.stderr)


def hook_for(json_output: bool = False, stream=None) -> Hook:
    """A :class:`TerminalProgress` on ``stream`` (stderr) where :func:`shows_progress`, else
    :func:`quiet`."""
    stream = stream or sys.stderr
    return TerminalProgress(stream) if shows_progress(json_output, stream) else quiet


def installed_hook() -> Hook | None:
    """The hook :func:`set_hook` gave (the command line's, for the command running), or None."""
    return _hook


def current_hook() -> Hook:
    """The hook :func:`set_hook` gave, else the rule applied to stderr."""
    return _hook if _hook is not None else hook_for()


@contextlib.contextmanager
def working(what: str) -> Iterator[None]:
    """Report a step of unknown length (``with working("training the tagger"): …``); on a
    terminal its elapsed time ticks until it ends."""
    hook = current_hook()
    hook(what)
    try:
        yield
    finally:
        if hasattr(hook, "close"):
            hook.close()  # a terminal's bar stays, showing the time it took


def counted(items: Iterable[T], what: str, total: int | None = None) -> Iterator[T]:
    """Iterate ``items``, reporting ``what`` with how many are done (of ``total`` or ``len``)."""
    hook = current_hook()
    if total is None:
        try:
            total = len(items)  # type: ignore[arg-type]
        except TypeError:
            total = None
    hook(what, 0, total)
    try:
        for number, item in enumerate(items, start=1):
            yield item
            hook(what, number, total)
    finally:
        if hasattr(hook, "close"):
            hook.close()


def process_age() -> float:
    """Seconds since this process started (Linux: from /proc; elsewhere 0.0)."""
    try:
        with open("/proc/self/stat", encoding="ascii") as stat, open("/proc/uptime", encoding="ascii") as uptime:
            started_ticks = int(stat.read().rpartition(")")[2].split()[19])  # field 22, after the name
            now = float(uptime.read().split()[0])
        return max(0.0, now - started_ticks / os.sysconf("SC_CLK_TCK"))
    except (OSError, ValueError, IndexError):
        return 0.0


class Heartbeat:
    """For a command that may work a while before it prints: once ``delay_s`` have passed since
    ``since`` (a :func:`time.monotonic` time; default when :meth:`start` is called) without an
    end, a terminal line ``what … 00:05`` ticks until :meth:`stop` (then it is erased), so no
    wait is silent. The command line counts from the process's start (:func:`process_age`):
    Python's start-up and imports take a second or more on a loaded machine. Does nothing when
    ``stream`` is not a terminal."""

    def __init__(self, what: str, delay_s: float = 2.0, stream=None, since: float | None = None):
        self.what = what
        self.delay_s = delay_s
        self.stream = stream or sys.stderr
        self.since = since
        self._done = threading.Event()
        self._thread: threading.Thread | None = None

    def start(self) -> "Heartbeat":
        if is_terminal(self.stream):
            started = time.monotonic() if self.since is None else self.since
            self._thread = threading.Thread(target=self._run, args=(started,), name="progress-heartbeat",
                                            daemon=True)
            self._thread.start()
        return self

    def _run(self, started: float) -> None:
        from tqdm import tqdm

        if self._done.wait(max(0.0, started + self.delay_s - time.monotonic())):
            return
        bar = None
        while True:
            if _open_bars > 0:  # another progress line says what is going on
                if bar is not None:
                    bar.close()
                    bar = None
            else:
                if bar is None:  # (delay: not drawn before its clock is set to the process's start)
                    bar = tqdm(total=None, desc=self.what, file=self.stream, leave=False, dynamic_ncols=True,
                               bar_format="{desc} … {elapsed}", delay=1e-6)
                    bar.start_t -= time.monotonic() - started
                with contextlib.suppress(Exception):
                    bar.refresh()
            if self._done.wait(TICK_S):
                break
        if bar is not None:
            bar.close()

    def stop(self) -> None:
        self._done.set()
        if self._thread is not None:
            self._thread.join(timeout=1.0)

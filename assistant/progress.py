"""Progress of long work, shown to the person waiting: what is being done and how far along.

Two kinds of waits: a counted stage ("fetch trials 12/128") and a step of unknown length
("training the language models on first use"). :class:`TerminalProgress` shows both with
``tqdm`` on a terminal — a bar with a count and a rate, or the step's elapsed seconds ticking
every half second so a long step never looks hung. :class:`LineProgress` writes one line per
call (a log, a pipe); :func:`quiet` says nothing.

Library code reports long steps through :func:`working` and :func:`counted`, which use the
process's hook: by default a terminal display when stderr is a terminal and nothing otherwise;
the command line sets it once (:func:`set_hook`): quiet with ``--json``. The hook has the
signature of :class:`assistant.eval.progress.Progress`: ``hook(what, done=None, total=None)``.
"""

from __future__ import annotations

import contextlib
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


class LineProgress:
    """One line per call on ``stream`` (stderr): ``what``, then ``(done/total)`` if counted."""

    def __init__(self, stream=None):
        self.stream = stream

    def __call__(self, what: str, done: int | None = None, total: int | None = None) -> None:
        stream = self.stream or sys.stderr
        count = "" if done is None else f" ({done}/{total})" if total is not None else f" ({done})"
        stream.write(f"{what}{count}\n")
        stream.flush()

    def close(self) -> None:
        pass


class TerminalProgress:
    """tqdm on a terminal: a bar per counted stage, a ticking clock for an uncounted step.

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
                if not counted:
                    self._start_ticker()
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


def current_hook() -> Hook:
    if _hook is not None:
        return _hook
    try:
        terminal = sys.stderr.isatty()
    except (AttributeError, ValueError):  # a closed or replaced stderr
        terminal = False
    return TerminalProgress() if terminal else quiet


def for_terminal(json_output: bool, stream=None) -> Hook:
    """The hook a command uses: quiet with ``--json``; tqdm on a terminal; lines otherwise."""
    if json_output:
        return quiet
    stream = stream or sys.stderr
    try:
        terminal = stream.isatty()
    except (AttributeError, ValueError):
        terminal = False
    return TerminalProgress(stream) if terminal else LineProgress(stream)


@contextlib.contextmanager
def working(what: str) -> Iterator[None]:
    """Report a step of unknown length (``with working("training the tagger"): …``); on a
    terminal its elapsed time ticks until it ends."""
    hook = current_hook()
    started = time.monotonic()
    hook(what)
    try:
        yield
    finally:
        if isinstance(hook, LineProgress):
            hook(f"{what}: done in {time.monotonic() - started:.1f} s")
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


class Heartbeat:
    """For a command that may work a while before it prints: after ``delay_s`` without an end,
    a terminal line ``what … 00:05`` ticks until :meth:`stop` (then it is erased), so no wait
    is silent. Does nothing when ``stream`` is not a terminal."""

    def __init__(self, what: str, delay_s: float = 2.0, stream=None):
        self.what = what
        self.delay_s = delay_s
        self.stream = stream or sys.stderr
        self._done = threading.Event()
        self._thread: threading.Thread | None = None

    def start(self) -> "Heartbeat":
        try:
            terminal = self.stream.isatty()
        except (AttributeError, ValueError):
            terminal = False
        if terminal:
            self._thread = threading.Thread(target=self._run, name="progress-heartbeat", daemon=True)
            self._thread.start()
        return self

    def _run(self) -> None:
        from tqdm import tqdm

        started = time.monotonic()
        if self._done.wait(self.delay_s):
            return
        bar = None
        while True:
            if _open_bars > 0:  # another progress line says what is going on
                if bar is not None:
                    bar.close()
                    bar = None
            else:
                if bar is None:
                    bar = tqdm(total=None, desc=self.what, file=self.stream, leave=False, dynamic_ncols=True,
                               bar_format="{desc} … {elapsed}")
                    bar.start_t -= time.monotonic() - started  # count from the command's start
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

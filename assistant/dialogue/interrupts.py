"""Ctrl-C for the chat, handled the moment it arrives — even while readline is busy.

Python runs a signal handler between bytecodes of the main thread. While ``input()`` waits in
readline's ``select()`` a SIGINT interrupts the wait and the handler runs at once; but a SIGINT
that lands in the instant after the prompt is drawn and before readline blocks is only handled
when the next line is typed (the signal does not interrupt a ``select()`` that has not started).

:class:`InterruptWatcher` does not depend on the main thread for that. The interpreter's C-level
signal handler writes each signal's number to a pipe (:func:`signal.set_wakeup_fd`) the
instant the signal arrives, and a watcher thread reading that pipe calls ``on_interrupt()``
right away — stopping the robot needs no main-thread cooperation. The Python-level SIGINT
handler does nothing, so no ``KeyboardInterrupt`` lands in the middle of other code.

When the main thread must leave a blocking read (the second Ctrl-C), :meth:`release_read` sends
it SIGUSR1 until it has left: the SIGUSR1 handler raises ``KeyboardInterrupt`` while
``reading()`` says the main thread is in (or about to enter) its read, which makes ``input()``
return; a nudge that lands in the window before ``select()`` is simply repeated 50 ms later.
"""

from __future__ import annotations

import os
import signal
import threading
import time
from collections.abc import Callable

#: the byte the watcher's own stop request writes to the pipe (no signal has number 0)
_STOP = 0


class InterruptWatcher:
    """Watches for SIGINT from a thread; use as a context manager in the main thread.

    ``on_interrupt()``: called in the watcher thread for every SIGINT, as it arrives; returns
    True when the main thread should leave its blocking read (then :meth:`release_read` runs).
    ``reading()``: whether the main thread is in (or entering) a blocking read that a
    ``KeyboardInterrupt`` may abort. ``nudge_s``: seconds between two SIGUSR1 nudges;
    ``give_up_s``: how long :meth:`release_read` keeps nudging.
    """

    def __init__(self, on_interrupt: Callable[[], bool], reading: Callable[[], bool],
                 nudge_s: float = 0.05, give_up_s: float = 5.0):
        self.on_interrupt = on_interrupt
        self.reading = reading
        self.nudge_s = nudge_s
        self.give_up_s = give_up_s
        self.active = False
        self._thread: threading.Thread | None = None
        self._main = threading.main_thread().ident
        self._previous: dict = {}
        self._pipe: tuple[int, int] | None = None

    # ----------------------------------------------------------------- set-up
    def __enter__(self) -> "InterruptWatcher":
        self.start()
        return self

    def __exit__(self, *exc) -> None:
        self.stop()

    def start(self) -> bool:
        """Install the handlers and the watcher (main thread only; False elsewhere, e.g. a test
        that runs the chat in a thread — Ctrl-C then keeps Python's default behaviour)."""
        if threading.current_thread() is not threading.main_thread() or self.active:
            return False
        r, w = os.pipe()
        os.set_blocking(w, False)
        self._pipe = (r, w)
        self._previous["wakeup"] = signal.set_wakeup_fd(w, warn_on_full_buffer=False)
        self._previous[signal.SIGINT] = signal.signal(signal.SIGINT, self._on_sigint)
        self._previous[signal.SIGUSR1] = signal.signal(signal.SIGUSR1, self._on_nudge)
        self._thread = threading.Thread(target=self._watch, name="assistant-ctrl-c", daemon=True)
        self.active = True
        self._thread.start()
        return True

    def stop(self) -> None:
        """Restore the previous handlers and end the watcher thread."""
        if not self.active:
            return
        self.active = False
        signal.set_wakeup_fd(self._previous.pop("wakeup"))
        for signum in (signal.SIGINT, signal.SIGUSR1):
            signal.signal(signum, self._previous.pop(signum))
        r, w = self._pipe
        try:
            os.write(w, bytes([_STOP]))
        except OSError:
            pass
        self._thread.join(2.0)
        os.close(w)
        os.close(r)
        self._pipe = None

    # ----------------------------------------------------------------- handlers
    @staticmethod
    def _on_sigint(signum, frame) -> None:
        """Main-thread SIGINT handler: nothing — the watcher thread does the work."""

    def _on_nudge(self, signum, frame) -> None:
        if self.reading():
            raise KeyboardInterrupt

    def _watch(self) -> None:
        r = self._pipe[0]
        while True:
            try:
                data = os.read(r, 64)
            except OSError:
                return
            if not data:
                return
            for byte in data:
                if byte == _STOP:
                    return
                if byte == signal.SIGINT:
                    try:
                        leave = self.on_interrupt()
                    except Exception:  # a front-end problem must not end Ctrl-C handling
                        leave = False
                    if leave:
                        self.release_read()

    def release_read(self) -> bool:
        """Get the main thread out of its blocking read; True once it has left (or was not in
        one)."""
        deadline = time.monotonic() + self.give_up_s
        while self.reading() and self.active:
            if time.monotonic() > deadline:
                return False
            try:
                signal.pthread_kill(self._main, signal.SIGUSR1)
            except (OSError, ProcessLookupError):
                return False
            time.sleep(self.nudge_s)
        return True

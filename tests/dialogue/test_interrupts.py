"""The Ctrl-C watcher: SIGINTs are handled in a thread as they arrive, and the main thread is
got out of a blocking read on request (real signals to this process)."""

import os
import signal
import threading
import time

import pytest

from assistant.dialogue.interrupts import InterruptWatcher


def test_sigint_is_handled_while_main_thread_blocks_then_read_is_released():
    calls = []
    reading = [False]

    def on_interrupt():
        calls.append(time.monotonic())
        return len(calls) >= 2  # the second Ctrl-C leaves

    r, w = os.pipe()
    watcher = InterruptWatcher(on_interrupt, lambda: reading[0])
    assert watcher.start()
    try:
        def press_twice():
            time.sleep(0.2)
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(0.2)
            os.kill(os.getpid(), signal.SIGINT)

        threading.Thread(target=press_twice, daemon=True).start()
        reading[0] = True
        started = time.monotonic()
        with pytest.raises(KeyboardInterrupt):
            os.read(r, 1)  # blocks: only the watcher's nudge ends it
        reading[0] = False
        assert len(calls) == 2 and time.monotonic() - started < 5.0
    finally:
        watcher.stop()
        os.close(r)
        os.close(w)
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler  # restored


def test_sigint_outside_a_read_raises_nothing_in_the_main_thread():
    calls = []
    with InterruptWatcher(lambda: calls.append(1) or False, lambda: False):
        os.kill(os.getpid(), signal.SIGINT)
        deadline = time.monotonic() + 2.0
        while not calls and time.monotonic() < deadline:
            time.sleep(0.01)  # the handler runs here: it must not raise
    assert calls == [1]


def test_not_started_outside_the_main_thread():
    out = []
    t = threading.Thread(target=lambda: out.append(InterruptWatcher(lambda: False, lambda: False).start()))
    t.start()
    t.join()
    assert out == [False]

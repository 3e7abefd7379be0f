"""The chat's status line: while the robot carries out a task, a line just above the prompt says
what it is doing and for how long, redrawn every second, so the person typing never faces a
silent screen between the robot's sentences (the robot's work between two events takes 8–21 s
on a loaded machine).

Where it is shown follows :func:`assistant.progress.shows_progress` applied to the chat's
output: on a terminal only; nothing in a pipe, a log or a transcript, and never spoken (the
robot's sentences are the worker's ``say``). The line is drawn without disturbing ``readline``:
the first draw moves the prompt (and what has been typed) one line down, as a printed sentence
does; later draws save the cursor, rewrite the line above and restore the cursor, so typing,
the cursor and line editing carry on. A sentence printed meanwhile takes the status line's place
(:meth:`StatusLine.erase`); the next tick draws it again below that sentence.
"""

from __future__ import annotations

import shutil
import threading
from collections.abc import Callable

__all__ = ["StatusLine", "TICK_S", "status_text"]

#: how often the status line is redrawn (its clock shows whole seconds)
TICK_S = 1.0

_SAVE, _RESTORE, _UP, _CLEAR, _CLEAR_BELOW = "\0337", "\0338", "\033[A", "\r\033[K", "\033[J"


def _up(rows: int) -> str:
    """The cursor ``rows`` rows up (its column kept)."""
    return _UP if rows == 1 else f"\033[{rows}A"


def status_text(doing: str, seconds: float, width: int = 200) -> str:
    """``(looking around the kitchen … 0:12 — "stop" stops me)``, cut to fit ``width`` columns
    (a wrapped line would break the redraw)."""
    minutes, secs = divmod(int(seconds), 60)
    text = f"({doing} … {minutes}:{secs:02d} — \"stop\" stops me)"
    return text if len(text) < width else text[:max(0, width - 2)] + "…"


class StatusLine:
    """The ticking line above ``prompt`` on ``out``.

    ``activity()``: (what the robot is doing, seconds) while a task runs, else None
    (:attr:`~assistant.dialogue.DialogueManager.activity`); ``at_prompt()``: whether the prompt
    is on screen waiting for a line; ``typed()``: what has been typed at it; ``lock``: the lock
    every write to ``out`` holds. Use :meth:`erase` before printing above the prompt and
    :meth:`left_prompt` when a typed line ends (the prompt moved down).
    """

    def __init__(self, out, lock, prompt: str, activity: Callable[[], tuple[str, float] | None],
                 at_prompt: Callable[[], bool], typed: Callable[[], str] = lambda: "",
                 columns: Callable[[], int] = lambda: shutil.get_terminal_size((200, 40)).columns):
        self.out, self.lock, self.prompt = out, lock, prompt
        self.activity, self.at_prompt, self.typed, self.columns = activity, at_prompt, typed, columns
        self.drawn = False
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    def tick(self) -> bool:
        """Draw the line once if the robot is working and the prompt waits; True when drawn."""
        with self.lock:
            now = self.activity()
            if now is None or not self.at_prompt():
                return False
            text = status_text(*now, width=self.columns())
            if self.drawn:  # rewrite the line above the prompt, the cursor back where it was
                self.out.write(_SAVE + _up(self._rows_above_cursor() + 1) + _CLEAR + text + _RESTORE)
            else:  # take the prompt's line, the prompt and what was typed one line down
                self.out.write(self._clear_prompt() + text + "\n" + self.prompt + self.typed())
                self.drawn = True
            self.out.flush()
            return True

    def erase(self) -> str:
        """What to write (under ``lock``) before printing a line above the prompt: the cursor to
        the start of the status line when it is drawn, else to the start of the prompt's line."""
        if not self.drawn:
            return self._clear_prompt()
        self.drawn = False
        rows = self._rows_above_cursor()
        return _CLEAR + _UP + _CLEAR if rows == 0 else "\r" + _up(rows + 1) + _CLEAR_BELOW

    def _clear_prompt(self) -> str:
        """The cursor to the start of the prompt's first row, that row and any it wraps onto
        cleared."""
        rows = self._rows_above_cursor()
        return _CLEAR if rows == 0 else "\r" + _up(rows) + _CLEAR_BELOW

    def _rows_above_cursor(self) -> int:
        """Screen rows of the prompt's line above the cursor: a typed line longer than the
        terminal is wide wraps, and the status line is that many rows higher (the cursor is
        taken to be at the end of what was typed; a full row keeps it on that row)."""
        used = len(self.prompt) + len(self.typed())
        return max(0, used - 1) // max(1, self.columns())

    def left_prompt(self) -> None:
        """A typed line ended: the status line (if drawn) is no longer just above the prompt."""
        with self.lock:
            self.drawn = False

    def start(self) -> "StatusLine":
        self._stop.clear()
        self._thread = threading.Thread(target=self._run, name="chat-status", daemon=True)
        self._thread.start()
        return self

    def _run(self) -> None:
        while not self._stop.wait(TICK_S):
            try:
                self.tick()
            except (OSError, ValueError):  # the terminal went away: the chat is ending
                return

    def stop(self) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=2.0)

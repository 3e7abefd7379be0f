"""The one progress hook of the evaluations.

An evaluation says what it is doing through a callback the caller supplies — ``progress(what,
done, total)``: ``what`` a short line ("fetch trials", "scene 3 …"), ``done`` and ``total`` how far
along a counted stage is (both ``None`` for a stage without a count). The evaluations never
write to a stream themselves; the command line decides where progress goes (stderr, a progress
bar, nowhere).
"""

from __future__ import annotations

from typing import Protocol


class Progress(Protocol):
    def __call__(self, what: str, done: int | None = None, total: int | None = None) -> None: ...


def no_progress(what: str, done: int | None = None, total: int | None = None) -> None:
    """The default hook: says nothing."""

"""Errors a user can act on.

Every error raised towards a person says what went wrong and what to do next. The command line
turns an :class:`AssistantError` into one line on stderr and exit status 2; the dialogue turns it
into a sentence. Nothing else in the product should need to catch bare ``Exception``.
"""

from __future__ import annotations

from collections.abc import Iterable


class AssistantError(Exception):
    """Base class of the errors meant for the person using the product."""


class UnknownNameError(AssistantError, KeyError):
    """A name (world, model, command, room…) that is not known; lists the known ones."""

    def __init__(self, kind: str, name: str, known: Iterable[str]):
        self.kind = kind
        self.name = name
        self.known = sorted(known)
        super().__init__(f"unknown {kind} {name!r}; known: {', '.join(self.known) or '(none)'}")

    def __str__(self) -> str:  # KeyError would otherwise quote the message
        return self.args[0]


class DataFileError(AssistantError, ValueError):
    """A data file (world, corpus, demonstration…) that cannot be read as it is.

    The message names the file, the section, the index and the key, e.g.
    ``apartment.yaml: furniture[3].yaw: expected a number, got 'north'``.
    """

    def __init__(self, path: str, where: str, problem: str):
        self.path = path
        self.where = where
        self.problem = problem
        location = f"{path}: {where}" if where else path
        super().__init__(f"{location}: {problem}")


class NotFittedError(AssistantError, ValueError, AttributeError):
    """A learned model (tagger, chunker, grounder, policy, generation model) used before it was
    trained. Also a :class:`ValueError` and :class:`AttributeError`, as scikit-learn's own
    ``NotFittedError`` is, so code written against scikit-learn's convention still catches it."""

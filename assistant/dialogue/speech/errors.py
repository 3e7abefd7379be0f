"""Errors of speech in and out, each saying what to do next (see :mod:`assistant.errors`)."""

from __future__ import annotations

from assistant.errors import AssistantError


class SpeechError(AssistantError):
    """Base class of the speech errors."""


class AudioFileError(SpeechError):
    """An audio file that cannot be used: missing, empty, corrupt, too long, only silence."""


class MicrophoneError(SpeechError):
    """No microphone, a busy one, or PortAudio missing; the chat goes on by text."""


class RecogniserError(SpeechError):
    """A recogniser that cannot start: an unknown engine, a missing or broken model."""


class SpeechOutputError(SpeechError):
    """Speech output that cannot be made: no espeak-ng, an unknown voice, an unwritable file."""


def require(module: str, install: str, error=SpeechError):
    """Import an optional speech library, or raise ``error`` with the line that installs it."""
    import importlib

    try:
        return importlib.import_module(module)
    except ImportError as exc:
        raise error(f"{module} is not available ({exc}); install it with: {install}") from None
    except OSError as exc:  # a wheel whose system library is missing (PortAudio, libsndfile)
        raise error(f"{module} cannot load its system library ({exc}); install it with: {install}") from None

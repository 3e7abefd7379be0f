"""Speech in and out, offline: recognisers (pocketsphinx, vosk) behind one interface, the home's
language model, audio files and the microphone, end-of-utterance detection, "Did you say …?",
speech out with pyttsx3 on espeak-ng, and barge-in ("stop"). See docs/speech.md.

* :func:`make_recogniser` — an engine by name; :class:`Recognition` — what it heard.
* :class:`Listener` — files or samples → :class:`Heard` (checks, endpoints, decoding).
* :class:`Speaker` — replies spoken and/or written to a WAV file.
* :class:`KeywordSpotter` — "stop" while the robot is busy.
* :class:`SpeechChat` — ``assistant chat --speech``.

Everything loads lazily: importing this package imports no speech library.
"""

from __future__ import annotations

import importlib

__all__ = ["Heard", "KeywordSpotter", "Listener", "Recognition", "Recogniser", "Speaker", "SpeechChat",
           "make_recogniser", "read_audio"]

_LAZY = {
    "Heard": "assistant.dialogue.speech.listener",
    "Listener": "assistant.dialogue.speech.listener",
    "KeywordSpotter": "assistant.dialogue.speech.keyword",
    "Recognition": "assistant.dialogue.speech.recogniser",
    "Recogniser": "assistant.dialogue.speech.recogniser",
    "make_recogniser": "assistant.dialogue.speech.recogniser",
    "Speaker": "assistant.dialogue.speech.tts",
    "SpeechChat": "assistant.dialogue.speech.session",
    "read_audio": "assistant.dialogue.speech.audio",
}


def __getattr__(name: str):
    if name in _LAZY:
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'assistant.dialogue.speech' has no attribute {name!r}")

"""Talking to the robot: a dialogue manager that routes each utterance to grounding and the
executor (fetch), to generation ("where is my X?"), to demonstration recording (teaching) or
answers it (control), asks when a command is ambiguous or incomplete, and remembers every
object the robot has seen.

* :class:`DialogueManager` — ``handle(text) -> Turn``; a fetch runs in a worker thread.
* :class:`Turn` — reply text, action, outcome, data (any front end can render it).
* :class:`ObjectMemory`, :class:`MemoryEntry` — the persisted object memory.
* :class:`Services` — the lazily built parser, describer and fetch runner.
* :func:`classify` — the deterministic intent rules.
"""

from __future__ import annotations

from assistant.dialogue.intents import Intent, classify, normalise
from assistant.dialogue.manager import HELP_TEXT, DialogueManager, Turn
from assistant.dialogue.memory import ObjectMemory, MemoryEntry, age_phrase, default_data_dir
from assistant.dialogue.services import FetchReport, Interrupted, Services, fetch_report

__all__ = ["HELP_TEXT", "DialogueManager", "FetchReport", "Intent", "Interrupted", "ObjectMemory",
           "Services", "MemoryEntry", "Turn", "age_phrase", "classify", "default_data_dir", "fetch_report",
           "normalise"]

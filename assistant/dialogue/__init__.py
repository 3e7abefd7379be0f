"""Talking to the robot: a dialogue manager that routes each utterance to grounding and the
executor (fetch), to generation ("where is my X?"), to demonstration recording (teaching) or
answers it (control), asks when a command is ambiguous or incomplete, and remembers every
object the robot has seen.

* :class:`DialogueManager` — ``handle(text) -> Turn``; a fetch runs in a worker thread.
* :class:`Turn` — reply text, action, outcome, data (any front end can render it).
* :class:`ObjectMemory`, :class:`MemoryEntry` — the persisted object memory.
* :class:`Services` — the lazily built parser, describer and the application layer's use cases
  (a fetch or a search ends in an :class:`assistant.app.Result`).
* :func:`classify` — the deterministic intent rules.
"""

from __future__ import annotations

from assistant.dialogue.intents import Intent, classify, normalise
from assistant.dialogue.manager import DialogueManager
from assistant.dialogue.memory import MemoryEntry, ObjectMemory, age_phrase, default_data_dir
from assistant.dialogue.services import Services
from assistant.dialogue.turns import HELP_TEXT, Turn

__all__ = ["HELP_TEXT", "DialogueManager", "Intent", "MemoryEntry", "ObjectMemory", "Services", "Turn",
           "age_phrase", "classify", "default_data_dir", "normalise"]

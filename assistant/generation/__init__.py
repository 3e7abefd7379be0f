""""Where is my X?": content selection and surface realization (dissertation chapter 6).

* :class:`Describer` — a sighting and the environment model in, a short human-like
  description out (static, or how-to-find from the listener's pose).
* :class:`GenerationModel`, :func:`load_generation_model` — co-occurrence weights, chunk texts
  ``P(text, type | RDT)`` and the six chunk relations learned from the annotated corpus.
* :func:`select_content` (equation 2, exact over subsets), :func:`realize` (Algorithm 1).
* :meth:`Describer.describe_search` composes the answer from the environment model the robot's
  search (:class:`~assistant.executor.search.SearchTask`) built.
* :func:`oracle_sighting` and :func:`oracle_environment` read a
  :class:`~assistant.perception.objects.Sighting` and the furniture from the world file (the labelled ``oracle`` search, and
  the evaluation's ground truth).
"""

from __future__ import annotations

import importlib

from assistant.generation.types import (
    STYLES,
    ChunkNode,
    ContentNode,
    GeneratedDescription,
)

__all__ = [
    "STYLES", "ChunkNode", "ContentNode", "GeneratedDescription",
    # lazily imported
    "ALPHA", "Candidate", "Describer", "GenerationModel", "GenerationModelNotFittedError",
    "candidate_nodes", "is_are", "it_them", "known_objects", "load_generation_model", "not_found_description",
    "some",
    "objective_values", "OracleCase", "oracle_cases", "oracle_environment", "oracle_sighting", "realize", "repeated_phrases",
    "route_nodes", "select_content", "style_for_question",
    "room_only_description",
]

_LAZY = {
    "ALPHA": "assistant.generation.content",
    "Candidate": "assistant.generation.content",
    "candidate_nodes": "assistant.generation.content",
    "objective_values": "assistant.generation.content",
    "select_content": "assistant.generation.content",
    "Describer": "assistant.generation.describer",
    "known_objects": "assistant.generation.describer",
    "not_found_description": "assistant.generation.describer",
    "some": "assistant.generation.describer",
    "is_are": "assistant.generation.describer",
    "it_them": "assistant.generation.describer",
    "OracleCase": "assistant.generation.describer",
    "oracle_cases": "assistant.generation.describer",
    "oracle_environment": "assistant.generation.describer",
    "oracle_sighting": "assistant.generation.describer",
    "style_for_question": "assistant.generation.describer",
    "GenerationModel": "assistant.generation.model",
    "GenerationModelNotFittedError": "assistant.generation.model",
    "load_generation_model": "assistant.generation.model",
    "realize": "assistant.generation.realize",
    "repeated_phrases": "assistant.generation.realize",
    "route_nodes": "assistant.generation.route",
    "room_only_description": "assistant.generation.describer",
}


def __getattr__(name: str):
    if name in _LAZY:
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'assistant.generation' has no attribute {name!r}")

"""Chunk tree → grounding plan: target room, RDT nodes, target object (dissertation 4.3, 4.4).

Two grounders share one interface (``fit(records, groundings)``, ``ground(records)``,
``accuracy(gold)``): :class:`ScoredGrounder`, the weighted-Levenshtein template scorer of
dissertation 4.3 II.C, and :class:`LearnedGrounder`, per-field scikit-learn classifiers over
chunk-type and word features after 4.4. :func:`assemble_plan` turns grounded chunks into a
:class:`GroundingPlan`; :class:`CommandParser` runs the whole way from text.
"""

from assistant.grounding.base import COMMAND, BaseGrounder, GrounderNotFittedError, grounding_accuracy
from assistant.grounding.combined import CombinedGrounder
from assistant.grounding.labels import (
    ChunkGroundingFile,
    attach_structure,
    parse_content,
    read_chunk_groundings,
    records_from_tree,
)
from assistant.grounding.learned import LearnedGrounder
from assistant.grounding.parser import CommandParser, ParseResult
from assistant.grounding.plan import FLAG_HELP, assemble_plan
from assistant.grounding.scored import ScoredGrounder
from assistant.grounding.training import DEFAULT_GROUNDER, GROUNDERS, load_labels, train_grounder
from assistant.grounding.types import (
    FIELDS,
    RDT,
    ChunkGrounding,
    ChunkRecord,
    GroundingPlan,
    LabelledCommand,
    RDTNode,
)
from assistant.grounding.vocabulary import DIRECTIONS, NO_TARGET, STRUCTURE_REFERENCES, canonical_tokens

__all__ = [
    "COMMAND", "DEFAULT_GROUNDER", "DIRECTIONS", "FIELDS", "FLAG_HELP", "GROUNDERS", "NO_TARGET",
    "RDT", "STRUCTURE_REFERENCES", "BaseGrounder", "ChunkGrounding", "ChunkGroundingFile",
    "ChunkRecord", "CombinedGrounder", "CommandParser", "GrounderNotFittedError", "GroundingPlan", "LabelledCommand",
    "LearnedGrounder", "ParseResult", "RDTNode", "ScoredGrounder", "assemble_plan",
    "attach_structure", "canonical_tokens", "grounding_accuracy", "load_labels", "parse_content",
    "read_chunk_groundings", "records_from_tree", "train_grounder",
]

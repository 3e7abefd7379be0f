"""Words → tokens → POS tags → nested semantic chunks → a chunk tree (dissertation 4.2).

Heavy parts (NLTK, CRFsuite, scikit-learn) load only when the corpus reader, the tagger or
the pipeline is first used, so ``import assistant.language`` stays cheap.
"""

from __future__ import annotations

import importlib

from assistant.language.tokenize import tokenize
from assistant.language.tree import CHUNK_LABELS, OUTSIDE, Chunk, ChunkTree, Token

__all__ = [
    "CHUNK_LABELS", "OUTSIDE", "Chunk", "ChunkTree", "Token", "tokenize",
    # lazily imported
    "Analysis", "LanguageModel", "NestedChunker", "SemanticPosTagger", "CorpusReadResult",
    "Description", "default_corpus_paths", "read_corpora", "read_corpus",
]

_LAZY = {
    "Analysis": "assistant.language.pipeline",
    "LanguageModel": "assistant.language.pipeline",
    "NestedChunker": "assistant.language.chunker",
    "SemanticPosTagger": "assistant.language.postag",
    "CorpusReadResult": "assistant.language.corpus",
    "Description": "assistant.language.corpus",
    "default_corpus_paths": "assistant.language.corpus",
    "read_corpora": "assistant.language.corpus",
    "read_corpus": "assistant.language.corpus",
}


def __getattr__(name: str):
    if name in _LAZY:
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'assistant.language' has no attribute {name!r}")

"""Text → tokens → POS tags → nested chunk labels → chunk tree, as one trained model.

:meth:`LanguageModel.load` trains the POS tagger and the nested chunker from the corpus (by
default the repository's ``corpus/*.xml``) or loads them from the model cache, keyed by a hash
of the corpus files' content, the lexicon and the code version, so a changed corpus retrains
and an unchanged one loads in milliseconds. Training is deterministic.
"""

from __future__ import annotations

import hashlib
import logging
from dataclasses import dataclass, field
from pathlib import Path

from assistant.errors import AssistantError
from assistant.fileio import cache_dir, cached
from assistant.language.chunker import NestedChunker
from assistant.language.corpus import CorpusReadResult, default_corpus_paths, read_corpora
from assistant.language.postag import LEXICON_PATH, SemanticPosTagger
from assistant.language.tokenize import tokenize
from assistant.language.tree import ChunkTree

__all__ = ["Analysis", "LanguageModel", "MODEL_VERSION"]

log = logging.getLogger(__name__)

#: bump when the tagger, chunker or their features change: cached models are then retrained
MODEL_VERSION = "language-6"


@dataclass
class Analysis:
    """What the language layer understood of one utterance."""

    text: str
    tokens: list[str]
    pos: list[str]
    chunk_labels: list[str]
    tree: ChunkTree
    unknown: list[str] = field(default_factory=list)
    corrections: dict[str, str] = field(default_factory=dict)

    def to_dict(self) -> dict:
        """JSON form: ``tokens``, ``pos``, ``chunk_labels``, ``tree`` (nested dict),
        ``bracketed``, ``unknown``, ``corrections``."""
        return {
            "text": self.text,
            "tokens": list(self.tokens),
            "pos": list(self.pos),
            "chunk_labels": list(self.chunk_labels),
            "tree": self.tree.to_dict(),
            "bracketed": self.tree.bracketed(),
            "unknown": list(self.unknown),
            "corrections": dict(self.corrections),
        }


class LanguageModel:
    """The trained language layer: ``.tagger`` (POS) and ``.chunker`` (nested chunks)."""

    def __init__(self, tagger: SemanticPosTagger, chunker: NestedChunker,
                 corpus_files: list[str] | None = None, problems: list[str] | None = None,
                 n_descriptions: int = 0):
        self.tagger = tagger
        self.chunker = chunker
        self.corpus_files = list(corpus_files or [])
        self.problems = list(problems or [])
        self.n_descriptions = n_descriptions

    # --- building --------------------------------------------------------------------------
    @classmethod
    def train(cls, corpus: CorpusReadResult) -> "LanguageModel":
        """Train both parts on a read corpus (no cache)."""
        if not corpus.descriptions:
            where = ", ".join(corpus.files) or "(no files)"
            raise AssistantError(
                f"no readable descriptions in the training corpus {where}; "
                "check the corpus files or set $ASSISTANT_CORPUS / --corpus"
            )
        trees = corpus.trees()
        tagger = SemanticPosTagger().fit([list(zip(t.words, t.pos_tags)) for t in trees])
        chunker = NestedChunker().fit(trees)
        return cls(tagger, chunker, corpus.files, corpus.problems, len(trees))

    @classmethod
    def load(cls, corpus_paths=None, *, use_cache: bool = True) -> "LanguageModel":
        """Train from ``corpus_paths`` (default :func:`default_corpus_paths`) or load the
        cached model trained on exactly these files' content."""
        paths = [Path(p) for p in (corpus_paths if corpus_paths is not None
                                   else default_corpus_paths())]
        if not paths:
            raise AssistantError(
                "no training corpus: the repository's corpus/*.xml is empty and "
                "$ASSISTANT_CORPUS is not set; give corpus files with --corpus PATH"
            )
        key = corpus_key(paths)
        cache_file = cache_dir() / f"language-{key}.pickle"

        def train():
            from assistant.progress import working

            with working("training the tagger and chunker (first use; cached after)"):
                return cls.train(read_corpora(paths))

        return cached(cache_file, train, cls, use_cache=use_cache)

    # --- use -------------------------------------------------------------------------------
    def analyse(self, text: str) -> Analysis:
        """Tokenize, tag and chunk one utterance. Never fails on odd text: empty text gives
        an empty analysis, unknown words are tagged and listed in ``unknown``."""
        tokens = tokenize(text)
        return self.analyse_tokens(tokens, text=text)

    def analyse_tokens(self, tokens: list[str], text: str | None = None) -> Analysis:
        pos, corrections, unknown = self.tagger.analyse(tokens)
        # the chunker reads the corrected words; the analysis keeps what was said
        labels, starts = self.chunker.label([corrections.get(t, t) for t in tokens], pos)
        tree = ChunkTree.from_labels(tokens, pos, labels, start_depths=starts)
        return Analysis(text if text is not None else " ".join(tokens), list(tokens), pos,
                        labels, tree, unknown, corrections)


def corpus_key(paths) -> str:
    """Hash of the corpus files' content, the lexicon and :data:`MODEL_VERSION`."""
    digest = hashlib.sha256(MODEL_VERSION.encode())
    for path in paths:
        try:
            data = Path(path).read_bytes()
        except OSError as error:
            raise AssistantError(f"cannot read corpus file {path}: {error.strerror or error}") from error
        digest.update(hashlib.sha256(data).digest())
    digest.update(LEXICON_PATH.read_bytes())
    return digest.hexdigest()[:20]

"""A product of the two grounders: the scored grounder's template evidence times the learned
grounder's probabilities, field by field.

The scored grounder's step-2 template evidence ``S^sharpness`` (without its P(g | tag) priors by
default: the classifier already carries them) is normalised into a distribution (a field
outside its step-1 type is N/A) and mixed with ``smoothing`` of the uniform distribution, so
neither part can veto the other; the value with the largest product wins. The two fail differently — the
template scorer on compositions whose nearest template belongs to another value (*to the left
of the sofa*), the classifier on phrasings whose words the corpus labels both ways — and the
product keeps what each gets right (measured in docs/grounding.md).
"""

from __future__ import annotations

from collections.abc import Sequence

from assistant.grounding.base import BaseGrounder, NormalisedChunk
from assistant.grounding.learned import LearnedGrounder
from assistant.grounding.scored import ScoredGrounder
from assistant.grounding.types import FIELD_ATTRS, FIELDS, ChunkGrounding, ChunkRecord


class CombinedGrounder(BaseGrounder):
    """Scored × learned, per field. Parameters: ``smoothing`` — uniform share mixed into the
    scored distribution; ``priors`` — keep the scorer's P(g | tag) factor in its evidence;
    ``scored_params`` / ``learned_params`` — parameters of the parts."""

    def __init__(self, smoothing: float = 0.3, priors: bool = False, scored_params: dict | None = None,
                 learned_params: dict | None = None):
        self.smoothing = smoothing
        self.priors = priors
        self.scored_params = scored_params
        self.learned_params = learned_params

    def fit(self, records: Sequence[ChunkRecord], groundings: Sequence[ChunkGrounding]) -> "CombinedGrounder":
        self.scored_ = ScoredGrounder(**(self.scored_params or {})).fit(records, groundings)
        self.learned_ = LearnedGrounder(**(self.learned_params or {})).fit(records, groundings)
        self.vocabulary_ = self.scored_.vocabulary_ | self.learned_.vocabulary_
        self.fitted_ = True
        return self

    def _ground_one(self, chunk: NormalisedChunk) -> ChunkGrounding:
        return self._ground_chunks([chunk])[0]

    def _ground_chunks(self, chunks: Sequence[NormalisedChunk]) -> list[ChunkGrounding]:
        scored = self.scored_.field_distributions(chunks, priors=self.priors)
        learned = self.learned_.field_probabilities(chunks)
        out = []
        for chunk, s_fields, l_fields in zip(chunks, scored, learned):
            if not chunk.words:
                out.append(ChunkGrounding())
                continue
            values = {}
            for field_name in FIELDS:
                probabilities = l_fields.get(field_name, {None: 1.0})
                evidence = s_fields.get(field_name) or {None: 1.0}
                total = sum(evidence.values()) or 1.0
                k = len(set(probabilities) | set(evidence))
                best = max(set(probabilities) | set(evidence), key=lambda v: (
                    probabilities.get(v, 0.0) * ((1 - self.smoothing) * evidence.get(v, 0.0) / total + self.smoothing / k),
                    str(v)))
                values[FIELD_ATTRS[field_name]] = best
            out.append(ChunkGrounding(**values))
        return out

"""The scored grounder of dissertation 4.3 II.C: probabilities times WLD template membership.

Step 1, the grounding type of a chunk *s* (room / object / rdt / none)::

    T = argmax_t  P(t | tag_s) · S(text_s, templates of type t)

Step 2, each field *f* of that type (for rdt: reference, direction, target)::

    G_f = argmax_g  P(g | tag_s) · S(text_s, templates with f = g) · P(g | parent tag_s) · P(g | child tags_s)

``S = 1 - min WLD`` is the membership of the chunk's words in a set of template chunks, the
word-level weighted Levenshtein distance of :mod:`assistant.grounding.wld`. The chunk tag is the
first symbol of every sequence, so a template of another tag matches less well. Every
probability is counted from the training labels with add-``alpha`` smoothing; parent and child
factors are skipped for a record whose structure is unknown. ``sharpness`` raises ``S`` to a
power (1 reproduces the dissertation's product).
"""

from __future__ import annotations

from collections.abc import Sequence

from assistant.grounding.base import BaseGrounder, NormalisedChunk, normalise
from assistant.grounding.types import FIELD_ATTRS, TYPE_FIELDS, ChunkGrounding, ChunkRecord
from assistant.grounding.wld import (
    CONTENT_TAGS,
    TemplateIndex,
    WordCoder,
    informativeness_weights,
    smoothed_conditional,
)


#: grounding types whose fields use the parent/child factors: where a reference chunk sits
#: (under a FURTP or an OBTP) says something about its RDT; it says nothing about which room or
#: object a chunk names, and on a small corpus those statistics are only noise
STRUCTURAL_TYPES = frozenset({"rdt"})
#: fields grounded with the templates of the command's own world when it is known
WORLD_FIELDS = frozenset({"target room"})


class ScoredGrounder(BaseGrounder):
    """Template-matching grounder (WLD × probabilities), dissertation 4.3 II.C.

    Parameters: ``alpha`` — add-alpha smoothing of every probability; ``sharpness`` — the
    exponent on S; ``max_weight`` — the largest word weight; ``use_structure`` — use the parent
    and child factors when the record carries them (off by default: while tuning on the CSISL
    templates they cost about five points of whole-command accuracy, see docs/grounding.md).
    """

    def __init__(self, alpha: float = 0.5, sharpness: float = 8.0, max_weight: int = 6,
                 use_structure: bool = False):
        self.alpha = alpha
        self.sharpness = sharpness
        self.max_weight = max_weight
        self.use_structure = use_structure

    # --- training -----------------------------------------------------------------------------
    def fit(self, records: Sequence[ChunkRecord], groundings: Sequence[ChunkGrounding]) -> "ScoredGrounder":
        chunks = self._start_fit(records, groundings)
        kinds = [g.kind for g in groundings]
        coder = WordCoder()
        self.coder_ = coder
        # step 1: the grounding type
        type_weights = informativeness_weights([c.words for c in chunks], kinds, max_weight=self.max_weight)
        self.type_index_ = TemplateIndex(coder, type_weights, _unknown_weight).fit(
            [(c.label, c.words, c.pos, k) for c, k in zip(chunks, kinds)])
        self.p_type_tag_ = smoothed_conditional([(c.label, k) for c, k in zip(chunks, kinds)], self.alpha)
        self.types_ = sorted(set(kinds))
        # step 2: one model per field, trained on the chunks whose type has that field
        self.field_models_ = {}
        for type_name, fields in TYPE_FIELDS.items():
            for field_name in fields:
                subset = [(c, g.get(field_name)) for c, g, k in zip(chunks, groundings, kinds)
                          if type_name in k.split("+")]
                if not subset:
                    continue
                model = self._fit_field(coder, subset, type_name in STRUCTURAL_TYPES)
                if field_name in WORLD_FIELDS:  # "the room on the right" depends on the home
                    worlds = sorted({c.world for c, _ in subset if c.world is not None})
                    model["by_world"] = {w: self._fit_field(coder, [(c, v) for c, v in subset if c.world == w], False)
                                         for w in worlds}
                self.field_models_[field_name] = model
        self.fitted_ = True
        return self

    def _fit_field(self, coder: WordCoder, subset: list[tuple[NormalisedChunk, str | None]],
                   structural: bool) -> dict:
        values = [v for _, v in subset]
        weights = informativeness_weights([c.words for c, _ in subset], [str(v) for v in values],
                                          max_weight=self.max_weight)
        index = TemplateIndex(coder, weights, _unknown_weight).fit(
            [(c.label, c.words, c.pos, v) for c, v in subset])
        return {
            "index": index,
            "p_tag": smoothed_conditional([(c.label, v) for c, v in subset], self.alpha),
            "p_parent": smoothed_conditional([(c.parent, v) for c, v in subset if c.parent is not None], self.alpha),
            "p_children": smoothed_conditional([(c.children_key, v) for c, v in subset
                                                if c.children is not None], self.alpha),
            "has_parent": structural and any(c.parent is not None for c, _ in subset),
            "has_children": structural and any(c.children is not None for c, _ in subset),
        }

    # --- grounding ----------------------------------------------------------------------------
    def type_scores(self, chunk: NormalisedChunk, membership: dict | None = None) -> dict[str, float]:
        if membership is None:
            membership = self.type_index_.membership(chunk.label, chunk.words, chunk.pos)
        return {t: self.p_type_tag_(t, chunk.label) * membership.get(t, 0.0) ** self.sharpness
                for t in self.types_}

    def _field_model(self, chunk: NormalisedChunk, field_name: str) -> dict:
        model = self.field_models_[field_name]
        return model.get("by_world", {}).get(chunk.world, model)

    def field_scores(self, chunk: NormalisedChunk, field_name: str,
                     membership: dict | None = None, priors: bool = True) -> dict[str | None, float]:
        model = self._field_model(chunk, field_name)
        if membership is None:
            membership = model["index"].membership(chunk.label, chunk.words, chunk.pos)
        scores = {}
        for value, s in membership.items():
            score = s ** self.sharpness
            if not priors:  # template evidence only
                scores[value] = score
                continue
            score *= model["p_tag"](value, chunk.label)
            if self.use_structure and chunk.parent is not None and model["has_parent"]:
                score *= model["p_parent"](value, chunk.parent)
            if self.use_structure and chunk.children is not None and model["has_children"]:
                score *= model["p_children"](value, chunk.children_key)
            scores[value] = score
        return scores

    def _ground_one(self, chunk: NormalisedChunk) -> ChunkGrounding:
        return self._ground_chunks([chunk])[0]

    def field_distributions(self, chunks: Sequence[NormalisedChunk], priors: bool = True) -> list[dict[str, dict]]:
        """Per chunk, the step-2 scores of every field of its step-1 type
        (``{field: {value: score}}``; fields outside the type are absent, meaning N/A).

        Step 1 for every chunk, then step 2 field by field, each with one rapidfuzz call per
        template index (a command's chunks are scored together).
        """
        live = [i for i, c in enumerate(chunks) if c.words]
        type_memberships = self.type_index_.membership_many(
            [(chunks[i].label, chunks[i].words, chunks[i].pos) for i in live])
        out: list[dict[str, dict]] = [{} for _ in chunks]
        groups: dict[tuple[str, int], list[int]] = {}
        for i, membership in zip(live, type_memberships):
            scores = self.type_scores(chunks[i], membership)
            best_type = max(scores, key=lambda t: (scores[t], t))
            for t in best_type.split("+"):
                for field_name in TYPE_FIELDS.get(t, ()):
                    if field_name in self.field_models_:
                        model_id = id(self._field_model(chunks[i], field_name))
                        groups.setdefault((field_name, model_id), []).append(i)
        for (field_name, _), members in groups.items():
            index = self._field_model(chunks[members[0]], field_name)["index"]
            memberships = index.membership_many([(chunks[i].label, chunks[i].words, chunks[i].pos) for i in members])
            for i, membership in zip(members, memberships):
                field_scores = self.field_scores(chunks[i], field_name, membership, priors)
                if field_scores:
                    out[i][field_name] = field_scores
        return out

    def _ground_chunks(self, chunks: Sequence[NormalisedChunk]) -> list[ChunkGrounding]:
        out = []
        for fields in self.field_distributions(chunks):
            values = {FIELD_ATTRS[f]: max(scores, key=lambda v: (scores[v], str(v))) for f, scores in fields.items()}
            out.append(ChunkGrounding(**values))
        return out


def _unknown_weight(word: str, pos: str) -> int:
    """Weight of a word never seen in training: content words 2, others 1."""
    return 2 if pos.upper() in CONTENT_TAGS else 1


__all__ = ["ScoredGrounder", "normalise"]

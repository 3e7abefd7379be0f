"""A learned grounder after dissertation 4.4: chunk type and words in, one model per field out.

The dissertation trains one LSTM per grounding type on a binary vector of chunk-type one-hot
and word one-hot features, with an extra *outlier* output. Here each of the five fields gets a
scikit-learn classifier over the same kind of features — chunk type one-hot, bag of (canonical)
words and word bigrams, and, when known, the parent and child chunk types — whose classes are
the field's values plus the outlier class ``N/A`` (the chunk says nothing about the field).

``model="logistic"`` (default) is a multinomial logistic regression; ``model="mlp"`` a
one-hidden-layer perceptron. Both are deterministic (``random_state``).
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence
from dataclasses import replace

import numpy as np
from scipy import sparse
from sklearn.feature_extraction import DictVectorizer
from sklearn.linear_model import LogisticRegression
from sklearn.neural_network import MLPClassifier
from threadpoolctl import threadpool_limits

from assistant.grounding.base import BaseGrounder, NormalisedChunk
from assistant.grounding.types import FIELD_ATTRS, FIELDS, ChunkGrounding, ChunkRecord

#: the outlier class: the chunk does not ground this field
OUTLIER = "N/A"
MODELS = ("logistic", "mlp")


def chunk_features(chunk: NormalisedChunk, *, structure: bool = True, bigrams: bool = True) -> dict[str, float]:
    """Sparse binary features of one chunk (chunk type, words, bigrams, parent/child types)."""
    feats = {f"tag={chunk.label}": 1.0}
    for word in chunk.words:
        feats[f"w={word}"] = 1.0
        feats[f"tw={chunk.label}:{word}"] = 1.0
    if bigrams:
        for a, b in zip(chunk.words, chunk.words[1:]):
            feats[f"b={a}_{b}"] = 1.0
    if chunk.words:  # where a phrase starts and ends ("… again", "then …") matters
        feats[f"first={chunk.words[0]}"] = 1.0
        feats[f"last={chunk.words[-1]}"] = 1.0
    if not chunk.words:
        feats["empty"] = 1.0
    if chunk.world is not None:  # which room "on the right" is depends on the home
        feats[f"world={chunk.world}"] = 1.0
        for word in chunk.words:
            feats[f"ww={chunk.world}:{chunk.label}:{word}"] = 1.0
    if structure and chunk.parent is not None:
        feats[f"parent={chunk.parent}"] = 1.0
    if structure and chunk.children is not None:
        for child in chunk.children:
            feats[f"child={child}"] = 1.0
    return feats


def _int32(X):
    """CSR with 32-bit indices (liblinear refuses 64-bit ones)."""
    X = X.tocsr()
    X.indices = X.indices.astype(np.int32, copy=False)
    X.indptr = X.indptr.astype(np.int32, copy=False)
    return X


class LearnedGrounder(BaseGrounder):
    """One scikit-learn classifier per grounding field over chunk-type and word features.

    Parameters: ``model`` — ``"logistic"`` or ``"mlp"``; ``C`` — inverse regularisation of the
    logistic model; ``hidden`` — hidden units of the MLP; ``use_structure`` — parent/child chunk
    types as features; ``world_dropout`` — train on every chunk also without its world, so a
    command from an unnamed home still grounds; ``random_state`` — seed.
    """

    def __init__(self, model: str = "logistic", C: float = 20.0, hidden: int = 128,
                 use_structure: bool = False, world_dropout: bool = True, random_state: int = 0):
        self.model = model
        self.C = C
        self.hidden = hidden
        self.use_structure = use_structure
        self.world_dropout = world_dropout
        self.random_state = random_state

    def _estimator(self):
        if self.model == "logistic":
            return LogisticRegression(C=self.C, max_iter=2000, random_state=self.random_state)
        if self.model == "mlp":
            return MLPClassifier(hidden_layer_sizes=(self.hidden,), max_iter=600, alpha=1e-4,
                                 random_state=self.random_state)
        raise ValueError(f"unknown model {self.model!r}; known: {', '.join(MODELS)}")

    def fit(self, records: Sequence[ChunkRecord], groundings: Sequence[ChunkGrounding]) -> "LearnedGrounder":
        chunks = self._start_fit(records, groundings)
        groundings = list(groundings)
        if self.world_dropout:  # also learn to ground without knowing the home
            extra = [(replace(c, world=None), g) for c, g in zip(chunks, groundings) if c.world is not None]
            chunks = chunks + [c for c, _ in extra]
            groundings = groundings + [g for _, g in extra]
        # identical (chunk, grounding) pairs train once, weighted by their count
        counts = Counter(zip(chunks, groundings))
        chunks = [c for c, _ in counts]
        groundings = [g for _, g in counts]
        weights = np.array(list(counts.values()), dtype=float)
        self.vectorizer_ = DictVectorizer(sparse=True)
        X = _int32(self.vectorizer_.fit_transform([chunk_features(c, structure=self.use_structure) for c in chunks]))
        self.estimators_ = {}
        self.constants_ = {}
        for field_name in FIELDS:
            y = np.array([g.get(field_name) or OUTLIER for g in groundings], dtype=object)
            classes = sorted(set(y))
            if len(classes) == 1:  # nothing to learn: always the same value
                self.constants_[field_name] = classes[0]
                continue
            # one BLAS thread: on a busy 2-core machine the default pool makes lbfgs ~15x slower
            with threadpool_limits(1):
                self.estimators_[field_name] = self._estimator().fit(X, y, sample_weight=weights)
        self.fitted_ = True
        return self

    def _ground_chunks(self, chunks: Sequence[NormalisedChunk]) -> list[ChunkGrounding]:
        X = self._features(chunks)
        columns = {}
        for field_name in FIELDS:
            if field_name in self.constants_:
                columns[field_name] = [self.constants_[field_name]] * len(chunks)
            else:
                columns[field_name] = _predict(self.estimators_[field_name], X)
        out = []
        for i, chunk in enumerate(chunks):
            if not chunk.words:
                out.append(ChunkGrounding())
                continue
            values = {FIELD_ATTRS[f]: (None if columns[f][i] == OUTLIER else str(columns[f][i]))
                      for f in FIELDS}
            out.append(ChunkGrounding(**values))
        return out

    def _ground_one(self, chunk: NormalisedChunk) -> ChunkGrounding:
        return self._ground_chunks([chunk])[0]

    def field_probabilities(self, chunks: Sequence[NormalisedChunk]) -> list[dict[str, dict]]:
        """Per chunk, ``{field: {value or None: probability}}`` (None is the outlier class)."""
        X = self._features(chunks)
        out: list[dict[str, dict]] = [{} for _ in chunks]
        for field_name in FIELDS:
            if field_name in self.constants_:
                value = self.constants_[field_name]
                for row in out:
                    row[field_name] = {None if value == OUTLIER else value: 1.0}
                continue
            estimator = self.estimators_[field_name]
            proba = _predict_proba(estimator, X)
            classes = [None if c == OUTLIER else str(c) for c in estimator.classes_]
            for row, p in zip(out, proba):
                row[field_name] = dict(zip(classes, p.tolist()))
        return out

    def _features(self, chunks: Sequence[NormalisedChunk]) -> sparse.csr_matrix:
        """The feature matrix, built straight from the fitted vocabulary (DictVectorizer's
        input validation costs more than the whole product for one command)."""
        vocabulary = self.vectorizer_.vocabulary_
        rows, cols = [], []
        for i, chunk in enumerate(chunks):
            for name in chunk_features(chunk, structure=self.use_structure):
                j = vocabulary.get(name)
                if j is not None:
                    rows.append(i)
                    cols.append(j)
        data = np.ones(len(rows))
        return sparse.csr_matrix((data, (rows, cols)), shape=(len(chunks), len(vocabulary)))


def _predict_proba(estimator, X) -> np.ndarray:
    """``estimator.predict_proba(X)``; for a logistic model, the softmax of the product itself."""
    coef = getattr(estimator, "coef_", None)
    if coef is None:
        return estimator.predict_proba(X)
    scores = np.asarray(X @ coef.T) + estimator.intercept_
    if scores.shape[1] == 1:
        p = 1.0 / (1.0 + np.exp(-scores[:, 0]))
        return np.column_stack([1.0 - p, p])
    scores -= scores.max(axis=1, keepdims=True)
    e = np.exp(scores)
    return e / e.sum(axis=1, keepdims=True)


def _predict(estimator, X) -> list:
    """``estimator.predict(X)``; for a linear model, the product itself (same result, without
    scikit-learn's per-call validation, which dominates at one command per call)."""
    coef = getattr(estimator, "coef_", None)
    if coef is None:
        return list(estimator.predict(X))
    scores = np.asarray(X @ coef.T) + estimator.intercept_
    if scores.shape[1] == 1:
        index = (scores[:, 0] > 0).astype(int)
    else:
        index = scores.argmax(axis=1)
    return list(estimator.classes_[index])

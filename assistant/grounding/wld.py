"""Word-level weighted Levenshtein distance (WLD) between chunk texts, computed by rapidfuzz.

Every word is one symbol; a word of weight *k* is spelled as *k* copies of its symbol, so
deleting or inserting it costs *k* and substituting it by a word of weight *j* costs
``max(j, k)``. rapidfuzz's C++ Levenshtein then gives the weighted distance of whole word
sequences; :meth:`TemplateIndex.nearest` normalises it by the longer weighted length, so
``S = 1 - WLD`` lies in [0, 1] (dissertation 4.3 II.C).

Weights are per word and per grounding field (:func:`informativeness_weights`): a word that
shifts the distribution of a field's groundings away from its prior (``behind`` → direction
*back*, ``bed`` → reference *bed*) weighs more than one that does not (``the``, ``to``), which
is how "content words count more than function words" is learned from the corpus instead of
being listed by hand.
"""

from __future__ import annotations

from collections import Counter, defaultdict
from collections.abc import Hashable, Sequence

import numpy as np
from rapidfuzz import process
from rapidfuzz.distance import Levenshtein

#: symbols for known words start here (Unicode private use planes)
_KNOWN_BASE = 0xF0000
#: symbols for words unseen in training, per query
_UNKNOWN_BASE = 0x100000
#: POS tags whose unseen words count as content words
CONTENT_TAGS = frozenset({"FUR", "RM", "DIR", "STR", "NN", "NNS", "NNP", "JJ", "VB", "VBD",
                          "VBP", "VBZ", "VBG", "VBN", "CD"})


def informativeness_weights(
    sequences: Sequence[Sequence[str]],
    labels: Sequence[Hashable],
    *,
    max_weight: int = 5,
    smoothing: float = 8.0,
    scale: float = 3.0,
) -> dict[str, int]:
    """Integer weight per word: ``1 + round(scale · KL(P(label | word) ‖ P(label)))``, capped.

    ``P(label | word)`` is estimated from the sequences that contain the word, smoothed towards
    the prior with ``smoothing`` pseudo-counts, so a word seen once cannot look decisive.
    """
    prior = Counter(labels)
    classes = sorted(prior, key=str)
    total = sum(prior.values())
    p_prior = np.array([prior[c] / total for c in classes])
    index = {c: i for i, c in enumerate(classes)}
    by_word: dict[str, np.ndarray] = defaultdict(lambda: np.zeros(len(classes)))
    for seq, label in zip(sequences, labels):
        for word in set(seq):
            by_word[word][index[label]] += 1
    weights = {}
    for word, counts in by_word.items():
        p = (counts + smoothing * p_prior) / (counts.sum() + smoothing)
        kl = float(np.sum(p * np.log(p / p_prior)))
        weights[word] = int(min(max_weight, 1 + round(scale * kl)))
    return weights


class WordCoder:
    """Maps words to one-character symbols (stable within one fitted grounder)."""

    def __init__(self) -> None:
        self.codes: dict[str, str] = {}

    def add(self, word: str) -> str:
        code = self.codes.get(word)
        if code is None:
            code = chr(_KNOWN_BASE + len(self.codes))
            self.codes[word] = code
        return code

    def encode(self, words: Sequence[str], weights: Sequence[int], *, learn: bool = False) -> str:
        parts = []
        unknown: dict[str, str] = {}
        for word, weight in zip(words, weights):
            code = self.add(word) if learn else self.codes.get(word)
            if code is None:
                code = unknown.setdefault(word, chr(_UNKNOWN_BASE + len(unknown)))
            parts.append(code * max(1, int(weight)))
        return "".join(parts)


class TemplateIndex:
    """Template sequences with a label each; the best membership score of a text per label."""

    def __init__(self, coder: WordCoder, weights: dict[str, int], unknown_weight, head_weight: int = 2):
        self.coder = coder
        self.weights = weights
        self.unknown_weight = unknown_weight  # callable(word, pos) -> int
        self.head_weight = head_weight
        self.labels_: list[Hashable] = []
        self.choices_: list[str] = []
        self._order: np.ndarray | None = None
        self._starts: np.ndarray | None = None
        self._group_labels: list[Hashable] = []

    def _weights_for(self, head: str, words: Sequence[str], pos: Sequence[str]) -> list[int]:
        out = [self.head_weight]
        for word, tag in zip(words, pos):
            w = self.weights.get(word)
            out.append(w if w is not None else self.unknown_weight(word, tag))
        return out

    def encode(self, head: str, words: Sequence[str], pos: Sequence[str], *, learn: bool = False) -> str:
        return self.coder.encode([head, *words], self._weights_for(head, words, pos), learn=learn)

    def fit(self, items: Sequence[tuple[str, Sequence[str], Sequence[str], Hashable]]) -> "TemplateIndex":
        """``items``: (head symbol such as the chunk tag, words, POS tags, label)."""
        seen = set()
        for head, words, pos, label in items:
            code = self.encode(head, words, pos, learn=True)
            if (code, label) in seen:
                continue
            seen.add((code, label))
            self.choices_.append(code)
            self.labels_.append(label)
        keys = [str(label) for label in self.labels_]
        order = np.argsort(np.array(keys, dtype=object), kind="stable")
        sorted_keys = [keys[i] for i in order]
        starts = [0] + [i for i in range(1, len(sorted_keys)) if sorted_keys[i] != sorted_keys[i - 1]]
        self._order = order
        self._starts = np.array(starts, dtype=np.intp)
        self._group_labels = [self.labels_[order[s]] for s in starts]
        self._choices_sorted = [self.choices_[i] for i in order]
        return self

    def membership(self, head: str, words: Sequence[str], pos: Sequence[str]) -> dict[Hashable, float]:
        """``S = 1 - min WLD`` of the text to the templates of each label."""
        return self.membership_many([(head, words, pos)])[0]

    def membership_many(self, texts: Sequence[tuple[str, Sequence[str], Sequence[str]]]) -> list[dict[Hashable, float]]:
        """:meth:`membership` of several texts with one rapidfuzz call."""
        if not self.choices_:
            return [{} for _ in texts]
        if not texts:
            return []
        queries = [self.encode(head, words, pos) for head, words, pos in texts]
        dist = process.cdist(queries, self._choices_sorted, scorer=Levenshtein.normalized_distance,
                             dtype=np.float32, workers=1)
        mins = np.minimum.reduceat(dist, self._starts, axis=1)
        return [{label: 1.0 - float(m) for label, m in zip(self._group_labels, row)} for row in mins]


class ConditionalTable:
    """``P(value | condition)`` with add-``alpha`` smoothing; unseen conditions give uniform.

    Built from (condition, value) pairs; call it as ``table(value, condition)``.
    """

    def __init__(self, pairs: Sequence[tuple[Hashable, Hashable]], alpha: float = 0.5):
        counts: dict[Hashable, Counter] = defaultdict(Counter)
        values = set()
        for condition, value in pairs:
            counts[condition][value] += 1
            values.add(value)
        k = max(1, len(values))
        self.uniform = 1.0 / k
        self.table = {}
        self.unseen = {}
        for condition, counter in counts.items():
            n = sum(counter.values())
            self.table[condition] = {v: (counter[v] + alpha) / (n + alpha * k) for v in values}
            self.unseen[condition] = alpha / (n + alpha * k)  # a value never seen with it

    def __call__(self, value: Hashable, condition: Hashable) -> float:
        row = self.table.get(condition)
        if row is None:
            return self.uniform
        return row.get(value, self.unseen[condition])


def smoothed_conditional(pairs: Sequence[tuple[Hashable, Hashable]], alpha: float = 0.5) -> ConditionalTable:
    """``P(value | condition)`` as a picklable :class:`ConditionalTable`."""
    return ConditionalTable(pairs, alpha)

"""The semantic POS tagger: NLTK's back-off chain refined by Brill (dissertation Figure 4.3).

The chain, from the last resort up::

    regular expressions → affix → domain lexicon → unigram → bigram → trigram  → Brill

Each stage returns ``None`` for a word it cannot tag and passes it down (NLTK's
``SequentialBackoffTagger``). The Brill trainer then learns transformation rules with the whole
chain as its base line system. Before tagging, a word the tagger never saw is resolved against
the vocabulary (training words and the domain lexicon) with a fuzzy matcher, so "tabel" is
tagged as "table"; a word still unknown is tagged by the lower stages and reported.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Iterable, Sequence
from functools import lru_cache
from pathlib import Path

import yaml
from nltk.tag import AffixTagger, BigramTagger, TrigramTagger, UnigramTagger
from nltk.tag.sequential import SequentialBackoffTagger
from nltk.tag.brill import brill24, fntbl37, nltkdemo18
from nltk.tag.brill_trainer import BrillTaggerTrainer
from rapidfuzz import process
from rapidfuzz.distance import OSA
from assistant.errors import NotFittedError

__all__ = ["SemanticPosTagger", "load_lexicon", "accuracy_of"]

LEXICON_PATH = Path(__file__).with_name("data") / "lexicon.yaml"

#: shapes of words the corpus never showed (the bottom of the chain)
REGEXP_PATTERNS = [
    (r"^-?\d+(?:[.,]\d+)*$", "CD"),
    (r"^(?:one|two|three|four|five|six|seven|eight|nine|ten|twenty|thirty|forty|fifty|"
     r"sixty|seventy|eighty|ninety|hundred)(?:-\w+)?$", "CD"),
    (r"^'(?:ll|d)$", "MD"),
    (r"^'(?:re|m|ve)$", "VBP"),
    (r"^'s$", "VBZ"),
    (r"^n't$", "RB"),
    (r".*ing$", "VBG"),
    (r".*ed$", "VBD"),
    (r".*ly$", "RB"),
    (r".*(?:ous|ful|ive|able|ible|al|ic|ish)$", "JJ"),
    (r".*[^s]s$", "NNS"),
    (r".*", "NN"),
]

#: the CSISL semantic word classes: short typos are corrected only towards these
DOMAIN_TAGS = frozenset({"FUR", "RM", "STR", "DIR"})

TEMPLATE_SETS = {"brill24": brill24, "fntbl37": fntbl37, "nltkdemo18": nltkdemo18}


class PatternTagger(SequentialBackoffTagger):
    """The bottom of the chain: a tag from the first regular expression the word matches.

    Like NLTK's ``RegexpTagger``, but with the standard ``re`` patterns, which pickle (NLTK
    3.10's ReDoS-guarded patterns lose their timeout setting when unpickled and then fail).
    """

    def __init__(self, patterns, backoff=None):
        super().__init__(backoff)
        self.patterns = [(re.compile(p), tag) for p, tag in patterns]

    def choose_tag(self, tokens, index, history):
        for pattern, tag in self.patterns:
            if pattern.match(tokens[index]):
                return tag
        return None


@lru_cache(maxsize=4)
def load_lexicon(path: str | None = None) -> dict[str, str]:
    """Word → tag from the domain lexicon YAML (tag: [words])."""
    data = yaml.safe_load(Path(path or LEXICON_PATH).read_text(encoding="utf-8")) or {}
    out = {}
    for tag, words in data.items():
        if not isinstance(tag, str) or not all(isinstance(w, str) for w in words):
            raise ValueError(f"{path or LEXICON_PATH}: {tag!r}: quote tags and words that YAML reads as booleans")
        out.update({w.lower(): tag for w in words})
    return out


def accuracy_of(predicted: Sequence[Sequence[str]], gold: Sequence[Sequence[str]]) -> float:
    """Fraction of positions where ``predicted`` and ``gold`` agree (sentences flattened)."""
    total = correct = 0
    for p_sent, g_sent in zip(predicted, gold, strict=True):
        total += len(g_sent)
        correct += sum(p == g for p, g in zip(p_sent, g_sent, strict=True))
    return correct / total if total else 0.0


class SemanticPosTagger:
    """Back-off + Brill POS tagger with fuzzy resolution of unknown words.

    Parameters
    ----------
    templates : name of an NLTK Brill template set (``brill24``, ``fntbl37``, ``nltkdemo18``).
    max_rules, min_score : Brill trainer limits.
    affix_length : suffix length for the affix tagger (negative = suffix).
    fuzzy_max_distance : largest edit distance (optimal string alignment) for a typo
        correction; words of up to 4 letters accept distance 1, shorter words none.
    lexicon_path : domain lexicon YAML (default: the package's ``data/lexicon.yaml``).
    """

    def __init__(self, templates: str = "brill24", max_rules: int = 150, min_score: int = 2,
                 affix_length: int = -3, fuzzy_max_distance: int = 2,
                 lexicon_path: str | None = None):
        self.templates = templates
        self.max_rules = max_rules
        self.min_score = min_score
        self.affix_length = affix_length
        self.fuzzy_max_distance = fuzzy_max_distance
        self.lexicon_path = lexicon_path

    # --- training --------------------------------------------------------------------------
    def fit(self, tagged_sents: Iterable[Sequence[tuple[str, str]]]) -> "SemanticPosTagger":
        """Train on sentences of ``(word, tag)``; returns ``self``."""
        sents = [list(s) for s in tagged_sents if len(s)]
        if not sents:
            raise ValueError("no tagged sentences to train the POS tagger on")
        if self.templates not in TEMPLATE_SETS:
            raise ValueError(f"unknown Brill template set {self.templates!r}; "
                             f"known: {', '.join(TEMPLATE_SETS)}")
        lexicon = load_lexicon(self.lexicon_path)
        chain = PatternTagger(REGEXP_PATTERNS)
        chain = AffixTagger(sents, affix_length=self.affix_length, min_stem_length=2, backoff=chain)
        chain = UnigramTagger(model=lexicon, backoff=chain)
        chain = UnigramTagger(sents, backoff=chain)
        chain = BigramTagger(sents, backoff=chain)
        chain = TrigramTagger(sents, backoff=chain)
        self.backoff_ = chain
        trainer = BrillTaggerTrainer(chain, TEMPLATE_SETS[self.templates](), trace=0,
                                     deterministic=True)
        self.brill_ = trainer.train(sents, max_rules=self.max_rules, min_score=self.min_score)
        counts = Counter(w for s in sents for w, _ in s)
        self.known_words_ = frozenset(counts) | frozenset(lexicon)
        # most frequent first, so that ties in the fuzzy match go to the common word
        self.vocabulary_ = sorted(self.known_words_, key=lambda w: (-counts.get(w, 0), w))
        self.vocabulary_ = [w for w in self.vocabulary_ if w.isalpha() and len(w) >= 3]
        self.domain_words_ = frozenset(w for w, t in lexicon.items() if t in DOMAIN_TAGS)
        self.tagset_ = sorted({t for s in sents for _, t in s} | set(lexicon.values()))
        return self

    def _check(self) -> None:
        if not hasattr(self, "brill_"):
            raise NotFittedError("this SemanticPosTagger is not trained yet; call fit(tagged_sents)")

    # --- tagging ---------------------------------------------------------------------------
    def resolve(self, word: str) -> str | None:
        """The known word a typo stands for, or ``None`` (known word, number, or no match).

        A correction keeps the first letter, is not an inflection of the word ("walks" is
        not "walk" misspelt; the affix stage tags it), and is at most one edit away (two
        for words of 8 letters or more); words of 4 letters are only corrected to domain
        words (furniture, rooms, structures, directions).
        """
        self._check()
        if word in self.known_words_ or len(word) < 4 or not re.fullmatch(r"[^\W\d_]+", word):
            return None
        for suffix in ("s", "es", "ed", "d", "ing", "er", "est", "ly"):
            if word.endswith(suffix) and word[: -len(suffix)] in self.known_words_:
                return None  # an inflection of a known word, not a typo
        limit = 2 if len(word) >= 8 else 1
        for candidate, _, _ in process.extract(word, self.vocabulary_, scorer=OSA.distance,
                                              score_cutoff=min(limit, self.fuzzy_max_distance),
                                              limit=8):
            if candidate[0] != word[0] or candidate.startswith(word) or word.startswith(candidate):
                continue
            if len(word) <= 4 and candidate not in self.domain_words_:
                continue
            return candidate
        return None

    def analyse(self, words: Sequence[str]) -> tuple[list[str], dict[str, str], list[str]]:
        """Tags for ``words``, the typo corrections made, and the words still unknown."""
        self._check()
        corrections: dict[str, str] = {}
        unknown: list[str] = []
        resolved = []
        for word in words:
            if word in self.known_words_:
                resolved.append(word)
                continue
            fixed = self.resolve(word)
            if fixed is not None:
                corrections[word] = fixed
                resolved.append(fixed)
            else:
                if not re.fullmatch(r"-?\d+(?:[.,]\d+)*", word) and word not in unknown:
                    unknown.append(word)
                resolved.append(word)
        tags = [t or "NN" for _, t in self.brill_.tag(resolved)] if resolved else []
        return tags, corrections, unknown

    def tag(self, words: Sequence[str]) -> list[tuple[str, str]]:
        """NLTK-style: ``[(word, tag), …]``."""
        tags, _, _ = self.analyse(words)
        return list(zip(words, tags))

    def tag_sents(self, sents: Iterable[Sequence[str]]) -> list[list[tuple[str, str]]]:
        return [self.tag(s) for s in sents]

    def accuracy(self, gold: Iterable[Sequence[tuple[str, str]]]) -> float:
        """NLTK ``TaggerI.accuracy``: tag the gold words, compare with the gold tags."""
        gold = [list(s) for s in gold]
        predicted = [[t for _, t in self.tag([w for w, _ in s])] for s in gold]
        return accuracy_of(predicted, [[t for _, t in s] for s in gold])

    @property
    def rules(self) -> list[str]:
        self._check()
        return [str(r) for r in self.brill_.rules()]

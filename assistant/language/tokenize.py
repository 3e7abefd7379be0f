"""Tokenizer for speech-like text, following the CSISL corpus conventions (dissertation 4.2.2).

Spoken commands have no punctuation, so the tokenizer lower-cases, strips punctuation and
splits contractions the way the corpus writes them: ``you'll`` → ``you 'll``, ``it's`` →
``it 's``, ``can't`` → ``ca n't``, ``gonna`` → ``gon na``. Numbers are kept (``45``, ``2.5``),
hyphenated words stay whole (``u-turn``, ``forty-five``) and letters outside ASCII are kept.
"""

from __future__ import annotations

import re
import unicodedata

__all__ = ["tokenize", "CLITICS"]

#: clitics split off the word before them, as the corpus writes them
CLITICS = ("n't", "'ll", "'re", "'ve", "'m", "'d", "'s")

# whole words the corpus splits in two (Penn Treebank convention)
_SPLIT_WORDS = {
    "gonna": ("gon", "na"),
    "wanna": ("wan", "na"),
    "gotta": ("got", "ta"),
    "cannot": ("can", "not"),
}
# negations whose stem changes: "can't" → "ca n't", "won't" → "wo n't"
_NEGATION_STEMS = {"ca", "wo", "sha", "ai"}

_APOSTROPHES = str.maketrans({"\u2019": "'", "\u2018": "'", "\u02bc": "'", "`": "'", "\u00b4": "'"})
# a word: letters/digits with inner hyphens or apostrophes; or a number with a decimal point
_WORD = re.compile(
    r"(?:n't|'(?:ll|re|ve|m|d|s))(?![^\W_])"  # a clitic already split off: "you 'll"
    r"|\d+(?:[.,]\d+)+"  # a number with a decimal point or thousands separator
    r"|[^\W_]+(?:['\-][^\W_]+)*'?",  # a word, with inner hyphens or apostrophes
    re.UNICODE,
)


def tokenize(text: str) -> list[str]:
    """Split ``text`` into lower-case word tokens; punctuation and symbols are dropped.

    >>> tokenize("You'll see it's on the table, can't miss it!")
    ['you', "'ll", 'see', 'it', "'s", 'on', 'the', 'table', 'ca', "n't", 'miss', 'it']
    """
    if not text:
        return []
    text = unicodedata.normalize("NFKC", str(text)).translate(_APOSTROPHES).lower()
    tokens: list[str] = []
    for match in _WORD.finditer(text):
        tokens.extend(_split_word(match.group(0)))
    return tokens


def _split_word(word: str) -> list[str]:
    if word in CLITICS:
        return [word]
    if word[0].isdigit():
        return [word.replace(",", "")] if re.fullmatch(r"\d{1,3}(,\d{3})+", word) else [word]
    word = word.strip("'")
    if not word:
        return []
    if word in _SPLIT_WORDS:
        return list(_SPLIT_WORDS[word])
    if "'" not in word:
        return [word]
    if word.endswith("n't") and len(word) > 3:
        stem = word[:-3]
        return [*_split_word(stem), "n't"] if stem not in _NEGATION_STEMS else [stem, "n't"]
    for clitic in CLITICS[1:]:
        if word.endswith(clitic) and len(word) > len(clitic):
            return [*_split_word(word[: -len(clitic)]), clitic]
    # an apostrophe elsewhere ("o'clock", "rock'n'roll"): keep the word whole
    return [word]

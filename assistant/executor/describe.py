"""Which perceived table fits the words said about it: "the round table", "the big table", "the desk".

Perception reports a furniture *category* (small table, large table, chair, couch, bed) and
the floor cells it covers, not the model. The furniture catalogue (product knowledge, not the
home's layout, ``catalogue.yaml``) says which models a word can mean — "round" the round table, "coffee" the coffee
table, "square" the coffee and the dinner table (by their ``shape``), "desk" the desk — and so
which category and roughly what footprint area to expect. :func:`description_fit` scores a
perceived entity against the words: 1 when it agrees with some model the words can mean, less
the more its category or its footprint area disagrees, never 0 (perception may have seen only
part of a table, and people call a big coffee table "the big table").
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from functools import lru_cache

from assistant.world import Entity, load_catalogue

__all__ = ["description_fit", "models_for_word"]

#: factor for a category that disagrees with the words
WRONG_CATEGORY = 0.4
#: factor for the area: exp(-AREA_SLOPE · |ln(perceived / expected)|), at least AREA_FLOOR
AREA_SLOPE = 0.8
AREA_FLOOR = 0.35


@lru_cache(maxsize=None)
def models_for_word(word: str) -> tuple[tuple[str, float], ...]:
    """(category, footprint area m²) of every catalogue model whose name or shape contains
    ``word`` ("round" → the round table; "square" → coffee and dinner table)."""
    from assistant.world import load_catalogue

    out = []
    for name, model in load_catalogue().models.items():
        words = set(name.lower().split()) | {model.shape.lower()}
        if word.lower() in words:
            area = model.length_m * model.width_m
            if model.shape == "round":
                area *= math.pi / 4
            out.append((model.category, area))
    return tuple(out)


def _word_fit(word: str, entity: Entity) -> float:
    """How well ``entity`` agrees with one descriptor or support word (1 when it says nothing
    the robot can check)."""
    category = entity.category
    catalogue = load_catalogue()
    sizes = catalogue.words.sizes
    if word in sizes:
        return 1.0 if category == sizes[word] else WRONG_CATEGORY
    suggested = catalogue.categories_of(word)  # "desk" → large table; "shelf" → either table
    if len(suggested) == 1 and not models_for_word(word):
        return 1.0 if category == suggested[0] else WRONG_CATEGORY
    models = models_for_word(word)
    if not models:
        return 1.0
    area = entity.area_m2
    best = 0.0
    for model_category, expected in models:
        fit = 1.0 if model_category == category else WRONG_CATEGORY
        if area > 0 and expected > 0:
            fit *= max(AREA_FLOOR, math.exp(-AREA_SLOPE * abs(math.log(area / expected))))
        best = max(best, fit)
    return best


def description_fit(support: str | None, descriptors: Sequence[str], entity: Entity) -> float:
    """In (0, 1]: how well a perceived table ``entity`` fits the support word said ("desk",
    "nightstand") and the descriptors ("small", "round", "coffee"). Not a table → 1 (the
    words are about tables)."""
    if entity.category not in ("small table", "large table"):
        return 1.0
    words = [w for w in descriptors if w]
    if support and support != "table":
        words.append(support)
    fit = 1.0
    for word in dict.fromkeys(words):
        fit *= _word_fit(word, entity)
    return fit

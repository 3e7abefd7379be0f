from collections import Counter

import pytest
from assistant.errors import NotFittedError

from assistant.language.chunker import NestedChunker, level_tags, merge_levels, repair_labels
from assistant.language.corpus import read_corpus
from assistant.language.tree import ChunkTree


def test_level_encoding_round_trips_nested_trees_with_adjacent_siblings():
    tree = ChunkTree.from_labels(
        "go left take a right and the mug is on the table".split(),
        ["VB", "DIR", "VB", "DT", "DIR", "CC", "DT", "NN", "VBZ", "ON", "DT", "FUR"],
        ["ORMTP"] * 2 + ["ORMTP-ORMRP"] * 3 + ["O"] + ["OBTP"] * 3 + ["OBTP-FURTP"] * 3,
        start_depths=[0, -1, 0, -1, -1, -1, 0, -1, -1, 1, -1, -1])
    assert tree.bracketed() == ("[ORMTP go left] [ORMTP [ORMRP take a right]] and "
                                "[OBTP the mug is [FURTP on the table]]")
    labels, starts = tree.nested_labels(), tree.start_depths()
    levels = [level_tags(labels, starts, d) for d in range(3)]
    assert levels[0][:3] == ["B-ORMTP", "I-ORMTP", "B-ORMTP"]
    assert merge_levels(levels) == (labels, starts)
    labels2, starts2 = merge_levels(levels)
    again = ChunkTree.from_labels(tree.words, tree.pos_tags, labels2, start_depths=starts2)
    assert again.bracketed() == tree.bracketed()


def test_repair_replaces_paths_the_grammar_never_allowed():
    allowed = Counter({"OBTP": 5, "OBTP-FURTP": 3, "FURTP": 2})
    labels, starts = repair_labels(["OBTP", "OBTP-FURTP-FURTP", "FURTP-OBTP"], [0, -1, 5], allowed, allowed)
    assert labels == ["OBTP", "OBTP-FURTP", "FURTP"]
    assert starts == [0, 1, 0]  # a new chunk opens where the path changes


def test_untrained_and_empty():
    with pytest.raises(NotFittedError):
        NestedChunker().label(["go"], ["VB"])
    with pytest.raises(ValueError):
        NestedChunker().fit([])


def test_learns_the_corpus_and_always_returns_a_valid_tree(small_corpus):
    trees = read_corpus(small_corpus).trees()
    chunker = NestedChunker(max_iterations=60).fit(trees)
    assert chunker.accuracy(trees) > 0.9  # fits its own training data
    labels, starts = chunker.label("zorp the blah blah".split(), ["NN", "DT", "NN", "NN"])
    assert len(labels) == 4 and all(l == "O" or l in chunker.paths_ for l in labels)
    tree = chunker.parse(["go"], ["VB"])
    assert tree.words == ["go"]
    assert chunker.label([], []) == ([], [])

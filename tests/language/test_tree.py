from assistant.language import Chunk, ChunkTree, Token


def _figure_4_4():
    # "the keys are on the white stand in the living room" as in dissertation Figure 4.4
    words = "the keys are on the white stand in the living room".split()
    pos = ["DT", "NNS", "VBP", "ON", "DT", "JJ", "FUR", "IN", "DT", "JJ", "RM"]
    labels = ["OBTP"] * 3 + ["OBTP-FURTP"] * 4 + ["OBTP-FURTP-ORMTP"] * 4
    return words, pos, labels


def test_labels_decode_to_the_nested_tree_and_back():
    words, pos, labels = _figure_4_4()
    tree = ChunkTree.from_labels(words, pos, labels)
    assert tree.bracketed() == "[OBTP the keys are [FURTP on the white stand [ORMTP in the living room]]]"
    assert tree.nested_labels() == labels
    assert tree.words == words and tree.pos_tags == pos
    (obtp, parent, depth), (furtp, p2, d2), (ormtp, p3, d3) = tree.chunks()
    assert parent is None and depth == 0 and p2 is obtp and p3 is furtp and d3 == 2
    assert furtp.own_tokens[-1] == Token("stand", "FUR")
    assert ormtp.text == "in the living room"


def test_boundaries_split_adjacent_chunks_of_the_same_label():
    words = "turn left go forward".split()
    pos = ["VB", "DIR", "VB", "RB"]
    labels = ["IRMRP"] * 4
    merged = ChunkTree.from_labels(words, pos, labels)
    assert merged.bracketed() == "[IRMRP turn left go forward]"
    split = ChunkTree.from_labels(words, pos, labels, boundaries=[True, False, True, False])
    assert split.bracketed() == "[IRMRP turn left] [IRMRP go forward]"
    assert split.boundaries() == [True, False, True, False]


def test_words_outside_chunks_and_words_after_a_nested_chunk():
    tree = ChunkTree([Chunk("ORMTP", [Token("go", "VB"), Chunk("ORMRP", [Token("left", "DIR")]),
                                      Token("then", "RB")]), Token("and", "CC")])
    assert tree.nested_labels() == ["ORMTP", "ORMTP-ORMRP", "ORMTP", "O"]
    again = ChunkTree.from_labels(tree.words, tree.pos_tags, tree.nested_labels(), tree.boundaries())
    assert again.bracketed() == tree.bracketed()

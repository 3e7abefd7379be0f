import json

import pytest

from assistant.language.consistency import (conventions, duplicate_agreement,
                                            leave_one_out_context, ngram_agreement,
                                            window_ceiling)
from assistant.language.tree import ChunkTree


def tree(text: str, pos: str, labels: str) -> ChunkTree:
    return ChunkTree.from_labels(text.split(), pos.split(), labels.split())


#: "go forward" annotated three ways: twice inside the room phrase, once outside
GO_IN = tree("go forward", "VB RB", "ORMTP ORMTP")
GO_OUT = tree("go forward", "VB RB", "O O")
TURN = tree("turn left", "VB DIR", "IRMRP IRMRP")


def test_window_ceiling_is_the_majority_share_of_each_context():
    trees = [GO_IN, GO_IN, GO_OUT, TURN]
    result = window_ceiling(trees, 1)
    # contexts: (<s> go forward) ×3 → ORMTP 2 / O 1; (go forward </s>) ×3 likewise; turn ×1 each
    assert result["words"] == 8
    assert result["ceiling"] == pytest.approx((2 + 2 + 1 + 1) / 8)
    assert result["repeated_word_share"] == pytest.approx(6 / 8)
    assert result["repeated_agreement"] == pytest.approx(4 / 6)


def test_the_ceiling_is_reached_by_a_consistent_file():
    result = window_ceiling([GO_IN, GO_IN, TURN], 2)
    assert result["ceiling"] == 1.0 and result["repeated_agreement"] == 1.0


def test_leave_one_out_labels_each_word_from_the_others_and_backs_off():
    trees = [GO_IN, GO_IN, GO_OUT, tree("go back", "VB RB", "IRMRP IRMRP")]
    result = leave_one_out_context(trees, 1)
    # the two GO_IN copies see ORMTP ×1 / O ×1 left (tie → first seen: ORMTP) → right;
    # GO_OUT sees ORMTP ×2 → wrong; "go back": "go" backs off to width 0 ("go" alone:
    # ORMTP ×2, O ×1 → ORMTP, wrong), "back" is unique even alone → O, wrong
    assert result["words"] == 8
    assert result["accuracy"] == pytest.approx(4 / 8)
    assert result["by_width"]["1"] == 6 and result["by_width"]["0"] == 1 and result["by_width"]["-1"] == 1


def test_ngram_agreement_counts_whole_labellings():
    result = ngram_agreement([GO_IN, GO_IN, GO_OUT, TURN], 2)
    assert result["ngrams"] == 1 and result["occurrences"] == 3
    assert result["agreement"] == pytest.approx(2 / 3)
    assert result["examples"][0] == {"ngram": "go forward", "occurrences": 3, "labellings": 2}


def test_identical_descriptions_are_compared_pairwise():
    result = duplicate_agreement([GO_IN, GO_OUT, GO_IN, TURN])
    assert result["groups"] == 1 and result["descriptions"] == 3 and result["pairs"] == 3
    assert result["identical_pairs"] == 1
    assert result["pairwise_word_agreement"] == pytest.approx(2 / 6)


def test_conventions_count_the_leading_motion_and_the_first_turn():
    a = tree("um go forward and turn left", "IGN VB RB CC VB DIR",
             "O ORMTP ORMTP ORMTP ORMTP-ORMRP ORMTP-ORMRP")
    b = tree("go forward and turn left", "VB RB CC VB DIR", "O O O ORMTP-ORMRP ORMTP-ORMRP")
    c = conventions([a, b])
    assert c["leading motion verb: outermost label"] == {"ORMTP": 1, "O": 1}
    assert c["leading motion + 'and' + turn: motion label"] == {"ORMTP": 1, "O": 1}
    assert c["first turn verb before a direction: label"] == {"ORMTP-ORMRP": 2}
    assert c["filler um/uh: inside a chunk?"] == {"outside": 1}
    assert c["object phrases per description"] == {"0": 2}


def test_eval_tagging_consistency_option(tiny_corpus, capsys):
    from assistant.cli import main

    assert main(["eval", "tagging", "--consistency", str(tiny_corpus), "--folds", "2", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)["consistency"][str(tiny_corpus)]
    assert report["descriptions"] == 60
    assert [w["k"] for w in report["window_ceiling"]] == [0, 1, 2, 3]
    ceilings = [w["ceiling"] for w in report["window_ceiling"]]
    assert ceilings == sorted(ceilings) and ceilings[-1] <= 1.0   # wider context, higher ceiling
    assert report["cross_validation"]["folds"] == 2
    assert 0.3 < report["cross_validation"]["chunk_accuracy"] <= 1.0
    assert main(["eval", "tagging", "--consistency", str(tiny_corpus), "--folds", "0"]) == 0
    out = capsys.readouterr().out
    assert "ceiling (in-sample majority)" in out and "identical descriptions" in out
    assert "within-file" not in out


def test_eval_tagging_consistency_names_a_missing_file(capsys):
    from assistant.cli import main

    assert main(["eval", "tagging", "--consistency", "/no/such/real.xml"]) == 2
    assert "/no/such/real.xml" in capsys.readouterr().err

import json

from assistant.cli import main


def test_eval_tagging_json_reports_cross_validation_and_test_sets(tiny_corpus, capsys):
    status = main(["eval", "tagging", "--corpus", str(tiny_corpus), "--test", str(tiny_corpus),
                   "--folds", "2", "--json"])
    assert status == 0
    out = json.loads(capsys.readouterr().out)
    cv = out["results"]["cross_validation"]
    assert cv["folds"] == 2 and 0.7 < cv["pos_accuracy"] <= 1 and 0.3 < cv["chunk_accuracy"] <= 1
    test = out["results"][str(tiny_corpus)]
    assert test["pos_accuracy"] > 0.95 and test["chunk_accuracy"] > 0.85  # its own training data
    assert {"chunk_exact_match", "chunk_accuracy_gold_pos", "pos_confusions", "chunk_confusions"} <= set(test)


def test_eval_tagging_table(tiny_corpus, capsys):
    assert main(["eval", "tagging", "--corpus", str(tiny_corpus), "--test", str(tiny_corpus),
                 "--folds", "0"]) == 0
    out = capsys.readouterr().out
    assert "POS acc" in out and "chunk acc" in out and "most frequent errors" in out


def test_coverage_names_what_the_training_corpus_lacks():
    from assistant.eval.tagging import coverage
    from assistant.language.tree import ChunkTree

    train = [ChunkTree.from_labels(["go", "left"], ["VB", "DIR"], ["IRMRP", "IRMRP"])]
    test = [ChunkTree.from_labels(["go", "right", "brian"], ["VB", "DIR", "WHO"], ["IRMRP", "IRMRP", "O"])]
    cov = coverage(train, test)
    assert cov["unseen_paths"] == [{"path": "O", "words": 1}]
    assert abs(cov["unseen_path_word_share"] - 1 / 3) < 1e-9
    assert [w["word"] for w in cov["oov_words"]] == ["right", "brian"]


def test_a_missing_test_file_is_reported_before_training(tiny_corpus, capsys):
    assert main(["eval", "tagging", "--corpus", str(tiny_corpus), "--test", "/no/such/file.xml",
                 "--folds", "0"]) == 2
    assert "no such corpus file: /no/such/file.xml" in capsys.readouterr().err


def test_the_evaluation_returns_its_report_and_prints_nothing(tiny_corpus, capsys):
    from assistant.eval.tagging import evaluate_tagging

    heard = []
    report = evaluate_tagging([tiny_corpus], [], folds=2,
                              progress=lambda what, done=None, total=None: heard.append((what, done, total)))
    assert capsys.readouterr().out == ""
    assert list(report["results"]) == ["cross_validation"]
    assert report["results"]["cross_validation"]["folds"] == 2
    assert ("cross-validation folds", 1, 2) in heard  # the second fold was announced

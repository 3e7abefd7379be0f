"""``assistant eval tagging``: POS and nested-chunk accuracy (dissertation 4.2.4).

Two experiments, as in the dissertation's table:

(a) k-fold cross-validation on the training corpus (ours by default);
(b) trained on the whole training corpus, tested on each test file a user points at (by
    default the CSISL real descriptions and templates, if ``../shared/realdata/csisl/`` is
    beside the checkout).

Test words are the annotated words of each description (the gold tokenization). Reported per
set: POS accuracy; nested chunk-label accuracy per word with the predicted POS tags (what the
product does) and with the gold ones; the share of descriptions whose labels are all right
(exact match); and a summary of the most frequent confusions.
"""

from __future__ import annotations

from pathlib import Path

from assistant.eval.progress import Progress, no_progress

__all__ = ["evaluate_tagging", "consistency_reports", "score", "coverage", "cross_validate",
           "default_test_paths"]

CSISL_FILES = ("csisl_real_descriptions_annotated.xml", "csisl_templates149_annotated.xml")


def default_test_paths() -> list[Path]:
    """The CSISL real descriptions and templates, those of them that are there."""
    from assistant.eval.csisl import csisl_folder

    folder = csisl_folder()
    return [folder / name for name in CSISL_FILES if (folder / name).exists()]


def score(tagger, chunker, trees) -> dict:
    """Accuracy figures and confusion counts of a tagger + chunker on gold trees."""
    from collections import Counter

    pos_total = pos_ok = chunk_ok = chunk_gold_ok = exact = exact_gold = pos_exact = 0
    pos_conf: Counter = Counter()
    chunk_conf: Counter = Counter()
    for tree in trees:
        words, gold_pos, gold_labels = tree.words, tree.pos_tags, tree.nested_labels()
        pos, corrections, _ = tagger.analyse(words)
        labels, _ = chunker.label([corrections.get(w, w) for w in words], pos)
        labels_gold_pos, _ = chunker.label(words, gold_pos)
        n = len(words)
        pos_total += n
        pos_hits = sum(a == b for a, b in zip(pos, gold_pos))
        pos_ok += pos_hits
        pos_exact += pos_hits == n
        hits = sum(a == b for a, b in zip(labels, gold_labels))
        chunk_ok += hits
        exact += hits == n
        hits_gold = sum(a == b for a, b in zip(labels_gold_pos, gold_labels))
        chunk_gold_ok += hits_gold
        exact_gold += hits_gold == n
        pos_conf.update((g, p) for g, p in zip(gold_pos, pos) if g != p)
        chunk_conf.update((g, p) for g, p in zip(gold_labels, labels) if g != p)
    n_desc = len(trees)
    return {
        "descriptions": n_desc,
        "words": pos_total,
        "pos_accuracy": pos_ok / pos_total if pos_total else 0.0,
        "pos_exact_match": pos_exact / n_desc if n_desc else 0.0,
        "chunk_accuracy": chunk_ok / pos_total if pos_total else 0.0,
        "chunk_exact_match": exact / n_desc if n_desc else 0.0,
        "chunk_accuracy_gold_pos": chunk_gold_ok / pos_total if pos_total else 0.0,
        "chunk_exact_match_gold_pos": exact_gold / n_desc if n_desc else 0.0,
        "_pos_confusions": pos_conf,
        "_chunk_confusions": chunk_conf,
    }


def coverage(train_trees, test_trees, top: int = 10) -> dict:
    """What a test set has that the training corpus lacks: nested-label paths never seen in
    training (share of test words, most frequent), words never seen (share of tokens, most
    frequent), and the paths whose share of words differs most between the two."""
    from collections import Counter

    train_paths = Counter(l for t in train_trees for l in t.nested_labels())
    train_words = Counter(w for t in train_trees for w in t.words)
    test_paths = Counter(l for t in test_trees for l in t.nested_labels())
    test_words = Counter(w for t in test_trees for w in t.words)
    n_test = sum(test_paths.values()) or 1
    n_train = sum(train_paths.values()) or 1
    unseen_paths = Counter({p: n for p, n in test_paths.items() if p not in train_paths})
    unseen_words = Counter({w: n for w, n in test_words.items() if w not in train_words})
    shift = sorted(set(test_paths) | set(train_paths),
                   key=lambda p: -abs(test_paths[p] / n_test - train_paths[p] / n_train))
    return {
        "unseen_path_word_share": sum(unseen_paths.values()) / n_test,
        "unseen_paths": [{"path": p, "words": n} for p, n in unseen_paths.most_common(top)],
        "oov_token_share": sum(unseen_words.values()) / n_test,
        "oov_words": [{"word": w, "count": n} for w, n in unseen_words.most_common(top)],
        "path_share_shift": [{"path": p, "test": test_paths[p] / n_test,
                              "train": train_paths[p] / n_train} for p in shift[:top]],
    }


def cross_validate(trees, folds: int, progress: Progress = no_progress) -> dict:
    """k-fold cross-validation of the tagger and chunker on ``trees`` (seeded folds); accuracy
    figures weighted over the folds, each fold's lowest, and the summed confusion counts."""
    import numpy as np
    from sklearn.model_selection import KFold

    from assistant.language.chunker import NestedChunker
    from assistant.language.postag import SemanticPosTagger

    folds = min(folds, len(trees))
    splitter = KFold(n_splits=folds, shuffle=True, random_state=0)
    totals: dict = {}
    per_fold = []
    for fold, (train_idx, test_idx) in enumerate(splitter.split(np.arange(len(trees)))):
        progress("cross-validation folds", fold, folds)
        train = [trees[i] for i in train_idx]
        test = [trees[i] for i in test_idx]
        tagger = SemanticPosTagger().fit([list(zip(t.words, t.pos_tags)) for t in train])
        chunker = NestedChunker().fit(train)
        result = score(tagger, chunker, test)
        per_fold.append(result)
        for key, value in result.items():
            if key.startswith("_"):
                totals[key] = totals.get(key, None) or type(value)()
                totals[key].update(value)
    words = sum(r["words"] for r in per_fold)
    descs = sum(r["descriptions"] for r in per_fold)
    out = {"descriptions": descs, "words": words, "folds": folds}
    for key in ("pos_accuracy", "chunk_accuracy", "chunk_accuracy_gold_pos"):
        out[key] = sum(r[key] * r["words"] for r in per_fold) / words
        out[key + "_fold_min"] = min(r[key] for r in per_fold)
    for key in ("pos_exact_match", "chunk_exact_match", "chunk_exact_match_gold_pos"):
        out[key] = sum(r[key] * r["descriptions"] for r in per_fold) / descs
    out.update(totals)
    return out


def evaluate_tagging(train_paths=None, test_paths=None, *, folds: int = 10, top: int = 8,
                     progress: Progress = no_progress) -> dict:
    """Experiments (a) and (b): ``folds``-fold cross-validation on the training corpus (skipped
    below 2) and, for each of ``test_paths``, the model trained on the whole training corpus.

    ``train_paths`` default to the repository's corpus, ``test_paths`` (``None``) to the CSISL
    files when present (``[]``: none). Returns the JSON report: ``training_corpus``,
    ``training_descriptions``, ``training_seconds`` and ``results`` (``cross_validation`` and
    one entry per test file, with the ``top`` most frequent confusions)."""
    import time

    from assistant.errors import AssistantError
    from assistant.language.corpus import default_corpus_paths, read_corpora, read_corpus
    from assistant.language.pipeline import LanguageModel

    train_paths = [Path(p) for p in train_paths] if train_paths else default_corpus_paths()
    if not train_paths:
        raise AssistantError("no training corpus: corpus/*.xml is empty; give --corpus PATH")
    test_paths = default_test_paths() if test_paths is None else [Path(p) for p in test_paths]
    missing = [str(p) for p in (*train_paths, *test_paths) if not Path(p).exists()]
    if missing:
        raise AssistantError(f"no such corpus file: {', '.join(missing)}; give existing "
                             "CSISL-format XML files with --corpus / --test")
    progress(f"training corpus: {', '.join(map(str, train_paths))}")
    progress(f"test files: {', '.join(map(str, test_paths)) or '(none)'}")

    corpus = read_corpora(train_paths)
    if corpus.problems:
        progress(f"training corpus: {len(corpus.problems)} problems (first: {corpus.problems[0]})")
    trees = corpus.trees()
    results: dict = {}
    if folds and folds > 1:
        started = time.perf_counter()
        results["cross_validation"] = cross_validate(trees, folds, progress)
        results["cross_validation"]["seconds"] = time.perf_counter() - started
    started = time.perf_counter()
    if test_paths:
        progress("training the tagger and chunker on the whole training corpus")
    model = LanguageModel.load(train_paths, use_cache=False) if test_paths else None
    train_seconds = time.perf_counter() - started
    for path in test_paths:
        test = read_corpus(path)
        if test.problems:
            progress(f"{path}: {len(test.problems)} problems read around (see `--json`)")
        result = score(model.tagger, model.chunker, test.trees())
        result["problems"] = test.problems
        result["coverage"] = coverage(trees, test.trees(), top)
        results[str(path)] = result
    return {
        "training_corpus": [str(p) for p in train_paths],
        "training_descriptions": len(trees),
        "training_seconds": train_seconds,
        "results": {k: _public(v, top) for k, v in results.items()},
    }


def consistency_reports(paths, folds: int = 10, progress: Progress = no_progress) -> dict:
    """``--consistency PATH``: path → the self-consistency report of each file (see
    :mod:`assistant.language.consistency`) with its within-file k-fold CV figure (unless
    ``folds`` < 2)."""
    import time

    from assistant.errors import AssistantError
    from assistant.language.consistency import consistency_report
    from assistant.language.corpus import read_corpus

    missing = [str(p) for p in paths if not Path(p).exists()]
    if missing:
        raise AssistantError(f"no such corpus file: {', '.join(missing)}; give CSISL-format XML "
                             "files with --consistency PATH")
    reports = {}
    for path in paths:
        read = read_corpus(path)
        trees = [t for t in read.trees() if t.words]
        if not trees:
            raise AssistantError(f"{path}: no readable descriptions to measure")
        progress(f"consistency of {path}")
        report = consistency_report(trees)
        if folds and folds > 1:
            started = time.perf_counter()
            cv = cross_validate(trees, folds, progress)
            report["cross_validation"] = {k: v for k, v in cv.items() if not k.startswith("_")}
            report["cross_validation"]["seconds"] = time.perf_counter() - started
        reports[str(path)] = report
    return reports


def _public(result: dict, top: int) -> dict:
    from assistant.language.consistency import errors_by_construction

    out = {k: v for k, v in result.items() if not k.startswith("_")}
    out["errors_by_construction"] = [{"construction": name, "count": n} for name, n in
                                     errors_by_construction(result["_chunk_confusions"])]
    out["pos_confusions"] = [{"gold": g, "predicted": p, "count": n}
                             for (g, p), n in result["_pos_confusions"].most_common(top)]
    out["chunk_confusions"] = [{"gold": g, "predicted": p, "count": n}
                               for (g, p), n in result["_chunk_confusions"].most_common(top)]
    return out

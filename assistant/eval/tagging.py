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

import argparse
import sys
from pathlib import Path

__all__ = ["add_arguments", "run", "score", "default_test_paths"]

CSISL_FILES = ("csisl_real_descriptions_annotated.xml", "csisl_templates149_annotated.xml")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--corpus", action="append", metavar="PATH",
                        help="training corpus file or folder (repeatable; default: the "
                             "repository's corpus/*.xml or $ASSISTANT_CORPUS)")
    parser.add_argument("--test", action="append", metavar="PATH",
                        help="test corpus file (repeatable; default: the two CSISL XML files "
                             "in ../shared/realdata/csisl/ if present)")
    parser.add_argument("--no-test", action="store_true",
                        help="skip experiment (b): only cross-validate on the training corpus")
    parser.add_argument("--folds", type=int, default=10,
                        help="cross-validation folds on the training corpus (0 to skip; default 10)")
    parser.add_argument("--top", type=int, default=8, help="confusions to list per set (default 8)")
    parser.add_argument("--consistency", action="append", metavar="PATH",
                        help="instead of (a)/(b): measure how consistent the annotation of PATH is "
                             "with itself (context-majority ceilings, repeated n-grams, identical "
                             "descriptions, conventions) and, unless --folds 0, cross-validate the "
                             "chunker within PATH (repeatable)")


def default_test_paths() -> list[Path]:
    from assistant.language.corpus import repo_root

    folder = repo_root().parent / "shared" / "realdata" / "csisl"
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


def _cross_validate(trees, folds: int) -> dict:
    import numpy as np
    from sklearn.model_selection import KFold

    from assistant.language.chunker import NestedChunker
    from assistant.language.postag import SemanticPosTagger

    folds = min(folds, len(trees))
    splitter = KFold(n_splits=folds, shuffle=True, random_state=0)
    totals: dict = {}
    per_fold = []
    for train_idx, test_idx in splitter.split(np.arange(len(trees))):
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


def run(args: argparse.Namespace) -> int:
    import time

    from assistant.cli.common import emit_json, print_table
    from assistant.errors import AssistantError
    from assistant.language.consistency import errors_by_construction
    from assistant.language.corpus import default_corpus_paths, read_corpora, read_corpus
    from assistant.language.pipeline import LanguageModel

    if getattr(args, "consistency", None):
        return _run_consistency(args)
    train_paths = [Path(p) for p in args.corpus] if args.corpus else default_corpus_paths()
    if not train_paths:
        raise AssistantError("no training corpus: corpus/*.xml is empty; give --corpus PATH")
    test_paths = ([] if args.no_test else
                  [Path(p) for p in args.test] if args.test else default_test_paths())
    missing = [str(p) for p in (*train_paths, *test_paths) if not Path(p).exists()]
    if missing:
        raise AssistantError(f"no such corpus file: {', '.join(missing)}; give existing "
                             "CSISL-format XML files with --corpus / --test")
    log = sys.stderr
    print(f"training corpus: {', '.join(map(str, train_paths))}", file=log)
    print(f"test files: {', '.join(map(str, test_paths)) or '(none)'}", file=log)

    corpus = read_corpora(train_paths)
    if corpus.problems:
        print(f"training corpus: {len(corpus.problems)} problems (first: {corpus.problems[0]})",
              file=log)
    trees = corpus.trees()
    rows = []
    results: dict = {}
    if args.folds and args.folds > 1:
        started = time.perf_counter()
        results["cross_validation"] = _cross_validate(trees, args.folds)
        results["cross_validation"]["seconds"] = time.perf_counter() - started
        rows.append(("training corpus", f"{results['cross_validation']['folds']}-fold CV",
                     results["cross_validation"]))
    started = time.perf_counter()
    model = LanguageModel.load(train_paths, use_cache=False) if test_paths else None
    train_seconds = time.perf_counter() - started
    for path in test_paths:
        test = read_corpus(path)
        if test.problems:
            print(f"{path}: {len(test.problems)} problems read around (see `--json`)", file=log)
        result = score(model.tagger, model.chunker, test.trees())
        result["problems"] = test.problems
        result["coverage"] = coverage(trees, test.trees(), args.top)
        results[str(path)] = result
        rows.append((Path(path).name, "trained on corpus", result))

    if args.json:
        emit_json({
            "training_corpus": [str(p) for p in train_paths],
            "training_descriptions": len(trees),
            "training_seconds": train_seconds,
            "results": {k: _public(v, args.top) for k, v in results.items()},
        })
        return 0
    if model is not None:
        print(f"trained on {len(trees)} descriptions in {train_seconds:.1f} s")
    print_table(
        [(name, how, r["descriptions"], r["words"], _pct(r["pos_accuracy"]),
          _pct(r["chunk_accuracy"]), _pct(r["chunk_accuracy_gold_pos"]),
          _pct(r["chunk_exact_match"])) for name, how, r in rows],
        ["test set", "method", "descr.", "words", "POS acc", "chunk acc", "chunk acc (gold POS)",
         "chunk exact"],
    )
    for name, _, r in rows:
        print(f"\n{name}: most frequent errors (gold → predicted, count)")
        for label, conf in (("POS", r["_pos_confusions"]), ("chunk", r["_chunk_confusions"])):
            top = conf.most_common(args.top)
            print(f"  {label:5s} " + ("; ".join(f"{g} → {p} ×{n}" for (g, p), n in top) or "none"))
        print("  chunk errors by construction (share of words): " + "; ".join(
            f"{name} ×{n} ({_pct(n / r['words'])})"
            for name, n in errors_by_construction(r["_chunk_confusions"])))
        cov = r.get("coverage")
        if cov:
            print(f"  not in the training corpus: {_pct(cov['unseen_path_word_share'])} of words "
                  f"have a label path never seen ("
                  + ", ".join(f"{u['path']} ×{u['words']}" for u in cov["unseen_paths"][:5])
                  + f"); {_pct(cov['oov_token_share'])} of tokens are unseen words ("
                  + ", ".join(f"{u['word']} ×{u['count']}" for u in cov["oov_words"][:8]) + ")")
            print("  label share test vs training: " + "; ".join(
                f"{u['path']} {_pct(u['test'])} vs {_pct(u['train'])}"
                for u in cov["path_share_shift"][:6]))
    return 0


def _run_consistency(args: argparse.Namespace) -> int:
    """``--consistency PATH``: the self-consistency report of each file (see
    :mod:`assistant.language.consistency`) and its within-file k-fold CV figure."""
    import time

    from assistant.cli.common import emit_json, print_table
    from assistant.errors import AssistantError
    from assistant.language.consistency import consistency_report
    from assistant.language.corpus import read_corpus

    missing = [p for p in args.consistency if not Path(p).exists()]
    if missing:
        raise AssistantError(f"no such corpus file: {', '.join(missing)}; give CSISL-format XML "
                             "files with --consistency PATH")
    reports = {}
    for path in args.consistency:
        read = read_corpus(path)
        trees = [t for t in read.trees() if t.words]
        if not trees:
            raise AssistantError(f"{path}: no readable descriptions to measure")
        report = consistency_report(trees)
        if args.folds and args.folds > 1:
            started = time.perf_counter()
            cv = _cross_validate(trees, args.folds)
            report["cross_validation"] = {k: v for k, v in cv.items() if not k.startswith("_")}
            report["cross_validation"]["seconds"] = time.perf_counter() - started
        reports[str(path)] = report
    if args.json:
        emit_json({"consistency": reports})
        return 0
    for path, r in reports.items():
        print(f"{path}: {r['descriptions']} descriptions, {r['words']} words")
        print_table(
            [(f"±{w['k']}", w["contexts"], _pct(w["ceiling"]), _pct(w["repeated_word_share"]),
              _pct(w["repeated_agreement"]), _pct(l["accuracy"]))
             for w, l in zip(r["window_ceiling"], r["leave_one_out_context"])],
            ["context (words+POS)", "contexts", "ceiling (in-sample majority)",
             "words in repeated contexts", "majority agreement there",
             "leave-one-out context majority"],
        )
        print("repeated n-grams (with POS), share of occurrences labelled as the n-gram's "
              "majority: " + "; ".join(f"{g['n']}-grams {_pct(g['agreement'])} of "
                                       f"{g['occurrences']}" for g in r["ngram_agreement"]))
        d = r["duplicates"]
        print(f"identical descriptions: {d['groups']} groups ({d['descriptions']} descriptions), "
              f"{d['identical_pairs']}/{d['pairs']} pairs labelled identically, pairwise "
              f"per-word agreement {_pct(d['pairwise_word_agreement'])}")
        cv = r.get("cross_validation")
        if cv:
            print(f"within-file {cv['folds']}-fold CV (POS tagger + chunker trained on the other "
                  f"folds): POS {_pct(cv['pos_accuracy'])}, chunk {_pct(cv['chunk_accuracy'])} "
                  f"(gold POS {_pct(cv['chunk_accuracy_gold_pos'])}), exact "
                  f"{_pct(cv['chunk_exact_match'])}, {cv['seconds']:.0f} s")
        print("conventions (label choices counted):")
        for name, counts in r["conventions"].items():
            total = sum(counts.values()) or 1
            print(f"  {name}: " + ", ".join(f"{k} {v} ({_pct(v / total)})"
                                            for k, v in list(counts.items())[:5]))
        print()
    return 0


def _pct(value: float) -> str:
    return f"{100 * value:.1f}%"


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

"""``assistant eval tagging``: options and printed tables of :mod:`assistant.eval.tagging`."""

from __future__ import annotations

import argparse
from pathlib import Path

from assistant.cli.common import emit_json, percent, print_table, progress_for, show_report, whole_number

#: what ``--quick`` stands for (see assistant.cli.eval): two-fold cross-validation on our corpus, no real test files
QUICK = ("--folds", "2", "--no-test")


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
    parser.add_argument("--top", type=whole_number(0, 1000), default=8, help="confusions to list per set (default 8)")
    parser.add_argument("--consistency", action="append", metavar="PATH",
                        help="instead of (a)/(b): measure how consistent the annotation of PATH is "
                             "with itself (context-majority ceilings, repeated n-grams, identical "
                             "descriptions, conventions) and, unless --folds 0, cross-validate the "
                             "chunker within PATH (repeatable)")


def run(args: argparse.Namespace) -> int:
    from assistant.eval.tagging import consistency_reports, evaluate_tagging

    if args.folds < 0 or args.folds == 1:
        from assistant.errors import AssistantError

        raise AssistantError(f"--folds {args.folds}: give 0 (no cross-validation) or 2 or more")
    progress = progress_for(args)
    if args.consistency:
        reports = consistency_reports(args.consistency, args.folds, progress)
        if args.json:
            emit_json({"consistency": reports})
        else:
            for path, report in reports.items():
                print_consistency(path, report)
        return 0
    test_paths = [] if args.no_test else args.test
    report = evaluate_tagging(args.corpus, test_paths, folds=args.folds, top=args.top,
                              progress=progress)
    return show_report(args, report, print_report)


def _row_names(key: str, result: dict) -> tuple[str, str]:
    if key == "cross_validation":
        return "training corpus", f"{result['folds']}-fold CV"
    return Path(key).name, "trained on corpus"


def print_report(report: dict) -> None:
    """The accuracy table of (a) and (b), then each set's most frequent errors."""
    results = report["results"]
    rows = [(*_row_names(key, r), r) for key, r in results.items()]
    if any(key != "cross_validation" for key in results):
        print(f"trained on {report['training_descriptions']} descriptions in "
              f"{report['training_seconds']:.1f} s")
    print_table(
        [(name, how, r["descriptions"], r["words"], percent(r["pos_accuracy"]),
          percent(r["chunk_accuracy"]), percent(r["chunk_accuracy_gold_pos"]),
          percent(r["chunk_exact_match"])) for name, how, r in rows],
        ["test set", "method", "descr.", "words", "POS acc", "chunk acc", "chunk acc (gold POS)",
         "chunk exact"],
    )
    for name, _, r in rows:
        print(f"\n{name}: most frequent errors (gold → predicted, count)")
        for label, conf in (("POS", r["pos_confusions"]), ("chunk", r["chunk_confusions"])):
            print(f"  {label:5s} " + ("; ".join(f"{c['gold']} → {c['predicted']} ×{c['count']}"
                                               for c in conf) or "none"))
        print("  chunk errors by construction (share of words): " + "; ".join(
            f"{e['construction']} ×{e['count']} ({percent(e['count'] / r['words'])})"
            for e in r["errors_by_construction"]))
        cov = r.get("coverage")
        if cov:
            print(f"  not in the training corpus: {percent(cov['unseen_path_word_share'])} of words "
                  f"have a label path never seen ("
                  + ", ".join(f"{u['path']} ×{u['words']}" for u in cov["unseen_paths"][:5])
                  + f"); {percent(cov['oov_token_share'])} of tokens are unseen words ("
                  + ", ".join(f"{u['word']} ×{u['count']}" for u in cov["oov_words"][:8]) + ")")
            print("  label share test vs training: " + "; ".join(
                f"{u['path']} {percent(u['test'])} vs {percent(u['train'])}"
                for u in cov["path_share_shift"][:6]))


def print_consistency(path: str, r: dict) -> None:
    """One file's self-consistency report (``--consistency PATH``)."""
    print(f"{path}: {r['descriptions']} descriptions, {r['words']} words")
    print_table(
        [(f"±{w['k']}", w["contexts"], percent(w["ceiling"]), percent(w["repeated_word_share"]),
          percent(w["repeated_agreement"]), percent(l["accuracy"]))
         for w, l in zip(r["window_ceiling"], r["leave_one_out_context"])],
        ["context (words+POS)", "contexts", "ceiling (in-sample majority)",
         "words in repeated contexts", "majority agreement there",
         "leave-one-out context majority"],
    )
    print("repeated n-grams (with POS), share of occurrences labelled as the n-gram's "
          "majority: " + "; ".join(f"{g['n']}-grams {percent(g['agreement'])} of "
                                   f"{g['occurrences']}" for g in r["ngram_agreement"]))
    d = r["duplicates"]
    print(f"identical descriptions: {d['groups']} groups ({d['descriptions']} descriptions), "
          f"{d['identical_pairs']}/{d['pairs']} pairs labelled identically, pairwise "
          f"per-word agreement {percent(d['pairwise_word_agreement'])}")
    cv = r.get("cross_validation")
    if cv:
        print(f"within-file {cv['folds']}-fold CV (POS tagger + chunker trained on the other "
              f"folds): POS {percent(cv['pos_accuracy'])}, chunk {percent(cv['chunk_accuracy'])} "
              f"(gold POS {percent(cv['chunk_accuracy_gold_pos'])}), exact "
              f"{percent(cv['chunk_exact_match'])}, {cv['seconds']:.0f} s")
    print("conventions (label choices counted):")
    for name, counts in r["conventions"].items():
        total = sum(counts.values()) or 1
        print(f"  {name}: " + ", ".join(f"{k} {v} ({percent(v / total)})"
                                        for k, v in list(counts.items())[:5]))
    print()

"""How consistent the CSISL annotation is with itself: the evidence for the chunking ceiling.

Run from the repository root::

    .venv/bin/python benchmarks/csisl_annotation_consistency.py            # real + templates + ours, 10-fold CV
    .venv/bin/python benchmarks/csisl_annotation_consistency.py --folds 0  # without the CV (seconds)
    .venv/bin/python benchmarks/csisl_annotation_consistency.py --csisl DIR --corpus corpus/descriptions.xml

For each file (the real CSISL descriptions, the 149 templates, our training corpus) it prints,
side by side (definitions in :mod:`assistant.language.consistency`):

* the in-sample context-majority ceiling for ±k words (with their POS tags): the best per-word
  nested-label accuracy of any labeller deciding from that window, even one fitted to the file;
* among the words whose ±k context occurs more than once, how often they carry the majority
  label (the ceiling on that part of the file);
* the leave-one-out context-majority labeller (each word labelled from the *other* words
  sharing its context, backing off to narrower windows);
* agreement of repeated word n-grams with their majority labelling, and of identical
  descriptions with each other;
* the within-file k-fold cross-validation of the product's POS tagger + chunker
  (``--folds``; the same split as ``assistant eval tagging --corpus FILE --no-test``).

The same report for one file: ``.venv/bin/assistant eval tagging --consistency FILE``.
Nothing of the CSISL files is written anywhere; only figures are printed.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def main(argv=None) -> int:
    from assistant.cli.common import print_table
    from assistant.language.consistency import consistency_report
    from assistant.language.corpus import read_corpus
    from assistant.eval.tagging import cross_validate

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--csisl", type=Path, default=ROOT.parent / "shared" / "realdata" / "csisl",
                    help="folder of the CSISL XML files (default ../shared/realdata/csisl)")
    ap.add_argument("--corpus", type=Path, default=ROOT / "corpus" / "descriptions.xml",
                    help="our training corpus, for comparison")
    ap.add_argument("--folds", type=int, default=10,
                    help="within-file cross-validation folds (0: skip; default 10)")
    args = ap.parse_args(argv)

    files = {"CSISL real": args.csisl / "csisl_real_descriptions_annotated.xml",
             "CSISL templates": args.csisl / "csisl_templates149_annotated.xml",
             "our corpus": args.corpus}
    missing = [str(p) for p in files.values() if not p.exists()]
    if missing:
        print(f"missing: {', '.join(missing)} (give --csisl DIR / --corpus FILE)", file=sys.stderr)
        return 2
    reports = {}
    for name, path in files.items():
        trees = [t for t in read_corpus(path).trees() if t.words]
        report = consistency_report(trees)
        if args.folds > 1:
            started = time.perf_counter()
            cv = cross_validate(trees, args.folds)
            report["cv"] = (cv["chunk_accuracy"], cv["chunk_accuracy_gold_pos"], time.perf_counter() - started)
        reports[name] = report
    names = list(reports)

    def pct(x: float) -> str:
        return f"{100 * x:.1f}%"

    rows = [("descriptions / words", *(f"{r['descriptions']} / {r['words']}" for r in reports.values()))]
    for i, k in enumerate(reports[names[0]]["window_ceiling"]):
        rows.append((f"±{k['k']} ceiling (in-sample majority)",
                     *(pct(r["window_ceiling"][i]["ceiling"]) for r in reports.values())))
        rows.append((f"±{k['k']} words in repeated contexts",
                     *(pct(r["window_ceiling"][i]["repeated_word_share"]) for r in reports.values())))
        rows.append((f"±{k['k']} majority agreement there",
                     *(pct(r["window_ceiling"][i]["repeated_agreement"]) for r in reports.values())))
        rows.append((f"±{k['k']} leave-one-out context majority",
                     *(pct(r["leave_one_out_context"][i]["accuracy"]) for r in reports.values())))
    for i, g in enumerate(reports[names[0]]["ngram_agreement"]):
        rows.append((f"repeated {g['n']}-grams: majority labelling",
                     *(pct(r["ngram_agreement"][i]["agreement"]) for r in reports.values())))
    rows.append(("identical descriptions: pairs (identical)",
                 *(f"{r['duplicates']['pairs']} ({r['duplicates']['identical_pairs']})" for r in reports.values())))
    rows.append(("identical descriptions: per-word agreement",
                 *(pct(r["duplicates"]["pairwise_word_agreement"]) if r["duplicates"]["pairs"] else "-"
                   for r in reports.values())))
    if args.folds > 1:
        rows.append((f"within-file {args.folds}-fold CV chunk (pred. POS)", *(pct(r["cv"][0]) for r in reports.values())))
        rows.append((f"within-file {args.folds}-fold CV chunk (gold POS)", *(pct(r["cv"][1]) for r in reports.values())))
    print_table(rows, ["measure", *names])
    print("\nannotation conventions (share of the label choices; n = occurrences)")
    keys = list(reports[names[0]]["conventions"])
    for key in keys:
        print(f"  {key}")
        for name in names:
            counts = reports[name]["conventions"][key]
            total = sum(counts.values())
            print(f"    {name:16s} n={total:5d}  " + ", ".join(
                f"{label} {pct(n / total)}" for label, n in list(counts.items())[:4]))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""Nested chunkers compared: the CRF cascade of the product vs Brill over the encoded labels.

    .venv/bin/python benchmarks/compare_chunkers.py [--corpus TRAIN.xml ...] [--test TEST.xml ...]

The dissertation (4.2.4) chunked with NLTK's Brill tagger over (POS tag, nested label) pairs;
this trains that baseline (trigram → bigram → unigram over POS tags, ``brill24`` templates,
100 rules) and the product's :class:`~assistant.language.chunker.NestedChunker` on the same
corpus (default ``corpus/*.xml``) and prints per-word nested-label accuracy on each test file
(default: the CSISL real descriptions and templates beside the checkout), with gold POS tags
as input, and the training time of each.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--corpus", action="append")
    parser.add_argument("--test", action="append")
    parser.add_argument("--brill-rules", type=int, default=100)
    args = parser.parse_args()

    from nltk.tag import BigramTagger, DefaultTagger, TrigramTagger, UnigramTagger
    from nltk.tag.brill import brill24
    from nltk.tag.brill_trainer import BrillTaggerTrainer

    from assistant.language.chunker import NestedChunker
    from assistant.language.corpus import default_corpus_paths, read_corpora, read_corpus
    from assistant.eval.tagging import default_test_paths

    train = read_corpora(args.corpus or default_corpus_paths()).trees()
    tests = {Path(p).name: read_corpus(p).trees() for p in (args.test or default_test_paths())}
    if not train or not tests:
        print("need a training corpus and at least one test file", file=sys.stderr)
        return 2

    pairs = [list(zip(t.pos_tags, t.nested_labels())) for t in train]
    started = time.perf_counter()
    base = TrigramTagger(pairs, backoff=BigramTagger(pairs, backoff=UnigramTagger(
        pairs, backoff=DefaultTagger("O"))))
    brill = BrillTaggerTrainer(base, brill24(), trace=0, deterministic=True).train(
        pairs, max_rules=args.brill_rules, min_score=3)
    brill_seconds = time.perf_counter() - started
    started = time.perf_counter()
    crf = NestedChunker().fit(train)
    crf_seconds = time.perf_counter() - started

    def brill_accuracy(trees):
        total = right = 0
        for tree in trees:
            predicted = [label for _, label in brill.tag(tree.pos_tags)]
            gold = tree.nested_labels()
            total += len(gold)
            right += sum(p == g for p, g in zip(predicted, gold))
        return right / total

    print(f"trained on {len(train)} descriptions")
    print(f"{'chunker':34s} {'train s':>8s} " + " ".join(f"{name[:28]:>28s}" for name in tests))
    print(f"{'CRF cascade (product)':34s} {crf_seconds:8.1f} "
          + " ".join(f"{100 * crf.accuracy(t):27.1f}%" for t in tests.values()))
    print(f"{'Brill over (POS, label) pairs':34s} {brill_seconds:8.1f} "
          + " ".join(f"{100 * brill_accuracy(t):27.1f}%" for t in tests.values()))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

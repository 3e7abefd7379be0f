"""Language layer timings: training from the corpus, and tagging + chunking one command.

    .venv/bin/python benchmarks/bench_language.py [--corpus PATH ...] [--repeats N]

Prints the median time to analyse one command (tokenize → POS → nested chunks → tree) over
typical commands, and the time to train everything from the corpus (no cache), both as
medians over repeated runs: other processes share the machine, so single runs are noisy.
Targets (issue "Understanding the words"): analysis median < 5 ms, training < 60 s.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

COMMANDS = [
    "go to the bedroom and the mug is on the table next to the bed",
    "walk forward and turn right, you'll find the glasses case on the desk",
    "um okay so go straight down the hall and take a left into the living room",
    "the keys are on the small table in front of the couch on your left",
    "turn around and go past the chair, it's on the nightstand to the right of the bed",
    "enter the room on the left and walk about halfway in then turn right",
    "uh the book should be on the coffee table behind the sofa",
    "go forward until you hit the wall then turn left and the laptop is on the tabel",
]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--corpus", action="append", help="training corpus (default: corpus/*.xml)")
    parser.add_argument("--repeats", type=int, default=200, help="analyses per command")
    parser.add_argument("--train-repeats", type=int, default=3, help="trainings from scratch")
    args = parser.parse_args()

    from assistant.language.corpus import default_corpus_paths, read_corpora
    from assistant.language.pipeline import LanguageModel

    paths = [Path(p) for p in args.corpus] if args.corpus else default_corpus_paths()
    if not paths:
        print("no corpus: corpus/*.xml is empty; give --corpus PATH", file=sys.stderr)
        return 2
    corpus = read_corpora(paths)
    train_times, train_cpu, read_times = [], [], []
    for _ in range(args.train_repeats):
        started = time.perf_counter()
        again = read_corpora(paths)
        read_times.append(time.perf_counter() - started)
        started, cpu = time.perf_counter(), time.process_time()
        model = LanguageModel.train(again)
        train_times.append(time.perf_counter() - started)
        train_cpu.append(time.process_time() - cpu)
    LanguageModel.load(paths)  # train into the cache if it is not there yet
    started = time.perf_counter()
    cached = LanguageModel.load(paths)
    load_time = time.perf_counter() - started

    per_call = []
    for text in COMMANDS:
        model.analyse(text)  # warm-up
        for _ in range(args.repeats):
            started = time.perf_counter()
            model.analyse(text)
            per_call.append(time.perf_counter() - started)
    words = sum(len(model.analyse(t).tokens) for t in COMMANDS) / len(COMMANDS)
    ms = sorted(1000 * t for t in per_call)

    print(f"corpus: {len(corpus.descriptions)} descriptions from {', '.join(map(str, paths))}")
    print(f"read corpus           median {statistics.median(read_times):7.3f} s  "
          f"(n={len(read_times)})")
    print(f"train tagger+chunker  median {statistics.median(train_times):7.3f} s  "
          f"(n={len(train_times)}, min {min(train_times):.3f}, max {max(train_times):.3f})  "
          f"target < 60 s")
    print(f"  (CPU time of this process: median {statistics.median(train_cpu):.3f} s; wall time "
          f"grows when other processes share the cores)")
    print(f"load from the cache   {load_time:7.3f} s")
    print(f"analyse one command   median {statistics.median(ms):7.3f} ms  "
          f"p90 {ms[int(0.9 * len(ms))]:.3f} ms  (n={len(ms)}, {words:.1f} words/command)  "
          f"target < 5 ms")
    del cached
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

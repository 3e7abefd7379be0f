"""Parsing and grounding one command, end to end from text: median time per command.

    .venv/bin/python benchmarks/bench_parse.py [--repeats N] [--corpus-sample N]

Loads the language model and the three grounders (trained from corpus/, or from the cache),
then times ``CommandParser.parse`` on hand-written commands and on a sample of the corpus's own
descriptions, the grounders interleaved. Prints the median over commands of each command's
median time, and the 90th percentile, per grounder (milliseconds). Target (issue "From chunks to a plan"): median under 10 ms.
"""

from __future__ import annotations

import argparse
import random
import statistics
import time

COMMANDS = [
    "go to the bedroom and turn left, the statue is on the table to the left of the bed",
    "head to the living room, the mug is on the table in front of the sofa",
    "walk straight about halfway in, turn right and go forward, you will find the laptop",
    "the glasses case is in the living room on the table behind the couch",
    "go into the bedroom, make a left, the monitor is on the nightstand",
    "the fork is on the table with the chairs on your right",
    "um the mug is uh on the table",
    "asdf qwerty",
]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=30, help="timed runs per command")
    parser.add_argument("--corpus-sample", type=int, default=100, help="corpus descriptions to time")
    args = parser.parse_args()

    from assistant.grounding import CommandParser
    from assistant.grounding.training import train_grounder
    from assistant.language.corpus import default_corpus_paths, read_corpora

    t0 = time.perf_counter()
    base = CommandParser.load("combined")
    load_s = time.perf_counter() - t0
    parsers = {"combined": base,
               "learned": CommandParser(base.language, train_grounder("learned")),
               "scored": CommandParser(base.language, train_grounder("scored"))}
    texts = list(COMMANDS)
    corpus = read_corpora(default_corpus_paths())
    sample = random.Random(0).sample(corpus.descriptions, min(args.corpus_sample, len(corpus.descriptions)))
    texts += [d.text for d in sample]
    print(f"loaded language model + grounders in {load_s:.2f} s; {len(texts)} commands, "
          f"{args.repeats} repeats for the hand-written ones, 3 for the corpus sample")
    for p in parsers.values():  # warm-up
        for text in texts[:3]:
            p.parse(text)
    # interleaved: every repeat times each grounder once, so load on the machine hits all alike
    times: dict[str, list[list[float]]] = {name: [[] for _ in texts] for name in parsers}
    for i, text in enumerate(texts):
        reps = args.repeats if i < len(COMMANDS) else 3
        for _ in range(reps):
            for name, p in parsers.items():
                t = time.perf_counter()
                p.parse(text)
                times[name][i].append(time.perf_counter() - t)
    results = {}
    for name in parsers:
        per_command = sorted(statistics.median(ts) for ts in times[name])
        results[name] = per_command
        median = statistics.median(per_command) * 1000
        p90 = per_command[int(0.9 * (len(per_command) - 1))] * 1000
        print(f"{name:<8} median {median:6.2f} ms   p90 {p90:6.2f} ms   max {per_command[-1] * 1000:6.2f} ms "
              f"per command (text → plan)")
    for name in ("scored", "combined"):
        ratio = statistics.median(results[name]) / statistics.median(results["learned"])
        print(f"{name} / learned median ratio: {ratio:.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

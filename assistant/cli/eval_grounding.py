"""``assistant eval grounding``: options and printed tables of :mod:`assistant.eval.grounding`."""

from __future__ import annotations

import argparse

from assistant.cli.common import percent, print_table, progress_for, seed_int, show_report, whole_number
from assistant.eval.grounding import DISSERTATION, FIELD_ROWS, GROUNDER_NAMES

#: what ``--quick`` stands for (see assistant.cli.eval): one bootstrap round of the scored grounder
QUICK = ("--rounds", "1", "--grounder", "scored", "--no-plans")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--corpus", metavar="PATH", action="append",
                        help="training corpus files/folders (*.csv labels, *.xml trees); default corpus/")
    parser.add_argument("--test", metavar="PATH",
                        help="held-out chunk-grounding CSV (default: the CSISL template labels in "
                             "../shared/realdata/csisl when present)")
    parser.add_argument("--test-world", metavar="NAME",
                        help="the home the test commands were given in (default: apartment for the "
                             "CSISL templates, whose living room is on the right and bedroom on the left)")
    parser.add_argument("--rounds", type=whole_number(0, 1000), default=10,
                        help="bootstrap rounds for (a) (default 10; 0 skips (a))")
    parser.add_argument("--seed", type=seed_int, default=0, help="seed of the first round")
    parser.add_argument("--grounder", choices=GROUNDER_NAMES, action="append",
                        help="evaluate only this grounder (repeatable; default all three)")
    parser.add_argument("--no-plans", dest="plans", action="store_false",
                        help="skip (c): parsing every corpus description from its text")
    parser.add_argument("--descriptions", metavar="PATH", action="append",
                        help="(d) annotated descriptions (corpus XML, e.g. the real CSISL file): parse each "
                             "text and report the share whose plan names the object they name and "
                             "leaves no spatial word unused (repeatable)")
    parser.add_argument("--descriptions-world", metavar="NAME", default="apartment",
                        help="the home the descriptions were given in (default apartment)")
    parser.add_argument("--errors", type=whole_number(0, 10**6), default=0, metavar="N",
                        help="also list up to N wrongly grounded test chunks per grounder")


def run(args: argparse.Namespace) -> int:
    from assistant.eval.grounding import evaluate_grounding

    result = evaluate_grounding(args.corpus, args.test, args.test_world, rounds=args.rounds,
                                seed=args.seed, grounders=args.grounder, plans=args.plans,
                                errors=args.errors, descriptions=args.descriptions,
                                descriptions_world=args.descriptions_world, progress=progress_for(args))
    return show_report(args, result, print_report)


def _pct(value) -> str:
    return percent(value, sign="")


def print_report(result: dict) -> None:
    """Tables 4-3 and 4-4 for (a) and (b), then (c)'s plan agreement per family."""
    names = list(result["corpus_split"])
    print(f"Training corpus: {result['corpus']['commands']} commands, {result['corpus']['chunks']} chunks "
          f"({', '.join(result['corpus']['files'])})\n")
    if result["protocol"]["rounds"] > 0:
        _table("(a) our corpus, 2/3 train – 1/3 test, "
               f"{result['protocol']['rounds']} bootstrap rounds (Table 4-3 form)",
               result["corpus_split"], names)
    else:
        print("(a) skipped: --rounds 0\n")
    if result["test"] is not None:
        _print_test(result, names)
    else:
        print("(b) skipped: no test file (give --test PATH)")
    if result.get("plans"):
        _print_plans(result["plans"], names)
    for name, cov in (result.get("descriptions") or {}).items():
        _print_coverage(name, cov)


def _print_coverage(name: str, cov: dict) -> None:
    print(f"\n(d) {', '.join(cov['files'])}: parsed in {cov['world']} with {name}: plan names the object "
          f"said and leaves no spatial word unused: {cov['covered']} / {cov['descriptions']} = "
          f"{_pct(cov['share'])} %")
    print(f"    misses by why: {cov['why']}")
    print(f"    spatial words left unused most: {cov['unused_words']}")
    for m in cov["misses"]:
        print(f"  #{m['number']} '{m['text']}': object (said, plan) {m['object']} unused {m['unused']}")


def _print_test(result: dict, names) -> None:
    t = result["test"]
    _table(f"(b) trained on our corpus, tested on {t['file']} "
           f"({t['commands']} commands, {t['chunks']} chunks, world {t['world'] or 'unknown'}) "
           "(Table 4-3 form)", t["accuracy"], names)
    print("Table 4-4 form — whole command accuracy (%)")
    rows = [["dissertation (CSISL split)", _pct(DISSERTATION["scored"]["whole command"]),
             _pct(DISSERTATION["learned"]["whole command"]), "-"]]
    rows.append(["ours, (a) corpus split",
                 *[_pct(result["corpus_split"].get(n, {}).get("whole command")) for n in GROUNDER_NAMES]])
    rows.append(["ours, (b) test file",
                 *[_pct(t["accuracy"].get(n, {}).get("whole command")) for n in GROUNDER_NAMES]])
    print_table(rows, ["", "scored (WLD) / previous approach", "learned / LSTM", "combined"])
    for name, items in t.get("errors", {}).items():
        print(f"\nerrors of {name} on the test file:")
        for e in items:
            gold = {k: v for k, v in e["gold"].items() if v}
            guess = {k: v for k, v in e["guess"].items() if v}
            print(f"  #{e['command']} {e['label']} '{e['words']}': gold {gold} guess {guess}")


def _print_plans(plans: dict, names) -> None:
    print("\n(c) every corpus description parsed from its text (tagger + chunker + grounder, "
          "trained on the whole corpus): plan (room, nodes, object) equal to its annotation's (%)")
    families = sorted({f for r in plans.values() for f in r["families"]})
    rows = [[f, *[_pct(plans[n]["families"].get(f)) for n in names]] for f in families]
    rows.append(["all descriptions", *[_pct(plans[n]["agreement"]) for n in names]])
    rows.append(["compared / skipped (rows ≠ tree)",
                 *[f"{plans[n]['descriptions']} / {plans[n]['skipped']}" for n in names]])
    print_table(rows, ["family", *names])
    for name in names:
        for d in plans[name]["disagreements"]:
            print(f"  {name} #{d['number']} '{d['text']}': annotation {d['gold']} parsed {d['parsed']}")


def _table(title: str, accuracies: dict, names) -> None:
    print(title)
    rows = [[label, *[_pct(accuracies[n].get(key)) for n in names],
             _pct(DISSERTATION["learned"].get(key))] for key, label in FIELD_ROWS]
    print_table(rows, ["Grounding type", *[f"{n} (%)" for n in names], "dissertation LSTM (%)"])
    print()

"""``assistant eval grounding``: dissertation Tables 4-3 and 4-4 for the three grounders.

(a) On our corpus with the dissertation's protocol (4.4.3): two thirds of the commands train,
one third test, 10 bootstrap rounds (seeded), accuracies averaged.
(b) Trained on all of our corpus, tested on a separate label file — by default the CSISL
template chunk labels in ``../shared/realdata/csisl/`` when that folder exists (``--test``).

Accuracy per grounding type is the fraction of chunks whose field is right; *whole command*
is the fraction of commands with every chunk right in every field.
"""

from __future__ import annotations

import argparse
import random
import sys
from pathlib import Path

FIELD_ROWS = (("target room", "Target room"), ("target object", "Target Object"),
              ("reference", "Reference"), ("direction", "Direction"), ("target", "Target"),
              ("whole command", "The whole spatial command"))
#: the dissertation's figures (Tables 4-3, 4-4), printed beside ours for comparison
DISSERTATION = {"learned": {"target room": 0.985, "target object": 0.971, "reference": 0.971,
                            "direction": 0.960, "target": 1.0, "whole command": 0.897},
                "scored": {"whole command": 0.879}}
GROUNDER_NAMES = ("scored", "learned", "combined")
#: the home of the CSISL fetch study (dissertation 4.3 IV): hallway, living room on the right
CSISL_WORLD = "apartment"


def default_test_path() -> Path | None:
    shared = Path(__file__).resolve().parents[3] / "shared" / "realdata" / "csisl"
    path = shared / "csisl_templates149_chunk_groundings.csv"
    return path if path.exists() else None


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--corpus", metavar="PATH", action="append",
                        help="training corpus files/folders (*.csv labels, *.xml trees); default corpus/")
    parser.add_argument("--test", metavar="PATH",
                        help="held-out chunk-grounding CSV (default: the CSISL template labels in "
                             "../shared/realdata/csisl when present)")
    parser.add_argument("--test-world", metavar="NAME",
                        help="the home the test commands were given in (default: apartment for the "
                             "CSISL templates, whose living room is on the right and bedroom on the left)")
    parser.add_argument("--rounds", type=int, default=10, help="bootstrap rounds for (a) (default 10)")
    parser.add_argument("--seed", type=int, default=0, help="seed of the first round")
    parser.add_argument("--grounder", choices=GROUNDER_NAMES, action="append",
                        help="evaluate only this grounder (repeatable; default all three)")
    parser.add_argument("--no-plans", dest="plans", action="store_false",
                        help="skip (c): parsing every corpus description from its text")
    parser.add_argument("--descriptions", metavar="PATH", action="append",
                        help="(d) annotated descriptions (corpus XML, e.g. the real CSISL file): parse each "
                             "text and report the share whose plan names the object they name and "
                             "leaves no spatial word unused (repeatable)")
    parser.add_argument("--descriptions-world", metavar="NAME", default=CSISL_WORLD,
                        help="the home the descriptions were given in (default apartment)")
    parser.add_argument("--errors", type=int, default=0, metavar="N",
                        help="also list up to N wrongly grounded test chunks per grounder")


def bootstrap(name: str, commands, rounds: int, seed: int) -> dict[str, float]:
    """Mean accuracies over ``rounds`` random 2/3–1/3 splits of the commands."""
    from assistant.grounding.training import make_grounder

    totals: dict[str, float] = {}
    for r in range(rounds):
        shuffled = list(commands)
        random.Random(seed + r).shuffle(shuffled)
        cut = (2 * len(shuffled)) // 3
        train, test = shuffled[:cut], shuffled[cut:]
        grounder = make_grounder(name).fit([x for c in train for x in c.records],
                                           [g for c in train for g in c.groundings])
        for key, value in grounder.accuracy(test).items():
            totals[key] = totals.get(key, 0.0) + value / rounds
    return totals


def plan_agreement(parser, descriptions, commands, limit: int = 10) -> dict:
    """Parse every description's text (in its own world, as ``parse --world`` would) and compare
    (room, nodes, object) with the plan its annotation gives (its gold tree with its gold chunk
    groundings). Per family as well."""
    from assistant.grounding.plan import assemble_plan

    from assistant.world import load_world, world_names

    by_number = {c.number: c for c in commands}
    known_worlds = set(world_names())
    worlds: dict = {}
    total = agree = skipped = 0
    families: dict[str, list[int]] = {}
    disagreements = []
    for description in descriptions:
        command = by_number.get(str(description.number))
        own = [tuple(t.text for t in chunk.own_tokens) for chunk, _, _ in description.tree.chunks()]
        if command is None or [r.words for r in command.records] != own:
            skipped += 1  # label rows that are not this description's chunks
            continue
        gold = assemble_plan(description.tree, list(command.groundings))
        name = description.attributes.get("world")
        if name in known_worlds and name not in worlds:
            worlds[name] = load_world(name)
        parser.world = worlds.get(name)  # the home the description was given in
        got = parser.parse(description.text).plan
        same = (got.room, got.node_strings, got.object) == (gold.room, gold.node_strings, gold.object)
        family = description.attributes.get("family", "-")
        counts = families.setdefault(family, [0, 0])
        counts[0] += same
        counts[1] += 1
        total += 1
        agree += same
        if not same and len(disagreements) < limit:
            disagreements.append({"number": description.number, "text": description.text,
                                  "gold": [gold.room, gold.node_strings, gold.object],
                                  "parsed": [got.room, got.node_strings, got.object]})
    return {"descriptions": total, "skipped": skipped, "agreement": agree / total if total else 0.0,
            "families": {f: c[0] / c[1] for f, c in sorted(families.items())},
            "disagreements": disagreements}


def run(args: argparse.Namespace) -> int:
    from assistant.cli.common import emit_json, print_table
    from assistant.errors import AssistantError
    from assistant.grounding.base import command_errors
    from assistant.grounding.labels import read_chunk_groundings, with_world
    from assistant.grounding.training import load_labels, make_grounder, split_corpus_paths

    names = args.grounder or list(GROUNDER_NAMES)
    csvs, xmls = split_corpus_paths(args.corpus)
    corpus = load_labels(csvs, xmls)
    if len(corpus.commands) < 3:
        raise AssistantError(f"need at least 3 labelled commands to split, found {len(corpus.commands)} "
                             f"in {', '.join(map(str, csvs))}")
    test_path = Path(args.test) if args.test else default_test_path()
    test = read_chunk_groundings(test_path) if test_path else None
    test_world = args.test_world
    if test_world is None and test_path is not None and test_path == default_test_path():
        test_world = CSISL_WORLD
    if test is not None and test_world:
        test.commands = [with_world(c, test_world) for c in test.commands]

    result: dict = {"corpus": {"files": [str(p) for p in csvs], "commands": len(corpus.commands),
                               "chunks": len(corpus.records), "problems": corpus.problems[:20]},
                    "protocol": {"rounds": args.rounds, "train_fraction": "2/3", "seed": args.seed},
                    "corpus_split": {}, "test": None, "dissertation": DISSERTATION}
    for name in names:
        result["corpus_split"][name] = bootstrap(name, corpus.commands, args.rounds, args.seed)
    if args.plans:
        from assistant.grounding.parser import CommandParser
        from assistant.language.corpus import read_corpora

        descriptions = read_corpora(xmls).descriptions if xmls else []
        result["plans"] = {}
        language = None
        for name in names:
            grounder = make_grounder(name).fit(corpus.records, corpus.groundings)
            if language is None:
                language = CommandParser.load(name, args.corpus).language
            result["plans"][name] = plan_agreement(CommandParser(language, grounder), descriptions,
                                                   corpus.commands, limit=args.errors)
    if args.descriptions:
        result["descriptions"] = _coverage(args, names)
    errors: dict[str, list] = {}
    if test is not None:
        result["test"] = {"file": str(test_path), "world": test_world, "commands": len(test.commands),
                          "chunks": len(test.records), "problems": test.problems[:20], "accuracy": {}}
        for name in names:
            grounder = make_grounder(name).fit(corpus.records, corpus.groundings)
            result["test"]["accuracy"][name] = grounder.accuracy(test.commands)
            if args.errors:
                errors[name] = [
                    {"command": number, "label": rec.label, "words": " ".join(rec.words),
                     "gold": truth.to_dict(), "guess": guess.to_dict()}
                    for number, rec, truth, guess in command_errors(grounder, test.commands)[:args.errors]]
        if errors:
            result["test"]["errors"] = errors

    if args.json:
        emit_json(result)
        return 0
    out = sys.stdout
    out.write(f"Training corpus: {result['corpus']['commands']} commands, {result['corpus']['chunks']} chunks "
              f"({', '.join(result['corpus']['files'])})\n\n")
    _table(print_table, "(a) our corpus, 2/3 train – 1/3 test, "
           f"{args.rounds} bootstrap rounds (Table 4-3 form)", result["corpus_split"], names)
    if result["test"] is not None:
        t = result["test"]
        _table(print_table, f"(b) trained on our corpus, tested on {t['file']} "
               f"({t['commands']} commands, {t['chunks']} chunks, world {t['world'] or 'unknown'}) "
               "(Table 4-3 form)", t["accuracy"], names)
        out.write("Table 4-4 form — whole command accuracy (%)\n")
        rows = [["dissertation (CSISL split)", _pct(DISSERTATION["scored"]["whole command"]),
                 _pct(DISSERTATION["learned"]["whole command"]), "-"]]
        rows.append(["ours, (a) corpus split", *[_pct(result["corpus_split"].get(n, {}).get("whole command")) for n in GROUNDER_NAMES]])
        rows.append(["ours, (b) test file", *[_pct(t["accuracy"].get(n, {}).get("whole command")) for n in GROUNDER_NAMES]])
        print_table(rows, ["", "scored (WLD) / previous approach", "learned / LSTM", "combined"])
        for name, items in errors.items():
            out.write(f"\nerrors of {name} on the test file:\n")
            for e in items:
                gold = {k: v for k, v in e["gold"].items() if v}
                guess = {k: v for k, v in e["guess"].items() if v}
                out.write(f"  #{e['command']} {e['label']} '{e['words']}': gold {gold} guess {guess}\n")
    else:
        out.write("(b) skipped: no test file (give --test PATH)\n")
    for name, cov in (result.get("descriptions") or {}).items():
        out.write(f"\n(d) {cov['files']}: parsed in {args.descriptions_world} with {name}: plan names the "
                  f"object said and leaves no spatial word unused: {cov['covered']} / {cov['descriptions']} "
                  f"= {_pct(cov['share'])} %\n    misses by why: {cov['why']}\n"
                  f"    spatial words left unused most: {cov['unused_words']}\n")
        for m in cov["misses"]:
            out.write(f"  #{m['number']} '{m['text']}': object (said, plan) {m['object']} unused {m['unused']}\n")
    if result.get("plans"):
        out.write("\n(c) every corpus description parsed from its text (tagger + chunker + grounder, "
                  "trained on the whole corpus): plan (room, nodes, object) equal to its annotation's (%)\n")
        families = sorted({f for r in result["plans"].values() for f in r["families"]})
        rows = [[f, *[_pct(result["plans"][n]["families"].get(f)) for n in names]] for f in families]
        rows.append(["all descriptions", *[_pct(result["plans"][n]["agreement"]) for n in names]])
        rows.append(["compared / skipped (rows ≠ tree)",
                     *[f"{result['plans'][n]['descriptions']} / {result['plans'][n]['skipped']}" for n in names]])
        print_table(rows, ["family", *names])
        for name in names:
            for d in result["plans"][name]["disagreements"]:
                out.write(f"  {name} #{d['number']} '{d['text']}': annotation {d['gold']} parsed {d['parsed']}\n")
    return 0


def _coverage(args, names) -> dict:
    """(d): each grounder's parser over the descriptions files (:mod:`assistant.grounding.coverage`)."""
    from assistant.grounding.coverage import plan_coverage
    from assistant.grounding.parser import CommandParser
    from assistant.language.corpus import read_corpora
    from assistant.world import load_world

    read = read_corpora(args.descriptions)
    world = load_world(args.descriptions_world)
    out = {}
    for name in names:
        parser = CommandParser.load(name, args.corpus, world)
        cov = plan_coverage(parser, read.descriptions, limit=args.errors)
        cov["files"] = ", ".join(str(f) for f in read.files)
        out[name] = cov
    return out


def _pct(value) -> str:
    return "-" if value is None else f"{100 * value:.1f}"


def _table(print_table, title: str, accuracies: dict, names) -> None:
    sys.stdout.write(title + "\n")
    rows = [[label, *[_pct(accuracies[n].get(key)) for n in names],
             _pct(DISSERTATION["learned"].get(key))] for key, label in FIELD_ROWS]
    print_table(rows, ["Grounding type", *[f"{n} (%)" for n in names], "dissertation LSTM (%)"])
    sys.stdout.write("\n")

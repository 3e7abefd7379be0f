"""``assistant eval generation``: options and printed Table 6-1 of :mod:`assistant.eval.generation`."""

from __future__ import annotations

import argparse

from assistant.cli.common import emit_json, miss_probability, print_table, progress_for
from assistant.eval.generation import DISSERTATION_TRUE, STUDY_WORLDS

#: what ``--quick`` stands for (see assistant.cli.eval): the apartment's objects from the world file, no listener
QUICK = ("--worlds", "apartment", "--search", "oracle", "--no-listener")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from assistant.generation.types import SEARCH_MODES

    parser.add_argument("--worlds", nargs="+", default=list(STUDY_WORLDS), metavar="WORLD",
                        help="worlds to describe (default: the four study homes)")
    parser.add_argument("--corpus", action="append", metavar="PATH",
                        help="annotated corpus to learn from (default: the repository's corpus/)")
    parser.add_argument("--search", choices=SEARCH_MODES, default="sensed",
                        help="sensed (default): the simulated robot searches and the description "
                             "uses its perceived furniture; oracle: the world file")
    parser.add_argument("--miss-rate", type=miss_probability, default=0.0, metavar="P",
                        help="object detector miss rate during the search (default 0)")
    parser.add_argument("--save-searches", metavar="FILE",
                        help="write the finished searches to FILE (pickle) to re-score later")
    parser.add_argument("--searches", metavar="FILE",
                        help="re-use searches written by --save-searches instead of searching again "
                             "(the descriptions and the listener test are run anew)")
    parser.add_argument("--listener", action="store_true", default=True,
                        help="hand each description to the simulated robot as a fetch command "
                             "(the default; a few seconds per description)")
    parser.add_argument("--no-listener", dest="listener", action="store_false",
                        help="skip the listener test")
    parser.add_argument("--listener-perception", choices=("sensed", "oracle"), default="sensed",
                        help="the listener robot's furniture perception (default sensed)")
    parser.add_argument("--policy-probabilities", action="store_true",
                        help="furniture relations' P also from the learned policy models (geometric "
                             "mean with the spatial relations'); default: spatial relations alone")
    parser.add_argument("--no-parse", action="store_true",
                        help="check the generator's own selected nodes instead of parsing the "
                             "sentence back (faster; does not test the wording)")


def read_searches(path: str) -> dict:
    """Searches written by ``--save-searches``."""
    import pickle

    from assistant.errors import DataFileError

    try:
        with open(path, "rb") as fh:
            return pickle.load(fh)
    except (OSError, pickle.UnpicklingError, EOFError, AttributeError) as error:
        raise DataFileError(path, "searches", f"cannot be read ({error}); write it with "
                            "--save-searches") from error


def run(args: argparse.Namespace) -> int:
    from assistant.eval.generation import evaluate

    searches = read_searches(args.searches) if args.searches else None
    report = evaluate(args.worlds, args.corpus, parse=not args.no_parse, progress=progress_for(args),
                      listener=args.listener, search=args.search, miss_rate=args.miss_rate,
                      listener_perception=args.listener_perception, searches=searches,
                      policies=args.policy_probabilities)
    done = report.pop("searches")
    if args.save_searches:
        import pickle

        from assistant.fileio import atomic_write_bytes

        atomic_write_bytes(args.save_searches, pickle.dumps(done))
    if args.json:
        emit_json(report)
    else:
        print_rows(report["rows"], report["summary"]["search"])
        print_summary(report["summary"])
    return 0


def _listener_cell(r: dict) -> str:
    if r["listener"] is None:
        return "-"
    return "yes" if r["listener"]["success"] else r["listener"]["failure"]


def _found_cell(r: dict) -> str:
    if r["search"] is None:
        return "oracle"
    return ("yes" if r["search"]["right_place"] else "wrong") if r["search"]["found"] else "NO"


def print_rows(rows: list[dict], search: str) -> None:
    """Table 6-1, one line per description, then the false relations and listener failures."""
    print(f"Table 6-1 (reproduced): generated descriptions of the study objects, {search} search\n")
    print_table([(i + 1, r["world"], r["scene"][:4], r["object"], _found_cell(r), r["description"],
                  r["words"], "yes" if r["true"] else "NO", "yes" if r["unique"] else "no",
                  ", ".join(r["repeated"]) or "-", _listener_cell(r),
                  "-" if r["bleu2"] is None else f"{r['bleu2']:.2f}",
                  "-" if r["human_relation_agreement"] is None else f"{r['human_relation_agreement']:.2f}")
                 for i, r in enumerate(rows)],
                ["#", "world", "scene", "object", "found", "description", "words", "true", "unique",
                 "repeated", "listener", "BLEU-2", "agree"])
    bad = [r for r in rows if not r["true"]]
    if bad:
        print("\nfalse relations:")
        for r in bad:
            print(f"  {r['world']} {r['scene']} {r['object']}: {'; '.join(r['problems'])}")
    missed = [r for r in rows if r["listener"] and not r["listener"]["success"]]
    if missed:
        print("\nlistener failures:")
        for r in missed:
            li = r["listener"]
            print(f"  {r['world']} {r['scene']} {r['object']} (on {r['support_id']} at {r['support_at']}): "
                  f"{li['failure']} — {li.get('message', '')}; went to {li.get('target')}")
    print()


def print_summary(s: dict) -> None:
    """The figures against the targets: search, truth, uniqueness, length, agreement, listener."""
    n = s["descriptions"]
    if s["search_found"] is not None:
        print(f"search: found {s['search_found']}/{n} (at the right place "
              f"{s['search_right_place']}/{n}); median {s['median_search_wall_seconds']:.1f} s "
              f"computer time, {s['median_search_sim_seconds']:.0f} s robot time, "
              f"{s['median_search_path_m']:.1f} m driven")
    print(f"every stated relation true: {s['all_relations_true']}/{n} "
          f"(checked by {s['truth_checked_by']}); no repeated phrase: "
          f"{s['no_repeated_phrase']}/{n}; both: {s['true_and_no_repeat']}/"
          f"{n} (target {n}/{n}; dissertation {DISSERTATION_TRUE[0]}/{DISSERTATION_TRUE[1]})")
    recovered = "not parsed" if s["recovered_by_parse"] is None else f"{s['recovered_by_parse']}/{n}"
    print(f"support singled out: {s['unique']}/{n} (the generator found no "
          f"true wording that does for {s['flagged_ambiguous']}); meant relations recovered by "
          f"the parse: {recovered}")
    print(f"median length {s['median_words']} words (target <= 16), longest {s['max_words']}")
    if s["median_bleu2"] is not None:
        print(f"agreement with the corpus's human descriptions: median BLEU-2 {s['median_bleu2']:.3f}, "
              f"mean share of stated relations people also used {s['mean_human_relation_agreement']:.2f}")
    print(f"median composition {s['median_compose_ms']:.1f} ms")
    print(f"listener: {s['listener']} (target >= {s['targets']['listener_min']})")
    print(f"evaluation took {s['wall_seconds']:.0f} s")
    if s["parser_note"]:
        print(s["parser_note"])

"""``assistant eval perception``: options and printed tables of :mod:`assistant.eval.perception`."""

from __future__ import annotations

import argparse

from assistant.cli.common import finite_float, print_table, progress_for, show_report, whole_number
from assistant.eval.perception import CATEGORY_ORDER, DEFAULT_CLASSIFIERS

#: what ``--quick`` stands for (see assistant.cli.eval): the GSVM on the held-out views only
QUICK = ("--skip", "orientation,scenes,real", "--classifiers", "gsvm")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--realdata", metavar="PATH",
                        help="folder of real depth frames (the shared realdata folder) to score too")
    parser.add_argument("--skip", default="", metavar="PARTS",
                        help="comma-separated parts to skip: classify,orientation,scenes,real")
    parser.add_argument("--classifiers", default=",".join(DEFAULT_CLASSIFIERS),
                        help="classifiers to compare (default: the dissertation's three, the random "
                             "forest and the GSVM+forest vote)")
    parser.add_argument("--train-plans", type=whole_number(1, 1000), default=None, metavar="K",
                        help="train on the first K training view plans only (default: all; 2 is "
                             "the previous default, without the views against a wall)")
    parser.add_argument("--range-m", type=finite_float, default=None, metavar="M",
                        help="how far ahead (metres) the detector keeps points (default: the "
                             "product's 4.0, as in the dissertation); an experiment knob")
    parser.add_argument("--no-coverage", action="store_true",
                        help="fuse detections by classifier confidence alone (not × view coverage)")
    parser.add_argument("--no-variants", action="store_true",
                        help="the detector without the verifier trained on the training variants "
                             "(desks, night stands, store beds, benches, dressers): issue 6's")


def run(args: argparse.Namespace) -> int:
    from assistant.eval.perception import evaluate_perception

    report = evaluate_perception(
        args.realdata, skip={s.strip() for s in (args.skip or "").split(",") if s.strip()},
        classifiers=[m.strip() for m in args.classifiers.split(",") if m.strip()],
        train_plans=args.train_plans, range_m=args.range_m, coverage=not args.no_coverage,
        variants=not args.no_variants,
        progress=progress_for(args))
    return show_report(args, report, print_report)


def realdata_summary_line(summary: dict) -> str:
    """One line of the real-frame checks: floors, and each labelled category detected as such."""
    parts = [f"floor found {summary['floor_found']}/{summary['frames']}"]
    for what, t in summary["labelled"].items():
        part = f"{what} {t['correct']}/{t['labelled']}"
        if t["in_range"] < t["labelled"]:
            beyond = t["labelled"] - t["in_range"]
            part += f" ({t['in_range_correct']}/{t['in_range']} of those mostly within range; "
            part += f"{t.get('out_of_range_partial', 0)}/{beyond} mostly beyond it reported as a partial {what})"
        parts.append(part)
    parts.append(f"false beds/couches: {summary['false_beds_or_couches_in_negatives']} in the "
                 f"negatives, {summary['false_beds_or_couches_elsewhere']} elsewhere")
    return "summary: " + "; ".join(parts)


def print_report(report: dict) -> None:
    """Each table the report holds, in the dissertation's order, then the real frames."""
    if "databases" in report:
        print(f"databases: {report['databases']}")
    for key, title in (("table_3_6", "Table 3-6: held-out simulated views of the study models"),
                       ("table_3_7", "Table 3-7: trained on the study models, tested on other instances")):
        if key not in report:
            continue
        print(f"\n{title}")
        table = report[key]
        names = list(table)
        rows = []
        for c in (*CATEGORY_ORDER, "all"):
            first = table[names[0]].get(c)
            if first is None:
                continue
            rows.append([c, first["n"], *[f"{100 * table[n][c]['accuracy']:.1f}%" for n in names]])
        print_table(rows, ["category", "samples", *names])
    if "table_3_8" in report:
        _print_orientation(report["table_3_8"])
    if "table_3_9" in report:
        _print_scenes(report["table_3_9"])
    if "realdata" in report:
        _print_realdata(report["realdata"], report["settings"]["range_m"])
    print(f"\n{report['seconds']} s")


def _print_orientation(table: dict) -> None:
    print("\nTable 3-8: orientation error, degrees (mean/std)")
    for db, rows in table.items():
        out = []
        for sub, row in rows.items():
            lin = row.get("linear")
            pl = row["plane"]
            out.append([sub, row["n"], "-" if lin is None else f"{lin['mean']}/{lin['std']}",
                        f"{pl['mean']}/{pl['std']} (median {pl['median']}, none {pl['no_estimate']})"])
        print(f"  {db} database")
        print_table(out, ["subclass", "views", "linear (Table 3-3)", "plane (this product)"])


def _print_scenes(table: dict) -> None:
    print("\nTable 3-9: scenes")
    rows = []
    for r in table["scenes"]:
        pe = "/".join(f"{i['position_error_m']:.2f}" if "position_error_m" in i else "miss" for i in r["items"])
        oe = "/".join(f"{i['orientation_error_rad']:.2f}" if "orientation_error_rad" in i else "-" for i in r["items"])
        rows.append([r["scene"], r["world"], " ".join(i["id"] for i in r["items"]), pe, oe,
                     "Y" if r["sr_match"] else "N", r["views"]])
    print_table(rows, ["#", "world", "items", "PE (m)", "OE (rad)", "SR", "views"])
    print(f"summary: {table['summary']}")


def _print_realdata(realdata: dict, range_m: float) -> None:
    print("\nReal frames")
    for folder, frames in realdata["folders"].items():
        for f in frames:
            floor = f["floor"]
            fl = f"floor {floor['height']:.2f} m, tilt {floor['tilt_deg']:.1f}°, roll {floor['roll_deg']:.1f}°" if floor else "no floor"
            dets = ", ".join(d["category"] + (" (partial)" if d.get("partial") else "")
                             + (f" (unsure {d['confidence']:.2f})" if d.get("unsure") else "")
                             for d in f["detections"]) or f"none ({f['reason']})"
            unknown = ", ".join(f"{u['best']} {u['probability']:.2f} ({u['why']})" for u in f.get("unknown", []))
            print(f"  {folder}/{f['file']}: {fl}; detections: {dets}" + (f"; unknown: {unknown}" if unknown else ""))
            for m in f.get("matches", []):
                share = (f", {100 * m['in_range_share']:.1f} % within {range_m:g} m"
                         if "in_range_share" in m else "")
                part = " (partial)" if m.get("partial") else ""
                print(f"      {m['object']}: {m.get('detected')}{part} (pixels {m['pixels']}{share})")
            for b in f.get("boxes", []):
                print(f"      {b['object']}: {b['detected']}")
    print("  " + realdata_summary_line(realdata["summary"]))

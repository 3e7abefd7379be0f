"""``assistant eval fetch``: end-to-end fetch trials over the dev set (dissertation 5.6.3,
Table 5-4).

Every command of ``corpus/fetch_dev.jsonl`` ({text, world, scene, object, kind}) is run in the
simulator from the world's start pose with sensed and/or oracle perception
(:class:`~assistant.executor.trial.FetchRunner`); a trial succeeds when the target object
covers at least 50 pixels of the final depth frame at a median distance of at most 4.5 m. The
report gives the success rate and the failure counts per home and scene (Table 5-4's rows:
not visible, parse, perception = reference not found, collision, ambiguous, no path, no room,
timeout) for each perception mode.
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

DEFAULT_DEV_SET = Path(__file__).resolve().parents[2] / "corpus" / "fetch_dev.jsonl"
#: Table 5-4 order of the outcome columns
OUTCOMES = ("success", "not_visible", "parse", "reference_not_found", "collision", "ambiguous",
            "no_path", "no_room", "timeout")
REQUIRED = ("text", "world", "scene", "object", "kind")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--perception", choices=("sensed", "oracle", "both"), default="both",
                        help="perception mode(s) to run (default: both)")
    parser.add_argument("--limit", type=int, default=None, metavar="N", help="only the first N commands")
    parser.add_argument("--world", metavar="NAME", help="only the commands of this home")
    parser.add_argument("--scene", choices=("original", "modified"), help="only this scene")
    parser.add_argument("--dev-set", metavar="FILE", default=None,
                        help=f"JSON lines {{{', '.join(REQUIRED)}}} (default: {DEFAULT_DEV_SET.name} in corpus/)")
    parser.add_argument("--grounder", choices=("scored", "learned"), default=None)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--trials", metavar="FILE", help="also write every trial's JSON line to FILE")


def load_dev_set(path: str | Path | None = None) -> list[dict]:
    """The dev set's records; a bad line raises a :class:`~assistant.errors.DataFileError`."""
    from assistant.errors import DataFileError

    path = Path(path) if path else DEFAULT_DEV_SET
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except OSError as error:
        raise DataFileError(str(path), "file", f"cannot be read: {error.strerror}") from error
    out = []
    for number, line in enumerate(lines, start=1):
        if not line.strip():
            continue
        try:
            record = json.loads(line)
        except json.JSONDecodeError as error:
            raise DataFileError(str(path), f"line {number}", f"not JSON: {error.msg}") from error
        missing = [k for k in REQUIRED if not isinstance(record.get(k), str) or not record.get(k)]
        if missing:
            raise DataFileError(str(path), f"line {number}", f"missing {', '.join(missing)}")
        out.append(record)
    return out


def summarise(trials: list[dict]) -> dict:
    """Counts per (perception, world, scene) and totals per perception mode."""
    groups: dict = {}
    totals: dict = {}
    for t in trials:
        outcome = "success" if t["success"] else t["failure"]
        key = (t["perception"], t["world"], t["scene"])
        for table, k in ((groups, key), (totals, t["perception"])):
            row = table.setdefault(k, {o: 0 for o in OUTCOMES} | {"all": 0})
            row[outcome] = row.get(outcome, 0) + 1
            row["all"] += 1
    for table in (groups, totals):
        for row in table.values():
            row["success_rate"] = round(row["success"] / row["all"], 4) if row["all"] else None
    return {"groups": [{"perception": p, "world": w, "scene": s, **row} for (p, w, s), row in sorted(groups.items())],
            "totals": totals}


def run(args: argparse.Namespace) -> int:
    import statistics

    from assistant.cli.common import emit_json, print_table
    from assistant.executor.trial import MAX_DISTANCE_M, MIN_PIXELS, FetchRunner

    records = load_dev_set(args.dev_set)
    if args.world:
        records = [r for r in records if r["world"] == args.world]
    if args.scene:
        records = [r for r in records if r["scene"] == args.scene]
    if args.limit is not None:
        records = records[: max(0, args.limit)]
    modes = ("sensed", "oracle") if args.perception == "both" else (args.perception,)
    runner = FetchRunner(grounder=args.grounder)
    trials = []
    sink = open(args.trials, "w", encoding="utf-8") if args.trials else None
    try:
        for mode in modes:
            for record in records:
                outcome = runner.run(record["text"], record["world"], record["scene"], mode, args.seed,
                                     record["object"])
                data = {**outcome.data, "kind": record["kind"]}
                trials.append(data)
                if sink is not None:
                    sink.write(json.dumps(data) + "\n")
                    sink.flush()
    finally:
        if sink is not None:
            sink.close()
    summary = summarise(trials)
    walls = [t["wall_seconds"] for t in trials]
    summary["median_wall_seconds"] = round(statistics.median(walls), 3) if walls else None
    summary["commands"] = len(records)
    summary["threshold"] = {"min_pixels": MIN_PIXELS, "max_distance_m": MAX_DISTANCE_M}
    if args.json:
        emit_json(summary)
        return 0
    header = ["perception", "world", "scene", *OUTCOMES, "all", "rate"]
    rows = [[g["perception"], g["world"], g["scene"], *(g[o] for o in OUTCOMES), g["all"],
             f"{100 * g['success_rate']:.1f}%"] for g in summary["groups"]]
    for mode, row in summary["totals"].items():
        rows.append([mode, "ALL", "both", *(row[o] for o in OUTCOMES), row["all"], f"{100 * row['success_rate']:.1f}%"])
    print_table(rows, header)
    print(f"success: target object ≥ {MIN_PIXELS} pixels of the final depth frame within {MAX_DISTANCE_M} m; "
          f"median wall-clock per fetch {summary['median_wall_seconds']} s")
    return 0

"""``assistant eval fetch``: end-to-end fetch trials over the dev set (dissertation 5.6.3,
Table 5-4).

Every command of ``corpus/fetch_dev.jsonl`` ({text, world, scene, object, kind}) is run in the
simulator from the world's start pose with sensed and/or oracle perception
(:meth:`assistant.app.Fetcher.fetch`, the product's own fetch); a trial succeeds when the target object
covers at least 50 pixels of the final depth frame at a median distance of at most 4.5 m. The
report gives the success rate and the failure counts per home and scene (Table 5-4's rows:
not visible, parse, perception = reference not found, collision, ambiguous, no path, no room,
timeout) for each perception mode.
"""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

from assistant.eval.progress import Progress, no_progress

DEFAULT_DEV_SET = Path(__file__).resolve().parents[2] / "corpus" / "fetch_dev.jsonl"
#: Table 5-4 order of the outcome columns
OUTCOMES = ("success", "not_visible", "parse", "reference_not_found", "collision", "ambiguous",
            "no_path", "no_room", "timeout")
REQUIRED = ("text", "world", "scene", "object", "kind")
#: the dissertation's fetch success rate (5.6.3, Table 5-4: the target object in view)
DISSERTATION_SUCCESS = 0.772


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


def select(records: list[dict], world: str | None = None, scene: str | None = None,
           limit: int | None = None) -> list[dict]:
    """The dev-set records of one home and/or scene, the first ``limit`` of them."""
    if world:
        records = [r for r in records if r["world"] == world]
    if scene:
        records = [r for r in records if r["scene"] == scene]
    if limit is not None:
        records = records[: max(0, limit)]
    return records


def evaluate_fetch(dev_set=None, *, perception: str = "both", world: str | None = None,
                   scene: str | None = None, limit: int | None = None, grounder: str | None = None,
                   seed: int = 0, on_trial: Callable[[dict], None] | None = None,
                   progress: Progress = no_progress) -> dict:
    """Table 5-4: every selected dev-set command (:func:`load_dev_set`, :func:`select`) fetched
    in the simulator with ``perception`` ``sensed``, ``oracle`` or ``both``. ``on_trial`` gets
    each trial's record as it ends. Returns :func:`summarise`'s counts with the median wall-clock
    per fetch, the number of commands and the success threshold."""
    import statistics

    from assistant.app import Fetcher
    from assistant.executor.trial import MAX_DISTANCE_M, MIN_PIXELS

    records = select(load_dev_set(dev_set), world, scene, limit)
    modes = ("sensed", "oracle") if perception == "both" else (perception,)
    fetcher = Fetcher(grounder=grounder)
    trials = []
    for mode in modes:
        for number, record in enumerate(records):
            progress(f"{mode} fetch trials", number, len(records))
            outcome = fetcher.fetch(record["text"], record["world"], record["scene"], mode, seed=seed,
                                    object_name=record["object"])
            data = {**outcome.data, "kind": record["kind"]}
            trials.append(data)
            if on_trial is not None:
                on_trial(data)
    summary = summarise(trials)
    walls = [t["wall_seconds"] for t in trials]
    summary["median_wall_seconds"] = round(statistics.median(walls), 3) if walls else None
    summary["commands"] = len(records)
    summary["threshold"] = {"min_pixels": MIN_PIXELS, "max_distance_m": MAX_DISTANCE_M}
    return summary

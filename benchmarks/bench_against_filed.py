"""Real-frame speed against the detector as issue 20 was filed, each run in its own process.

Issue 20 asks for "p90 ≤ 25 ms per frame for every size, median ≤ 18 ms" on the real frames,
and gives the detector as filed (commit :data:`FILED_COMMIT`) 18 ms median, 23 ms p90 over the
same 10 frames "on a quiet machine". Milliseconds depend on the machine: the shared 2-core VM
this product is built on ran the filed commit's own benchmark at 39 ms median (3 Dec 2026), so
an absolute figure from here says little about the target. This benchmark measures both in the
same run:

* the **filed commit as a whole** (its code, its models trained by its own code into a cache of
  its own, read with ``git archive``) and the **current tree** (its usual model cache), each timing
  ``FurnitureDetector.analyse(frame, use_mount=False)`` (the floor searched for) over every
  real frame ``--repeats`` times in a fresh process of the same Python;
* the two processes alternate for ``--rounds`` rounds (filed first in odd rounds), so both see
  the same load;
* it prints the wall-clock median and p90 of each, overall and per frame size, the ratio
  filed / current, and the current figures **on the machine the issue was measured on**: the
  current times divided by this machine's factor (the filed detector's median here / 18 ms, and
  its p90 here / 23 ms for the p90s).

    OMP_NUM_THREADS=1 .venv/bin/python benchmarks/bench_against_filed.py \
        --realdata ../shared/realdata [--rounds 3] [--repeats 5]

A checkout without the filed commit (a shallow clone) says so and stops.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tarfile
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
sys.path.insert(0, str(HERE))

from bench_perception import median, p90  # noqa: E402
from perception_reference import FILED_COMMIT  # noqa: E402

#: what the issue measured for the detector as filed on the real frames (ms, quiet machine)
FILED_MEDIAN_MS = 18.0
FILED_P90_MS = 23.0
#: the issue's targets for every frame size (ms)
TARGET_MEDIAN_MS = 18.0
TARGET_P90_MS = 25.0


def worker(realdata: Path, repeats: int) -> None:
    """Time the ``assistant`` package found first on ``sys.path`` (the tree this process was
    started with) and print one JSON line: the package's path and each run's
    (frame size, wall ms)."""
    import time

    from assistant.perception import FurnitureDetector
    from assistant.perception.realdata import load_frames

    frames = [frame for _, _, frame in load_frames(realdata)]
    detector = FurnitureDetector()
    for frame in frames:  # warm-up: imports, models, first allocations
        detector.analyse(frame, use_mount=False)
    runs = []
    for _ in range(repeats):
        for frame in frames:
            t = time.perf_counter()
            detector.analyse(frame, use_mount=False)
            runs.append((f"{frame.intrinsics.width}×{frame.intrinsics.height}",
                         (time.perf_counter() - t) * 1e3))
    import assistant

    print(json.dumps({"package": str(Path(assistant.__file__).parent), "runs": runs}))


def filed_tree(into: Path) -> Path:
    """The repository at :data:`FILED_COMMIT` (``git archive``), unpacked under ``into``."""
    tree = into / f"filed-{FILED_COMMIT}"
    archive = into / "filed.tar"
    try:
        with archive.open("wb") as out:
            subprocess.run(["git", "archive", FILED_COMMIT], cwd=REPO, stdout=out, check=True,
                           stderr=subprocess.PIPE)
    except (OSError, subprocess.CalledProcessError) as exc:
        raise SystemExit(f"cannot read commit {FILED_COMMIT} from this checkout ({exc}); fetch "
                         "the full history with `git fetch --unshallow` and run this again")
    with tarfile.open(archive) as tar:
        tar.extractall(tree, filter="data")
    return tree


def run_tree(tree: Path, cache: Path | None, realdata: Path, repeats: int) -> list[tuple[str, float]]:
    """One worker process on ``tree``, with the model cache ``cache`` (None: the usual one)."""
    env = dict(os.environ, PYTHONPATH=str(tree))
    if cache is not None:
        env["ASSISTANT_CACHE"] = str(cache)
    env.setdefault("OMP_NUM_THREADS", "1")
    done = subprocess.run([sys.executable, str(Path(__file__).resolve()), "--worker",
                           "--realdata", str(realdata.resolve()), "--repeats", str(repeats)],
                          cwd=tempfile.gettempdir(), env=env, capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"the run on {tree} failed:\n{done.stderr[-2000:]}")
    result = json.loads(done.stdout.strip().splitlines()[-1])
    if Path(result["package"]).resolve() != (tree / "assistant").resolve():
        raise SystemExit(f"the run meant for {tree} imported {result['package']}")
    return [tuple(run) for run in result["runs"]]


def figures(runs: list[tuple[str, float]]) -> dict[str, tuple[float, float, int]]:
    """{"all" and each size: (median ms, p90 ms, runs)}."""
    out = {"all": [wall for _, wall in runs]}
    for size, wall in runs:
        out.setdefault(size, []).append(wall)
    return {key: (median(walls), p90(walls), len(walls)) for key, walls in out.items()}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--realdata", type=Path, default=REPO.parent / "shared" / "realdata",
                        help="folder of real frames in the realdata layout")
    parser.add_argument("--rounds", type=int, default=3, help="alternations of the two trees (default 3)")
    parser.add_argument("--repeats", type=int, default=5, help="runs of every frame per process (default 5)")
    parser.add_argument("--worker", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.worker:
        worker(args.realdata, args.repeats)
        return 0
    if not args.realdata.is_dir():
        raise SystemExit(f"no folder of real frames at {args.realdata}: give it with --realdata PATH")
    with tempfile.TemporaryDirectory(prefix="bench-filed-") as tmp:
        tmp = Path(tmp)
        trees = {"as filed": (filed_tree(tmp), tmp / "cache-filed"),
                 "current": (REPO, None)}
        runs: dict[str, list] = {name: [] for name in trees}
        load_before = os.getloadavg()
        for k in range(args.rounds):
            order = list(trees) if k % 2 == 0 else list(trees)[::-1]
            for name in order:
                tree, cache = trees[name]
                print(f"round {k + 1}/{args.rounds}: {name} …", file=sys.stderr, flush=True)
                runs[name] += run_tree(tree, cache, args.realdata, args.repeats)
        load_after = os.getloadavg()
    filed, current = figures(runs["as filed"]), figures(runs["current"])
    factor_median = filed["all"][0] / FILED_MEDIAN_MS
    factor_p90 = filed["all"][1] / FILED_P90_MS
    print(f"real frames ({args.realdata}, floor searched for), {args.rounds} alternating rounds × "
          f"{args.repeats} runs of each frame, OMP_NUM_THREADS={os.environ.get('OMP_NUM_THREADS', '1 (set)')}; "
          f"load average {load_before[0]:.2f} before, {load_after[0]:.2f} after; {os.cpu_count()} cores")
    print(f"{'':12s}{'as filed (' + FILED_COMMIT + ')':>26s}{'current':>22s}{'filed/current':>16s}"
          f"{'current on the issue machine':>32s}")
    for key in ["all"] + sorted(k for k in current if k != "all"):
        fm, fp, _ = filed.get(key, (float("nan"),) * 3)
        cm, cp, n = current[key]
        print(f"{key:12s}{fm:13.1f} /{fp:6.1f} ms{cm:11.1f} /{cp:6.1f} ms{fm / cm:10.2f}× /{fp / cp:4.2f}×"
              f"{cm / factor_median:17.1f} /{cp / factor_p90:6.1f} ms")
    print(f"\nThis machine ran the filed detector {factor_median:.2f}× (median) and {factor_p90:.2f}× (p90) "
          f"slower than the issue's {FILED_MEDIAN_MS:.0f} / {FILED_P90_MS:.0f} ms; the last column is the "
          "current time divided by that factor.")
    worst_median = max(current[k][0] for k in current) / factor_median
    worst_p90 = max(current[k][1] for k in current) / factor_p90
    met = current["all"][0] / factor_median <= TARGET_MEDIAN_MS and worst_p90 <= TARGET_P90_MS
    print(f"Target (issue 20, every size): median ≤ {TARGET_MEDIAN_MS:.0f} ms over the real frames, p90 ≤ "
          f"{TARGET_P90_MS:.0f} ms for every size. On the issue's machine: median "
          f"{current['all'][0] / factor_median:.1f} ms (the slowest size's {worst_median:.1f}), worst size's "
          f"p90 {worst_p90:.1f} ms: {'met' if met else 'NOT met'}.")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

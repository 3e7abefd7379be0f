"""Perception speed: one depth frame → detections, end to end (``FurnitureDetector.analyse``).

Frames: simulated 640×480 Kinect views of the 16 furniture scenes of Table 3-9 in the four
study homes (the first ``--views`` viewpoints of each scene, furniture in view, robot mount
known), and — when ``--realdata PATH`` exists (default ``../shared/realdata``) — the real frames
of that folder (SUN RGB-D 730×530, NYU 640×480, Kinect v2 512×424, TUM 640×480; no mount: the
floor is searched for).

Every frame is run ``--repeats`` times through the current code and, in the same run and
interleaved with it (so both see the same load), through the code as it was before the speed
work (``benchmarks/perception_reference.py`` reads it from the git history). Printed per frame set: the median and p90
wall-clock milliseconds, the median CPU milliseconds of this process (``time.process_time``:
on a loaded 2-core machine the wall time includes waiting for a core), the per-stage medians,
the old path's medians and the old/new ratios, whether both paths detect the same categories,
and the load average before and after; the real frames also per frame size, and once more
with the floor reused across the runs of each frame (each frame one camera pose: its first
run searches the floor, the later ones check the remembered floor against their points,
``FurnitureDetector.analyse(pose_key=…)``). Targets: median ≤ 33 ms per 640×480 simulated
frame; real frames of every size p90 ≤ 25 ms, median ≤ 18 ms (issue 20). The old path runs
today's classifier, so its shape descriptor gets today's side cues appended.

    .venv/bin/python benchmarks/bench_perception.py [--repeats 5] [--views 2]
        [--realdata PATH] [--no-reference] [--threads]

``--front-half COMMIT`` instead times the real frames' front half alone (``analyse_frame``, the
floor searched for) against ``COMMIT``'s, CPU, interleaved frame by frame, and checks that
both give the same samples and features.

``--threads`` instead times the current code with numpy's BLAS and open3d's OpenMP pools
set to 1 or 2 threads (``threadpoolctl``), interleaved frame by frame: "BLAS 1, OpenMP 1" is
``OMP_NUM_THREADS=1`` set before numpy loads, "BLAS 2, OpenMP 1" what the product got when
numpy was loaded before ``assistant.perception`` set ``OMP_NUM_THREADS=1`` for open3d, "BLAS 2,
OpenMP 2" no setting at all on this 2-core machine (what the product got when the simulator had
imported open3d first), and the last row the product now (``FrameParams.threads=1``: one
OpenMP and one BLAS thread while a frame is analysed, whatever the process's setting).
"""

from __future__ import annotations

import argparse
import os
import statistics
import sys
import time
from contextlib import contextmanager
from pathlib import Path

HERE = Path(__file__).resolve().parent
DEFAULT_REALDATA = HERE.parent.parent / "shared" / "realdata"
sys.path.insert(0, str(HERE))
from perception_reference import FILED_COMMIT, ReferenceUnavailable, load as load_reference  # noqa: E402
STAGES = ("cloud", "floor", "samples", "features", "classify")


def simulated_frames(views: int) -> list:
    """(label, frame) of the first ``views`` viewpoints of each Table 3-9 scene."""
    from assistant.eval.perception_scenes import SCENES, viewpoints
    from assistant.sim.renderer import DepthRenderer
    from assistant.world import load_world

    worlds, renderers, out = {}, {}, []
    for number, (name, ids) in enumerate(SCENES, start=1):
        if name not in worlds:
            worlds[name] = load_world(name)
            renderers[name] = DepthRenderer(worlds[name], "original", seed=0)
        world = worlds[name]
        items = [f for f in world.scene("original").furniture if f.id in ids]
        for k, pose in enumerate(viewpoints(world, "original", items)[:views]):
            out.append((f"scene {number} view {k + 1}", renderers[name].render(pose)))
    return out


def real_frames(root: Path) -> list:
    """(label, frame) of the real frames of a realdata folder (as the evaluation reads them)."""
    from assistant.perception.realdata import load_frames

    return [(f"{folder}/{name}", frame) for folder, name, frame in load_frames(root)]


@contextmanager
def reference_path(detector=None, commit: str | None = None):
    """Run the detector's front half and shape descriptor as they were before the speed work
    — or, with ``commit`` = :data:`FILED_COMMIT` and the ``detector``, the detector as it was
    when issue 20 was filed: that front half and shape descriptor, no side cues, no verifier,
    no regrouping, scikit-learn's SVM decision function (the main classifier is today's)."""
    import assistant.perception.detector as detector_module

    ref = load_reference(commit) if commit else load_reference()
    ref_frame, ref_features = ref.frame, ref.features
    filed = commit == FILED_COMMIT

    import numpy as np

    from assistant.perception.features import side_cues

    def old_shape(points, normals, camera_xy=None, **kw):  # the old descriptor + today's cues
        shape = ref_features.shape_descriptor(points, normals, **kw)
        if filed:  # no cues then: the main classifier does not read them
            return np.append(shape, (0.0, 0.0))
        surface = shape[43] if shape[43] > 0 else 0.9 * shape[40]
        return np.append(shape, side_cues(points, surface, camera_xy))

    def old_frame(frame, params, *, use_mount=True, previous_floor=None):
        return ref_frame.analyse_frame(frame, params, use_mount=use_mount)

    saved = detector_module.analyse_frame, detector_module.shape_descriptor
    detector_module.analyse_frame = old_frame
    detector_module.shape_descriptor = old_shape
    switches = None
    if filed and detector is not None:
        classifier = detector.models.classifier
        switches = (detector.verify, detector.regroup, classifier.__dict__.get("_rbf_decision"))
        detector.verify = detector.regroup = False
        classifier.__dict__["_rbf_decision"] = False  # scikit-learn's decision function
    try:
        yield
    finally:
        detector_module.analyse_frame, detector_module.shape_descriptor = saved
        if switches is not None:
            detector.verify, detector.regroup, fast = switches
            detector.models.classifier.__dict__.pop("_rbf_decision", None)
            if fast is not None:
                detector.models.classifier.__dict__["_rbf_decision"] = fast


def run_once(detector, frame, use_mount: bool, pose_key=None) -> tuple[float, float, dict, dict, list]:
    """(wall ms, CPU ms, stage wall ms, stage CPU ms, detected categories) of one analyse;
    ``pose_key`` lets the detector reuse the floor of the last frame with the same key."""
    t, c = time.perf_counter(), time.process_time()
    result = detector.analyse(frame, use_mount=use_mount, pose_key=pose_key)
    wall, cpu = (time.perf_counter() - t) * 1e3, (time.process_time() - c) * 1e3
    stage_cpu = dict(getattr(result.analysis, "cpu_ms", {}) or {})
    if stage_cpu:
        stage_cpu["classify"] = max(0.0, cpu - sum(stage_cpu.values()))
    return wall, cpu, dict(result.timings_ms), stage_cpu, sorted(d.category for d in result.detections)


def median(values) -> float:
    return statistics.median(values) if values else float("nan")


def p90(values) -> float:
    return sorted(values)[int(0.9 * (len(values) - 1))] if values else float("nan")


def bench(detector, frames: list, use_mount: bool, repeats: int, reference: bool,
          reuse_floor: bool = False, commit: str | None = None) -> dict:
    """Every frame ``repeats`` times (and through the old path when ``reference``); with
    ``reuse_floor`` each frame is its own camera pose (its label the pose key), so its first
    run searches the floor and the later ones reuse it. Wall times are also kept per frame
    size ("W×H")."""
    new = {"wall": [], "cpu": [], "stage": {}, "stage_cpu": {}, "by_size": {}, "by_size_cpu": {}}
    old = {"wall": [], "cpu": []}
    ratios, differ = [], set()
    for rep in range(repeats):
        for i, (label, frame) in enumerate(frames):
            order = ("new", "old") if (rep + i) % 2 == 0 or not reference else ("old", "new")
            for which in order:
                if which == "old" and not reference:
                    continue
                if which == "new":
                    wall, cpu, stage, stage_cpu, cats_new = run_once(
                        detector, frame, use_mount, label if reuse_floor else None)
                    new["wall"].append(wall)
                    size = f"{frame.intrinsics.width}×{frame.intrinsics.height}"
                    new["by_size"].setdefault(size, []).append(wall)
                    new["by_size_cpu"].setdefault(size, []).append(cpu)
                    new["cpu"].append(cpu)
                    for k, v in stage.items():
                        new["stage"].setdefault(k, []).append(v)
                    for k, v in stage_cpu.items():
                        new["stage_cpu"].setdefault(k, []).append(v)
                else:
                    with reference_path(detector, commit):
                        wall_old, cpu_old, _, _, cats_old = run_once(detector, frame, use_mount)
                    old["wall"].append(wall_old)
                    old["cpu"].append(cpu_old)
            if reference:
                ratios.append(old["cpu"][-1] / max(new["cpu"][-1], 1e-6))
                if cats_new != cats_old:
                    differ.add(label)
    return {"new": new, "old": old, "cpu_ratios": ratios, "differ": sorted(differ)}


def report(name: str, frames: list, res: dict, reference: bool, old_name: str = "old path") -> None:
    new, old = res["new"], res["old"]
    print(f"\n{name}: {len(frames)} frames × {len(new['wall']) // max(1, len(frames))} runs")
    print(f"  current   wall median {median(new['wall']):6.1f} ms  p90 {p90(new['wall']):6.1f} ms   "
          f"CPU median {median(new['cpu']):6.1f} ms  p90 {p90(new['cpu']):6.1f} ms")
    parts = [f"{k} {median(new['stage'].get(k, [])):.1f}/{median(new['stage_cpu'].get(k, [])):.1f}"
             for k in STAGES if k in new["stage"]]
    print("  stages (wall/CPU median ms): " + ", ".join(parts))
    for size, walls in sorted(new["by_size"].items()):
        cpus = new["by_size_cpu"][size]
        print(f"  {size}: {len(walls)} runs, wall median {median(walls):6.1f} ms  p90 {p90(walls):6.1f} ms   "
              f"CPU median {median(cpus):6.1f} ms  p90 {p90(cpus):6.1f} ms")
    if reference:
        print(f"  {old_name:9s} wall median {median(old['wall']):6.1f} ms  p90 {p90(old['wall']):6.1f} ms   "
              f"CPU median {median(old['cpu']):6.1f} ms  p90 {p90(old['cpu']):6.1f} ms")
        print(f"  {old_name}/new: wall medians {median(old['wall']) / median(new['wall']):.2f}×, "
              f"CPU medians {median(old['cpu']) / median(new['cpu']):.2f}×, "
              f"median per-frame CPU ratio {median(res['cpu_ratios']):.2f}×")
        same = len(frames) - len(res["differ"])
        print(f"  same detected categories on {same}/{len(frames)} frames"
              + (f" (differ: {', '.join(res['differ'])})" if res["differ"] else ""))


THREAD_SETTINGS = (  # (name, process thread pools, FrameParams.threads)
    ("BLAS 1, OpenMP 1", {"blas": 1, "openmp": 1}, None),
    ("BLAS 2, OpenMP 1", {"blas": 2, "openmp": 1}, None),
    ("BLAS 2, OpenMP 2", {"blas": 2, "openmp": 2}, None),
    ("BLAS 2, OpenMP 2, analyse_frame limits both to 1 (product)", {"blas": 2, "openmp": 2}, 1),
)


def threads_comparison(detector, frames: list, use_mount: bool, repeats: int) -> None:
    """Wall and CPU medians of the current code with numpy's BLAS and open3d's OpenMP pools
    set to 1 or 2 threads (``threadpoolctl``), the settings interleaved frame by frame so that
    they share the machine's load."""
    import dataclasses

    from threadpoolctl import ThreadpoolController

    controller = ThreadpoolController()
    found = sorted({f"{lib.user_api}:{lib.internal_api}" for lib in controller.lib_controllers})
    wall = {name: [] for name, *_ in THREAD_SETTINGS}
    cpu = {name: [] for name, *_ in THREAD_SETTINGS}
    saved = detector.params
    try:
        for rep in range(repeats):
            for i, (_, frame) in enumerate(frames):
                k = (rep + i) % len(THREAD_SETTINGS)
                for name, limits, inner in THREAD_SETTINGS[k:] + THREAD_SETTINGS[:k]:
                    detector.params = dataclasses.replace(saved, threads=inner)
                    with controller.limit(limits=limits):
                        w, c, *_ = run_once(detector, frame, use_mount)
                    wall[name].append(w)
                    cpu[name].append(c)
    finally:
        detector.params = saved
    print(f"  thread pools found: {', '.join(found)}")
    for name, *_ in THREAD_SETTINGS:
        print(f"  {name}: wall median {median(wall[name]):6.1f} ms  p90 {p90(wall[name]):6.1f} ms   "
              f"CPU median {median(cpu[name]):6.1f} ms")


def front_half_comparison(frames: list, repeats: int, commit: str) -> None:
    """CPU milliseconds of the front half alone (``analyse_frame``, floor searched for) of the
    current code and of ``commit``'s (``perception_reference.load``), interleaved frame by
    frame so both see the same load; medians and p90 per frame size and the median per-frame
    ratio. The two must find the same floor and samples: the output says if they do not."""
    import numpy as np

    from assistant.perception.frame import analyse_frame

    ref = load_reference(commit)
    cpu = {"current": {}, commit: {}}
    ratios, differ = [], set()
    for rep in range(repeats):
        for i, (label, frame) in enumerate(frames):
            size = f"{frame.intrinsics.width}×{frame.intrinsics.height}"
            runs = {}
            for which in (("current", commit) if (rep + i) % 2 == 0 else (commit, "current")):
                fn = analyse_frame if which == "current" else ref.frame.analyse_frame
                c = time.process_time()
                runs[which] = fn(frame, use_mount=False)
                cpu[which].setdefault(size, []).append((time.process_time() - c) * 1e3)
            ratios.append(cpu[commit][size][-1] / max(cpu["current"][size][-1], 1e-6))
            a, b = runs["current"], runs[commit]
            if not (np.array_equal(a.features, b.features) and len(a.samples) == len(b.samples)
                    and all(np.array_equal(p.points, q.points) for p, q in zip(a.samples, b.samples))):
                differ.add(label)
    for which, by_size in cpu.items():
        every = [v for values in by_size.values() for v in values]
        sizes = ", ".join(f"{s} {median(v):.1f} / {p90(v):.1f}" for s, v in sorted(by_size.items()))
        print(f"  {which:9s} front half CPU median {median(every):6.1f} ms  p90 {p90(every):6.1f} ms"
              f"   ({sizes})")
    print(f"  {commit}/current: median per-frame CPU ratio {median(ratios):.3f}×; same samples and "
          f"features on {len(frames) - len(differ)}/{len(frames)} frames"
          + (f" (differ: {', '.join(sorted(differ))})" if differ else ""))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5, help="runs of every frame (default 5)")
    parser.add_argument("--views", type=int, default=2, help="viewpoints per scene (default 2)")
    parser.add_argument("--realdata", type=Path, default=DEFAULT_REALDATA,
                        help="folder of real frames (skipped if absent)")
    parser.add_argument("--no-reference", action="store_true", help="time the current code only")
    parser.add_argument("--threads", action="store_true",
                        help="compare 1 and 2 BLAS / OpenMP threads, interleaved, instead")
    parser.add_argument("--as-filed", action="store_true",
                        help=f"the old path is the detector as issue 20 was filed ({FILED_COMMIT}: its front "
                             "half, no cues, verifier or regrouping, scikit-learn's SVM decision), not the "
                             "code before the speed work")
    parser.add_argument("--real-only", action="store_true", help="time the real frames only")
    parser.add_argument("--front-half", metavar="COMMIT",
                        help="instead: the real frames' front half (analyse_frame) against COMMIT's, CPU, "
                             "interleaved")
    args = parser.parse_args()
    commit = FILED_COMMIT if args.as_filed else None
    from assistant.perception import FurnitureDetector

    if args.front_half:
        real = real_frames(args.realdata)
        print(f"real frames ({args.realdata}), front half only, floor searched for, {args.repeats} runs each:")
        front_half_comparison(real, args.repeats, args.front_half)
        return 0
    load_before = os.getloadavg()
    sim = [] if args.real_only else simulated_frames(args.views)
    real = real_frames(args.realdata) if args.realdata.is_dir() else []
    detector = FurnitureDetector()
    reference = not args.no_reference
    if reference:
        try:
            load_reference(commit) if commit else load_reference()
        except ReferenceUnavailable as exc:
            print(f"old path not timed: {exc}", file=sys.stderr)
            reference = False
    for _, frame in sim:  # warm-up: imports, model cache, catalogue
        detector.analyse(frame)
    for _, frame in real:
        detector.analyse(frame, use_mount=False)
    print(f"OMP_NUM_THREADS={os.environ.get('OMP_NUM_THREADS')!s}; "
          f"load average before: {' '.join(f'{v:.2f}' for v in load_before)} (1/5/15 min)")
    if args.threads:
        print("\nsimulated 640×480 frames, thread settings interleaved:")
        threads_comparison(detector, sim, True, args.repeats)
        if real:
            print("real frames, thread settings interleaved:")
            threads_comparison(detector, real, False, args.repeats)
    else:
        old = "as filed" if commit else "old path"
        if sim:
            res_sim = bench(detector, sim, True, args.repeats, reference, commit=commit)
            report("simulated 640×480 frames (robot mount known)", sim, res_sim, reference, old)
        if real:
            res_real = bench(detector, real, False, args.repeats, reference, commit=commit)
            report(f"real frames ({args.realdata}, floor searched for)", real, res_real, reference, old)
            res_reuse = bench(detector, real, False, args.repeats, False, reuse_floor=True)
            report("real frames, floor reused across the runs of each frame (one camera pose)",
                   real, res_reuse, False)
    load_after = os.getloadavg()
    print(f"\nload average after: {' '.join(f'{v:.2f}' for v in load_after)} (1/5/15 min); "
          f"{os.cpu_count()} cores. Targets: median ≤ 33 ms per 640×480 simulated frame; real frames "
          "of every size p90 ≤ 25 ms, median ≤ 18 ms (issue 20).")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

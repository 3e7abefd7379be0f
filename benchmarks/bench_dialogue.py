"""Turn-taking gap: from the end of a typed command to the robot's first reply (and, for
fetches, to its first motion), with the models already loaded.

Each utterance goes through :meth:`DialogueManager.handle` exactly as ``assistant chat`` sends
it; a fetch replies "Going to the bedroom." at once and runs in a worker thread (so does the robot's
search for an object it has never seen: "I haven't seen your glasses case yet — I'll go and look
for it."), which is stopped right away here (its simulator run is not part of the gap).
``where_memory`` answers from a remembered sighting, ``where_oracle`` from the world file
(``--search oracle``). Target: median first
reply ≤ 200 ms. The first-motion time (command → the fetch task's first velocity command to
the simulated robot) and the stop time ("stop" said while driving → the fetch has ended) are
measured on a few fetch starts.

    .venv/bin/python benchmarks/bench_dialogue.py [--repeats 5] [--motion 3]
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import threading
import time

UTTERANCES = [
    ("fetch", "bring me the mug from the table to the right of the chair in the bedroom"),
    ("fetch", "get my laptop from the table in front of the chair in the living room"),
    ("fetch", "go into the bedroom"),
    ("clarify", "get the statue from the table in the bedroom"),
    ("clarify", "bring me my fork"),
    ("unknown_word", "bring me the mug from the dresser in the bedroom"),
    ("search", "where is my glasses case?"),
    ("search", "have you seen my monitor"),
    ("where_memory", "where is my mug"),
    ("where_memory", "how do I get to my mug?"),
    ("where_oracle", "where is my glasses case?"),
    ("where_oracle", "how do I get to my fork?"),
    ("control", "which home am I in?"),
    ("control", "help"),
    ("control", "repeat that"),
    ("nonsense", "blorp zing wibble"),
    ("teach", "let me show you what 'in front of the couch' means"),
]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=5, help="passes over the utterances")
    ap.add_argument("--motion", type=int, default=3, help="fetches timed to the first motion (0: skip)")
    ap.add_argument("--world", default="apartment")
    args = ap.parse_args()

    from assistant.dialogue import DialogueManager, ObjectMemory, Services
    from assistant.app import stopping as stopping_module
    from assistant.world import load_world

    world = load_world(args.world)
    services = Services(perception="oracle")
    t0 = time.perf_counter()
    services.warm_up(world, background=False)
    load_s = time.perf_counter() - t0
    folder = tempfile.mkdtemp()

    times: dict[str, list[float]] = {}
    mug = next(f for f in world.scene("original").furniture if f.id == "hexagontable_1")
    for _ in range(args.repeats):
        for kind, text in UTTERANCES:
            memory = ObjectMemory(f"{folder}/m.json")
            for s in memory.sightings():
                memory.forget(s.world, s.object)
            if kind == "where_memory":  # seen 3 minutes ago (what a fetch or a search leaves)
                memory.remember(world.name, "mug", "bedroom", mug.id, "table", "on the table by the chair",
                                time_s=time.time() - 180, x_m=mug.x, y_m=mug.y)
            services.search_mode = "oracle" if kind == "where_oracle" else "sensed"
            manager = DialogueManager(world, services=services, memory=memory)
            start = time.perf_counter()
            turn = manager.handle(text)
            gap = time.perf_counter() - start
            manager.close(timeout=60.0)
            assert turn.intent != "error", turn.reply
            times.setdefault(kind, []).append(gap)

    motion, stops = [], []
    if args.motion:
        first_motion = {}
        original = stopping_module.StoppableRobot.__getattr__

        def spy(self, name):
            if name == "send_velocity" and "t" not in first_motion:
                first_motion["t"] = time.perf_counter()
            return original(self, name)

        stopping_module.StoppableRobot.__getattr__ = spy
        try:
            for _ in range(args.motion):
                first_motion.clear()
                manager = DialogueManager(world, services=services, memory=ObjectMemory(f"{folder}/m.json"))
                start = time.perf_counter()
                manager.handle("bring me the mug from the table to the right of the chair in the bedroom")
                while "t" not in first_motion and manager.busy:
                    time.sleep(0.002)
                if "t" in first_motion:
                    motion.append(first_motion["t"] - start)
                time.sleep(0.5)  # the robot is driving now
                stopped_at = time.perf_counter()
                manager.handle("stop")
                final = manager.wait(60.0)
                if final is not None and final.outcome == "stopped":
                    stops.append(time.perf_counter() - stopped_at)
                manager.close(timeout=60.0)
        finally:
            stopping_module.StoppableRobot.__getattr__ = original

    everything = [t for v in times.values() for t in v]
    print(f"models loaded in {load_s:.1f} s (parser, describer, environment, fetch runner; from the cache)")
    print(f"{'turn kind':<14} {'n':>4} {'median ms':>10} {'max ms':>8}")
    for kind, v in times.items():
        print(f"{kind:<14} {len(v):>4} {1000 * statistics.median(v):>10.2f} {1000 * max(v):>8.1f}")
    print(f"{'all':<14} {len(everything):>4} {1000 * statistics.median(everything):>10.2f} "
          f"{1000 * max(everything):>8.1f}   target: median ≤ 200 ms")
    if motion:
        print(f"command → first motion (fetch, {len(motion)} runs): median {1000 * statistics.median(motion):.0f} ms, "
              f"max {1000 * max(motion):.0f} ms")
    if stops:
        print(f"'stop' while driving → fetch ended ({len(stops)} runs): median {1000 * statistics.median(stops):.0f} ms, "
              f"max {1000 * max(stops):.0f} ms")
    print(f"threads alive at the end: {threading.active_count()}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

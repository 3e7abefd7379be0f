"""Speech timing: end of speech → the robot's first reply ready to play, the decoding real-time
factor, and "stop" → barge-in detected.

Utterances are spoken by espeak-ng (two voices, two rates) with a second of quiet room noise
after them, and streamed in 30 ms blocks — as the microphone delivers them — through the
endpointer, which feeds the recogniser while the person talks (``Recogniser.stream``). The gap
is counted from the true end of the speech:

    gap = the endpointer's wait for silence (audio time, it must hear the pause)
        + decoding's last passes + the dialogue's reply + synthesising its first sentence (wall;
          its CPU time is printed too: on a shared machine wall time counts other jobs' turns)

(the recogniser keeps up with the audio during the speech: its per-block cost is below the
block's length, see the real-time factor). Fetches are stopped as soon as they reply (their
drive is not part of the gap). The real-time factor is the whole-utterance decode time over
the audio length, home model, open fallback on. Barge-in: "stop" in four voices fed block by
block to the keyword spotter; latency = where it fired − the word's end (audio) + that block's
processing (wall). Targets: median gap ≤ 500 ms, real-time factor ≤ 0.3, barge-in ≤ 300 ms.

    .venv/bin/python benchmarks/bench_speech.py [--repeats 3]
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time

import numpy as np

UTTERANCES = (
    "where is my mug",
    "bring me the laptop from the table in the living room",
    "go to the bedroom the statue is on the table to the right of the bed",
    "have you seen my glasses case",
    "which home am i in",
    "how do i get to my fork",
)
SPEAKERS = (("en-us", 175), ("en-us+f3", 140))
BLOCK = 480  # 30 ms at 16 kHz


def _quiet_noise(n: int, seed: int) -> np.ndarray:
    return np.random.default_rng(seed).normal(0, 2e-3, n).astype(np.float32)


def measure_gap(text, voice, rate, recogniser, manager_factory, speaker, seed):
    from assistant.dialogue.speech.vad import UtteranceDetector
    from assistant.eval.speech_data import synthesise

    speech = synthesise(text, voice, rate)  # 0.5 s silence each side
    true_end_s = (len(speech) - 8000) / 16000.0
    audio = np.concatenate([speech, np.zeros(16000, np.float32)])
    audio = audio + _quiet_noise(len(audio), seed)
    stream = {"s": None}

    def on_samples(samples, starting):
        if starting:
            stream["s"] = recogniser.stream()
        stream["s"].feed(samples)

    detector = UtteranceDetector(on_samples=on_samples)
    for i in range(0, len(audio), BLOCK):
        done = detector.feed(audio[i:i + BLOCK])
        if done:
            heard_at_s = (i + BLOCK) / 16000.0
            break
    else:
        return None
    start, cpu_start = time.perf_counter(), time.process_time()
    heard = stream["s"].finish()
    manager = manager_factory()
    turn = manager.handle(heard.transcript)
    first = turn.reply.split(". ")[0]
    speaker.synthesise(first)
    wall, cpu = time.perf_counter() - start, time.process_time() - cpu_start
    manager.close(timeout=60.0)
    return heard_at_s - true_end_s, wall, cpu, heard


def measure_barge_in(voice, seed):
    from assistant.dialogue.speech.keyword import KeywordSpotter
    from assistant.eval.speech_data import synthesise

    stop = synthesise("stop", voice, 175)[8000:-8000]
    x = np.concatenate([np.zeros(16000, np.float32), stop, np.zeros(16000, np.float32)])
    x = x + _quiet_noise(len(x), seed)
    end_s = (16000 + len(stop)) / 16000.0
    spotter = KeywordSpotter("stop")
    for i in range(0, len(x), BLOCK):
        t0 = time.perf_counter()
        fired = spotter.feed(x[i:i + BLOCK])
        cost = time.perf_counter() - t0
        if fired:
            return (i + BLOCK) / 16000.0 - end_s + cost
    return None


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeats", type=int, default=3, help="passes over the utterances")
    args = ap.parse_args()

    from assistant.dialogue import DialogueManager, ObjectMemory, Services
    from assistant.dialogue.speech.recogniser import make_recogniser
    from assistant.dialogue.speech.tts import Speaker
    from assistant.eval.speech_data import synthesise
    from assistant.world import load_world

    world = load_world("apartment")
    t0 = time.perf_counter()
    recogniser = make_recogniser("pocketsphinx", world=world)
    services = Services(perception="oracle", search="oracle")
    services.warm_up(world, background=False)
    speaker = Speaker("en-us", 170, play=False)
    speaker.synthesise("ready")
    recogniser.recognise(synthesise("hello", "en-us", 175))
    load_s = time.perf_counter() - t0
    folder = tempfile.mkdtemp()

    def manager_factory():
        return DialogueManager(world, services=services, memory=ObjectMemory(f"{folder}/m.json"))

    gaps, waits, walls, cpus, rtf, misheard = [], [], [], [], [], 0
    for r in range(args.repeats):
        for n, text in enumerate(UTTERANCES):
            for voice, rate in SPEAKERS:
                measured = measure_gap(text, voice, rate, recogniser, manager_factory, speaker, seed=r * 100 + n)
                if measured is None:
                    continue
                wait, wall, cpu, heard = measured
                waits.append(wait)
                walls.append(wall)
                cpus.append(cpu)
                gaps.append(wait + wall)
                misheard += heard.transcript != text
                if r == 0:
                    samples = synthesise(text, voice, rate)
                    rtf.append(recogniser.recognise(samples).real_time_factor)
    barge = [b for r in range(args.repeats)
             for b in (measure_barge_in(v, seed=r) for v in ("en-us", "en-us+f3", "en-us+m3", "en-us-nyc"))
             if b is not None]
    print(f"models loaded in {load_s:.1f} s")
    print(f"end of speech → first reply synthesised ({len(gaps)} utterances, {misheard} not word-perfect): "
          f"median {1000 * statistics.median(gaps):.0f} ms, max {1000 * max(gaps):.0f} ms   target: median ≤ 500 ms")
    print(f"  of which the endpointer's wait for silence: median {1000 * statistics.median(waits):.0f} ms; "
          f"decode end + reply + synthesis: median {1000 * statistics.median(walls):.0f} ms wall, "
          f"{1000 * statistics.median(cpus):.0f} ms CPU")
    print(f"  with CPU time in place of wall time (what a quiet machine would give): median "
          f"{1000 * statistics.median([w + c for w, c in zip(waits, cpus)]):.0f} ms")
    print(f"decoding real-time factor ({len(rtf)} utterances): median {statistics.median(rtf):.3f}, "
          f"max {max(rtf):.3f}   target: ≤ 0.3")
    if barge:
        print(f"'stop' → barge-in detected ({len(barge)} of {4 * args.repeats}): median "
              f"{1000 * statistics.median(barge):.0f} ms, max {1000 * max(barge):.0f} ms   target: ≤ 300 ms")
    else:
        print("'stop' was never detected")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

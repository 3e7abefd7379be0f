"""Barge-in: how often "stop" is heard while the robot is busy, and how often something else is
taken for it (``assistant.dialogue.speech.keyword.KeywordSpotter``).

Heard: six ways of saying it ("stop", "robot stop", "stop it", "please stop", "okay stop now",
"no stop") in the four test voices at 140 and 175 words per minute over a quiet floor, and at
140 wpm in household noise at 10 dB SNR (72 utterances). False alarms: every third clean
sentence of the speech test set that does not hold "stop" (fetch commands, where-questions, chat
turns: ``assistant.eval.speech_data``) and eight sentences the robot itself says, in its default
voice (a microphone hears the robot's loudspeaker). Audio is fed in 30 ms blocks, as the
microphone delivers it. Each row is one setting of the spotter: the keyphrase threshold and the
longest stretch of speech a "stop" may end (``max_run_s``; none: the keyphrase search alone).

    .venv/bin/python benchmarks/bench_barge_in.py [--thresholds 1e-20,1e-23] [--runs none,1.6]
"""

from __future__ import annotations

import argparse

import numpy as np

BLOCK = 480  # 30 ms at 16 kHz
VOICES = ("en-us", "en-us+f3", "en-us+m3", "en-us-nyc")
PHRASES = ("stop", "robot stop", "stop it", "please stop", "okay stop now", "no stop")
ROBOT_SAYS = ("Looking in the hallway.", "I found your mug on the small table next to the couch.",
              "Going to the bedroom.", "Shall I go and get it?",
              "I looked in the kitchen and the living room and did not find your keys.",
              "The statue is on the table to the right of the bed.",
              "Sorry, I did not understand that.", "Okay, I will wait here.")


def _padded(speech: np.ndarray, before_s: float = 1.0, after_s: float = 1.0) -> np.ndarray:
    return np.concatenate([np.zeros(int(16000 * before_s), np.float32), speech,
                           np.zeros(int(16000 * after_s), np.float32)])


def stop_requests() -> list[tuple[str, np.ndarray]]:
    from assistant.eval.speech_data import household_noise, mix_at_snr, synthesise

    out = []
    for phrase in PHRASES:
        for voice in VOICES:
            for rate in (140, 175):
                x = _padded(synthesise(phrase, voice, rate)[8000:-8000])
                out.append((phrase, x + np.random.default_rng(rate).normal(0, 2e-3, len(x)).astype(np.float32)))
                if rate == 140:
                    out.append((phrase, mix_at_snr(x, household_noise(len(x), 3), 10.0)))
    return out


def other_speech() -> list[np.ndarray]:
    from assistant.eval.speech_data import audio_of, items, synthesise

    people = [i for i in items() if i.snr_db is None and "stop" not in i.text.split()][::3]
    robot = [_padded(synthesise(text, "en-us", 170), 0.5, 0.5) for text in ROBOT_SAYS]
    return [audio_of(i) for i in people] + robot


def detections(x: np.ndarray, threshold: float, max_run_s: float | None) -> int:
    from assistant.dialogue.speech.keyword import KeywordSpotter

    spotter = KeywordSpotter("stop", threshold=threshold, max_run_s=max_run_s)
    return sum(spotter.feed(x[i:i + BLOCK]) for i in range(0, len(x), BLOCK))


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--thresholds", default="1e-20", help="keyphrase thresholds, comma-separated")
    ap.add_argument("--runs", default="none,1.6", help="max_run_s values (none: no limit), comma-separated")
    args = ap.parse_args()
    stops, others = stop_requests(), other_speech()
    print(f"{len(stops)} stop requests, {len(others)} other utterances "
          f"({sum(len(x) for x in others) / 16000:.0f} s)")
    for threshold in (float(t) for t in args.thresholds.split(",")):
        for run in args.runs.split(","):
            max_run_s = None if run.strip() == "none" else float(run)
            heard = [detections(x, threshold, max_run_s) > 0 for _, x in stops]
            false = sum(detections(x, threshold, max_run_s) for x in others)
            missed = sorted({p for (p, _), h in zip(stops, heard) if not h})
            print(f"threshold {threshold:g}, longest speech {run} s: stop heard {sum(heard)}/{len(stops)}, "
                  f"false alarms {false} in {len(others)} utterances; missed phrasings: {', '.join(missed) or '-'}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

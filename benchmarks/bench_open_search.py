"""The open search (pocketsphinx's general US-English model, the recogniser's fallback when the
home search is unsure): CPU time and word error at its beam settings, on clean sentences of the
speech test set (every 22nd: commands, questions and chat turns), each decoded whole over the
noise floor, as the recogniser does. Rows: the home search's wide beams (what the open search
used until 2 Dec evening), pocketsphinx's default beams, and the product's open-search settings
(``sphinx.OPEN_SEARCH``: default beams, at most 3000 HMMs and 20 words per frame). Compare the
rows' real-time factors with each other (the same run, the same load), not across runs.

    .venv/bin/python benchmarks/bench_open_search.py [--count 12]
"""

from __future__ import annotations

import argparse
import time


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--count", type=int, default=12, help="sentences (default 12)")
    args = ap.parse_args()

    import pocketsphinx as ps

    from assistant.dialogue.speech.audio import to_pcm16, with_noise_floor
    from assistant.dialogue.speech.sphinx import DECODER_SETTINGS, OPEN_SEARCH, _decode
    from assistant.eval.speech import word_errors
    from assistant.eval.speech_data import audio_of, items

    chosen = [i for i in items() if i.snr_db is None][::22][:args.count]
    audio = [to_pcm16(with_noise_floor(audio_of(i), 30.0)) for i in chosen]
    seconds = sum(len(a) / 2 / 16000 for a in audio)
    rows = (("home search's wide beams (before)", {}),
            ("pocketsphinx's default beams", {"beam": 1e-48, "wbeam": 7e-29, "pbeam": 1e-48}),
            ("OPEN_SEARCH (now)", OPEN_SEARCH))
    for name, extra in rows:
        decoder = ps.Decoder(**{**DECODER_SETTINGS, **extra})
        cpu, errors, words = time.process_time(), 0, 0
        for item, pcm in zip(chosen, audio):
            heard = " ".join(w for w, *_ in _decode(decoder, pcm))
            errors += word_errors(item.reference, heard)
            words += len(item.reference.split())
        cpu = time.process_time() - cpu
        print(f"{name}: {cpu:.1f} s CPU for {seconds:.0f} s of audio (real-time factor {cpu / seconds:.2f}), "
              f"word error {100 * errors / words:.1f} %", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

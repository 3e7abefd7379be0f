"""Experiment: does adapting pocketsphinx's acoustic model to one voice ("enrolment") fix the
plan misses that are left (issue 17)? Not a product feature yet — the measurement that decides
whether to build ``assistant enrol``.

For one voice of the speech test set: ``--sentences`` enrolment sentences are synthesised with
that voice (sentences of the annotated corpus (or of the home model's text) that are not in the test set, alternating 140 and 175 words a
minute), front-end features are computed as the recogniser computes them (noise floor 30 dB
under the speech, the voice's VTLN warp, dither, pocketsphinx's feature parameters), SphinxTrain's
``bw`` collects the statistics, and ``mllr_solve`` (a transform the decoder applies: ``mllr=``)
or ``map_adapt`` (new model parameters: ``hmm=``) adapts the model. Then every clean command and
question of the test set in that voice is decoded before and after, and the plan agreement and
word error are printed.

Needs SphinxTrain's tools and the model converters (Debian: ``apt-get install sphinxtrain
sphinxbase-utils pocketsphinx``): ``bw``, ``mllr_solve``, ``map_adapt``, ``sphinx_fe`` and
``pocketsphinx_mdef_convert`` (the packaged model's ``mdef`` is binary, its mixture weights are
only the compressed ``sendump``, which is expanded here). Everything is written under ``--work``.

    .venv/bin/python benchmarks/speaker_adaptation.py --voice en-us+f3 [--method mllr|map] [--sentences 40]
"""

from __future__ import annotations

import argparse
import shutil
import struct
import subprocess
import sys
import wave
from pathlib import Path

import numpy as np

SPHINXTRAIN = Path("/usr/lib/sphinxtrain")
TOOLS = {"bw": SPHINXTRAIN / "bw", "mllr_solve": SPHINXTRAIN / "mllr_solve", "map_adapt": SPHINXTRAIN / "map_adapt",
         "sphinx_fe": Path(shutil.which("sphinx_fe") or "sphinx_fe"),
         "pocketsphinx_mdef_convert": Path(shutil.which("pocketsphinx_mdef_convert") or "pocketsphinx_mdef_convert")}
#: the packaged model's front end (its feat.params), as sphinx_fe options
FRONT_END = ["-lowerf", "130", "-upperf", "6800", "-nfilt", "25", "-transform", "dct", "-lifter", "22",
             "-samprate", "16000", "-dither", "yes", "-seed", "1", "-remove_silence", "no", "-remove_noise", "yes"]
FEATURES = ["-feat", "1s_c_d_dd", "-svspec", "0-12/13-25/26-38", "-cmn", "batch", "-agc", "none", "-varnorm", "no"]


def expand_sendump(path: Path) -> np.ndarray:
    """The mixture weights (senones × streams × densities) from pocketsphinx's 8-bit ``sendump``
    (each weight stored as ``-log_1.0001(w) >> mixw_shift``)."""
    data = path.read_bytes()
    pos = 0

    def integer() -> int:
        nonlocal pos
        value = struct.unpack_from("<I", data, pos)[0]
        pos += 4
        return value

    def string() -> str | None:
        nonlocal pos
        n = integer()
        text = data[pos:pos + n - 1].decode("ascii", "replace") if n else None
        pos += n
        return text

    string()  # title
    header = {}
    while (line := string()) is not None:
        key, *value = line.split()
        header[key] = value[0] if value else ""
    if int(header.get("cluster_count", 0)) != 0:
        raise SystemExit(f"{path}: clustered sendump files are not handled")
    streams, shift = int(header["feature_count"]), int(header.get("mixw_shift", 10))
    densities, senones = integer(), integer()
    weights = np.empty((senones, streams, densities))
    for s in range(streams):
        for d in range(densities):
            raw = np.frombuffer(data, np.uint8, senones, pos).astype(np.int64) << shift
            pos += senones
            weights[:, s, d] = np.power(1.0001, -raw.astype(np.float64))
    return weights


def write_mixture_weights(path: Path, weights: np.ndarray) -> None:
    """A SphinxTrain ``mixture_weights`` file (s3 header, byte-order word, 3-d float32 array)."""
    head = b"s3\nversion 1.0\n"
    pad = (4 - (len(head) + len(b"endhdr\n")) % 4) % 4
    d1, d2, d3 = weights.shape
    with open(path, "wb") as f:
        f.write(head + b" " * pad + b"endhdr\n" + struct.pack("=i", 0x11223344))
        f.write(struct.pack("=IIII", d1, d2, d3, d1 * d2 * d3))
        weights.astype("<f4").tofile(f)


def run(*args) -> None:
    done = subprocess.run([str(a) for a in args], capture_output=True, text=True)
    if done.returncode:
        raise SystemExit(f"{Path(str(args[0])).name} failed ({done.returncode}): {done.stderr.strip()[-400:]}")


def enrolment_sentences(count: int, source: str = "corpus") -> list[str]:
    """Sentences of 5–14 words that are not test sentences, spread through ``source``: the
    annotated corpus's descriptions (spoken form) or the home model's whole text."""
    from assistant.dialogue.speech.vocabulary import build_vocabulary, corpus_sentences, normalise_transcript
    from assistant.eval.speech_data import sentences

    test = {normalise_transcript(text) for text, _, _ in sentences()}
    text = corpus_sentences() if source == "corpus" else build_vocabulary().sentences
    pool = [s for s in text if 5 <= len(s.split()) <= 14 and s not in test]
    return pool[::max(1, len(pool) // count)][:count]


def prepare(voice: str, count: int, work: Path, source: str = "corpus") -> None:
    """Enrolment audio, features, control file, transcripts and dictionary under ``work``."""
    from assistant.dialogue.speech.audio import to_pcm16, with_noise_floor
    from assistant.dialogue.speech.language_model import build_home_model
    from assistant.dialogue.speech.listener import PAD_S
    from assistant.dialogue.speech.vtln import pitch_hz, warp_for_pitch
    from assistant.eval.speech_data import synthesise

    (work / "wav").mkdir(parents=True, exist_ok=True)
    (work / "feat").mkdir(exist_ok=True)
    ids, lines = [], []
    for n, text in enumerate(enrolment_sentences(count, source)):
        samples = synthesise(text, voice, (140, 175)[n % 2])
        pad = np.zeros(int(PAD_S * 16000), dtype=np.float32)
        samples = np.concatenate([pad, samples, pad])
        warp = warp_for_pitch(pitch_hz(samples))
        uid = f"enrol{n:03d}"
        with wave.open(str(work / "wav" / f"{uid}.wav"), "wb") as f:
            f.setnchannels(1)
            f.setsampwidth(2)
            f.setframerate(16000)
            f.writeframes(to_pcm16(with_noise_floor(samples, 30.0)))
        run(TOOLS["sphinx_fe"], *FRONT_END, "-warp_type", "inverse_linear", "-warp_params", f"{warp:g}", "-mswav", "yes",
            "-i", work / "wav" / f"{uid}.wav", "-o", work / "feat" / f"{uid}.mfc")
        ids.append(uid)
        lines.append(f"<s> {text} </s> ({uid})")
    (work / "ctl").write_text("\n".join(ids) + "\n")
    (work / "trans").write_text("\n".join(lines) + "\n")
    shutil.copy(build_home_model().dictionary, work / "dict")


def adapt(model: Path, work: Path, method: str) -> dict:
    """Run ``bw`` and the adaptation; the decoder settings that use the result."""
    run(TOOLS["pocketsphinx_mdef_convert"], "-text", model / "mdef", work / "mdef.txt")
    write_mixture_weights(work / "mixture_weights", expand_sendump(model / "sendump"))
    accum = work / "accum"
    accum.mkdir(exist_ok=True)
    run(TOOLS["bw"], "-moddeffn", work / "mdef.txt", "-ts2cbfn", ".ptm.", *FEATURES, "-dictfn", work / "dict",
        "-fdictfn", model / "noisedict", "-ctlfn", work / "ctl", "-lsnfn", work / "trans", "-accumdir", accum,
        "-cepdir", work / "feat", "-cepext", "mfc", "-mixwfn", work / "mixture_weights", "-meanfn", model / "means",
        "-varfn", model / "variances", "-tmatfn", model / "transition_matrices")
    if method == "mllr":
        run(TOOLS["mllr_solve"], "-meanfn", model / "means", "-varfn", model / "variances",
            "-outmllrfn", work / "mllr_matrix", "-accumdir", accum)
        return {"mllr": str(work / "mllr_matrix")}
    adapted = work / "map"
    adapted.mkdir(exist_ok=True)
    for name in ("mdef", "feat.params", "noisedict"):
        shutil.copy(model / name, adapted / name)
    run(TOOLS["map_adapt"], "-moddeffn", work / "mdef.txt", "-ts2cbfn", ".ptm.", "-meanfn", model / "means",
        "-varfn", model / "variances", "-mixwfn", work / "mixture_weights", "-tmatfn", model / "transition_matrices",
        "-accumdir", accum, "-mapmeanfn", adapted / "means", "-mapvarfn", adapted / "variances",
        "-mapmixwfn", adapted / "mixture_weights", "-maptmatfn", adapted / "transition_matrices")
    return {"hmm": str(adapted)}


def score(voice: str, settings: dict | None) -> tuple[int, int, float, list[str]]:
    """(plans equal, planned, word error, misses) over the voice's clean commands and questions."""
    from assistant.dialogue.speech.sphinx import PocketsphinxRecogniser
    from assistant.eval.speech import _Parsers, request_of, word_errors
    from assistant.eval.speech_data import audio_of, items

    chosen = [i for i in items(None, False, (None,), ["command", "where"]) if i.voice == voice]
    parsers = _Parsers()
    recogniser = PocketsphinxRecogniser(open_fallback=False, settings=settings)
    equal, errors, words, misses = 0, 0, 0, []
    for item in chosen:
        parser = parsers(item.world)
        recogniser.use_home(parser.world)
        heard = recogniser.recognise(audio_of(item)).transcript
        same = request_of(parser, heard) == request_of(parser, item.text)
        equal += same
        errors += word_errors(item.reference, heard)
        words += len(item.reference.split())
        if not same:
            misses.append(f"{item.reference!r} -> {heard!r}")
    return equal, len(chosen), errors / max(words, 1), misses


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--voice", default="en-us+f3", help="an espeak-ng voice of the test set (default en-us+f3)")
    ap.add_argument("--method", choices=("mllr", "map"), default="mllr", help="adaptation (default mllr)")
    ap.add_argument("--sentences", type=int, default=40, help="enrolment sentences (default 40)")
    ap.add_argument("--script", choices=("corpus", "home"), default="corpus",
                    help="enrolment sentences from the annotated corpus (default) or the home model's text")
    ap.add_argument("--work", type=Path, default=Path("/tmp/speaker-adaptation"), help="working folder")
    args = ap.parse_args()
    missing = [name for name, path in TOOLS.items() if not (path.is_file() or shutil.which(str(path)))]
    if missing:
        print(f"missing tools: {', '.join(missing)} — apt-get install sphinxtrain sphinxbase-utils pocketsphinx",
              file=sys.stderr)
        return 2
    import pocketsphinx

    model = Path(pocketsphinx.get_model_path()) / "en-us" / "en-us"
    work = args.work / f"{args.voice}-{args.method}-{args.sentences}-{args.script}"
    prepare(args.voice, args.sentences, work, args.script)
    settings = adapt(model, work, args.method)
    for name, used in (("packaged model", None), (f"{args.method}, {args.sentences} sentences", settings)):
        equal, planned, wer, misses = score(args.voice, used)
        print(f"{args.voice} {name}: plan = typed plan {equal} of {planned}, word error {100 * wer:.1f} %")
        for miss in misses:
            print(f"    {miss}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

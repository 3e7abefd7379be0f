"""Speaker adaptation per test voice: the packaged model, MLLR and MAP (which ``assistant enrol``
uses), compared on the voice's clean commands and questions of the speech test set.

For one voice: the first ``--sentences`` sentences of the enrolment script
(:func:`~assistant.dialogue.speech.enrol.enrolment_script`) are synthesised in that voice
(140 and 175 words a minute in turn), the features and statistics are made as ``assistant enrol``
makes them (:mod:`assistant.dialogue.speech.enrol`), and the model is adapted by ``mllr_solve``
(a transform the decoder applies, ``mllr=``) or ``map_adapt`` (new model parameters, ``hmm=``).
Then every clean command and question of the test set in that voice is decoded with the packaged
model and with the adapted one; plan agreement and word error are printed with the misses.
Needs SphinxTrain (``make setup`` installs it; ``mllr_solve`` comes with ``bw``).

    .venv/bin/python benchmarks/speaker_adaptation.py --voice en-us+f3 [--method map|mllr] [--sentences 40]
"""

from __future__ import annotations

import argparse
import shutil
import sys
import tempfile
from pathlib import Path


def adapted_settings(voice: str, method: str, count: int, work: Path) -> dict:
    """Decoder settings that use ``voice``'s adapted model (built under ``work``)."""
    from assistant.dialogue.speech import enrol
    from assistant.eval.speech import enrolment_recordings

    found = enrol.require_tools()
    base = enrol.training_model()
    enrol.training_files(enrolment_recordings(voice, count), work, found["sphinx_fe"])
    accum = enrol.collect_statistics(base, work, found)
    if method == "map":
        return {"hmm": str(enrol.map_adapt(base, work, found))}
    packaged = enrol.packaged_model()
    solver = enrol.SPHINXTRAIN_DIR / "mllr_solve"
    enrol.run_tool(solver if solver.is_file() else shutil.which("mllr_solve") or "mllr_solve", "-meanfn",
               packaged / "means", "-varfn", packaged / "variances", "-outmllrfn", work / "mllr_matrix",
               "-accumdir", accum)
    return {"mllr": str(work / "mllr_matrix")}


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
    ap.add_argument("--method", choices=("map", "mllr"), default="map", help="adaptation (default map)")
    ap.add_argument("--sentences", type=int, default=40, help="enrolment sentences (default 40)")
    args = ap.parse_args()
    from assistant.errors import AssistantError

    with tempfile.TemporaryDirectory(prefix="speaker-adaptation-") as folder:
        try:
            settings = adapted_settings(args.voice, args.method, args.sentences, Path(folder))
        except AssistantError as error:
            print(error, file=sys.stderr)
            return 2
        for name, used in (("packaged model", None), (f"{args.method}, {args.sentences} sentences", settings)):
            equal, planned, wer, misses = score(args.voice, used)
            print(f"{args.voice} {name}: plan = typed plan {equal} of {planned}, word error {100 * wer:.1f} %")
            for miss in misses:
                print(f"    {miss}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""``assistant eval speech``: recognition on the speech test set, and what it does to the plans.

For every utterance of :mod:`assistant.eval.speech_data` (our sentences spoken by espeak-ng, clean
and in household noise) the recogniser's words are compared with the typed sentence:

* **word error rate** — (substitutions + deletions + insertions) / reference words, over the
  normalised words (lower case, no punctuation);
* **plan equal** — for commands and where-questions, whether the robot would do the same with the
  heard words as with the typed text (:func:`request_of`, in the utterance's home): a command's
  plan (room, RDT nodes, object, support furniture) from :class:`~assistant.grounding.CommandParser`;
  a where-question's kind and the thing it asks for, read as the dialogue reads them;
* **intent equal** — for every utterance, whether the dialogue routes the heard words to the same
  intent as the typed ones (:func:`~assistant.dialogue.classify`);
* **timing** — decoding seconds and the real-time factor (decode time / audio length);
* **would confirm** — the share below the chat's "Did you say …?" threshold.

Rows come back per utterance; the summary groups them by engine, noise level, voice, rate and
kind. Nothing is printed here (``assistant/cli/eval_speech.py`` prints).
"""

from __future__ import annotations

import re
import statistics
import time
from collections import defaultdict
from pathlib import Path

from assistant.eval.progress import Progress, no_progress

PLAN_KEYS = ("room", "nodes", "object", "support")


def word_errors(reference: str, hypothesis: str) -> int:
    """Word-level edit distance (substitutions, deletions, insertions)."""
    from rapidfuzz.distance import Levenshtein

    return int(Levenshtein.distance(reference.split(), hypothesis.split()))


def plan_of(parser, text: str) -> dict:
    plan = parser.parse(text).to_dict()["plan"]
    return {k: plan.get(k) for k in PLAN_KEYS}


def request_of(parser, text: str) -> dict:
    """What the robot would do with ``text`` in ``parser``'s home, as the dialogue routes it
    (:class:`~assistant.dialogue.DialogueManager`): a where-question ("where are my keys", "how do
    I get to my wallet") → its kind and the thing asked for (known object, or the unknown noun);
    anything else → the command parser's plan. (The parser reads commands: "where are my keys"
    is no command to it and gives an empty plan, so where-questions are not compared by it.)"""
    from assistant.dialogue import classify
    from assistant.dialogue.clarify import named_object

    intent = classify(text)
    if intent.name in ("where", "where_dynamic"):
        return {"intent": intent.name, "object": named_object(intent.text, parser.world)}
    return {"intent": "command", **plan_of(parser, text)}


class _Parsers:
    """One command parser per home, trained once (the language and grounding models are shared)."""

    def __init__(self):
        self._by_world: dict = {}
        self._base = None

    def __call__(self, world_name: str):
        if world_name not in self._by_world:
            from assistant.grounding import CommandParser
            from assistant.world import load_world

            if self._base is None:
                self._base = CommandParser.load(None)
            self._by_world[world_name] = CommandParser(self._base.language, self._base.grounder,
                                                       load_world(world_name))
        return self._by_world[world_name]


def evaluate_speech(engine: str = "pocketsphinx", asr_model=None, per_kind: int | None = None, all_voices: bool = False,
                    kinds=None, snrs_db=None, open_fallback: bool = True, confirm_below: float | None = None,
                    shard: tuple[int, int] = (1, 1), home: bool = True, vtln: bool = True,
                    enrol: int | None = None, progress: Progress = no_progress) -> dict:
    """The report: ``rows`` (one per utterance), ``summary`` (all), ``groups`` (by factor).
    ``shard`` (i, n): only every n-th utterance from the i-th (1-based), to run in parallel
    processes; :func:`merge_reports` joins their reports. ``home``: tell the recogniser each
    utterance's home (:meth:`~assistant.dialogue.speech.recogniser.Recogniser.use_home`). ``vtln``
    (pocketsphinx): warp the front end to each voice's pitch (:mod:`~assistant.dialogue.speech.vtln`).
    ``enrol`` (pocketsphinx): each voice is first enrolled with that many sentences of the
    enrolment script, spoken in that voice (:func:`enrolled_voice`), and decoded with its model."""
    from assistant.dialogue import classify
    from assistant.dialogue.speech.listener import DEFAULT_CONFIRM_BELOW
    from assistant.dialogue.speech.recogniser import make_recogniser
    from assistant.eval import speech_data

    wall = time.perf_counter()
    options = {"asr_model": asr_model} if asr_model else {"open_fallback": open_fallback}
    if engine == "pocketsphinx":
        options["vtln"] = vtln
    progress(f"loading the {engine} recogniser")
    if enrol and engine != "pocketsphinx":
        from assistant.errors import AssistantError

        raise AssistantError(f"--enrol adapts pocketsphinx's acoustic model; {engine} has no enrolment")
    recogniser = make_recogniser(engine, **options)
    if engine == "pocketsphinx" and open_fallback and not enrol:  # (enrolled voices decode with their own)
        recogniser.recognise(speech_data.synthesise("hello", "en-us", 175))  # the open model is loaded
    by_voice: dict = {}  # voice → its enrolled recogniser (with ``enrol``)

    def recogniser_for(voice: str):
        if not enrol:
            return recogniser
        if voice not in by_voice:
            model = enrolled_voice(voice, enrol, progress)
            by_voice[voice] = make_recogniser(engine, **options, speaker=str(model))
        return by_voice[voice]

    parsers = _Parsers()
    threshold = DEFAULT_CONFIRM_BELOW if confirm_below is None else confirm_below
    todo = speech_data.items(per_kind, all_voices, speech_data.SNRS_DB if snrs_db is None else snrs_db, kinds)
    todo = todo[shard[0] - 1::shard[1]]
    rows = []
    for n, item in enumerate(todo, start=1):
        progress("speech test set", n, len(todo))
        audio = speech_data.audio_of(item)
        hearing = recogniser_for(item.voice)
        if home:
            hearing.use_home(parsers(item.world).world)  # the recogniser knows the home it serves
        heard = hearing.recognise(audio)
        ref = item.reference
        row = {"id": item.id, "kind": item.kind, "world": item.world, "voice": item.voice, "rate": item.rate,
               "noise": item.noise, "engine": engine, "reference": ref, "transcript": heard.transcript,
               "words": len(ref.split()), "errors": word_errors(ref, heard.transcript),
               "confidence": round(heard.confidence, 3), "search": heard.search, "warp": heard.warp,
               "audio_s": round(heard.audio_s, 3), "decode_s": round(heard.decode_s, 4),
               "intent_equal": classify(heard.transcript).name == classify(item.text).name,
               "plan_equal": None, "would_confirm": heard.confidence < threshold}
        if item.kind in ("command", "where"):
            parser = parsers(item.world)
            row["plan_equal"] = request_of(parser, heard.transcript) == request_of(parser, item.text)
        rows.append(row)
    for r in (recogniser, *by_voice.values()):
        r.close()
    head = {"engine": engine, "recogniser": recogniser.describe(), "per_kind": per_kind, "all_voices": all_voices,
            "confirm_below": threshold, "home": home, "vtln": vtln, "enrol": enrol, "shard": list(shard),
            "wall_seconds": round(time.perf_counter() - wall, 1)}
    return report_of(rows, head)


def enrolled_voice(voice: str, count: int, progress: Progress = no_progress) -> Path:
    """The acoustic model adapted to a test voice from the first ``count`` sentences of the
    enrolment script synthesised in it (140 and 175 words a minute in turn), built once and
    cached (keyed by the voice, the script and the enrolment's feature settings). No script sentence is a
    test sentence (``tests/dialogue/speech/test_enrol.py``)."""
    import hashlib

    from assistant.dialogue.speech.enrol import FEATURES, FRONT_END, enrol, enrolment_script, speaker_model
    from assistant.fileio import cache_dir

    script = enrolment_script(count)
    key = hashlib.sha1("\n".join([voice, *script, *FRONT_END, *FEATURES]).encode()).hexdigest()[:12]
    data_dir = cache_dir() / "speech" / "enrolled" / key
    name = re.sub(r"[^A-Za-z0-9_-]", "_", voice)
    model = speaker_model(name, data_dir)
    if not (model / "means").is_file():
        enrol(name, enrolment_recordings(voice, count, progress), data_dir)
    return model


def enrolment_recordings(voice: str, count: int, progress: Progress = no_progress) -> list:
    """(samples, sentence) of the first ``count`` enrolment-script sentences spoken by the test
    voice ``voice``, at 140 and 175 words a minute in turn (as the test set's rates)."""
    from assistant.dialogue.speech.enrol import enrolment_script
    from assistant.eval import speech_data

    script = enrolment_script(count)
    recordings = []
    for n, text in enumerate(script):
        progress(f"enrolling the voice {voice}", n + 1, len(script))
        recordings.append((speech_data.synthesise(text, voice, (140, 175)[n % 2]), text))
    return recordings


def report_of(rows: list[dict], head: dict) -> dict:
    """``head`` plus the summaries of ``rows`` (all, by factor, by noise and kind) and the rows."""
    groups = {factor: {value: summarise(rs) for value, rs in sorted(_group(rows, factor).items())}
              for factor in ("noise", "voice", "rate", "kind")}
    by_noise_kind = {f"{noise} / {kind}": summarise(rs) for (noise, kind), rs in sorted(_group2(rows).items())}
    return {**head, "utterances": len(rows), "summary": summarise(rows), "groups": groups,
            "noise_and_kind": by_noise_kind, "rows": rows}


def merge_reports(reports: list[dict]) -> dict:
    """One report from the reports of the shards of one run (rows in utterance order)."""
    rows = sorted((r for rep in reports for r in rep["rows"]), key=lambda r: r["id"])
    head = {k: v for k, v in reports[0].items() if k in ("engine", "recogniser", "per_kind", "all_voices", "confirm_below")}
    head["wall_seconds"] = max(rep.get("wall_seconds", 0.0) for rep in reports)
    head["merged_from"] = len(reports)
    return report_of(rows, head)


def summarise(rows: list[dict]) -> dict:
    """WER, plan and intent agreement, timing and confirmation share of some rows."""
    words = sum(r["words"] for r in rows)
    planned = [r["plan_equal"] for r in rows if r["plan_equal"] is not None]
    audio = sum(r["audio_s"] for r in rows)
    decode = [r["decode_s"] for r in rows]
    return {"utterances": len(rows), "words": words,
            "wer": round(sum(r["errors"] for r in rows) / words, 4) if words else None,
            "sentence_correct": round(sum(r["errors"] == 0 for r in rows) / len(rows), 4) if rows else None,
            "plan_equal": round(sum(planned) / len(planned), 4) if planned else None, "planned": len(planned),
            "intent_equal": round(sum(r["intent_equal"] for r in rows) / len(rows), 4) if rows else None,
            "would_confirm": round(sum(r["would_confirm"] for r in rows) / len(rows), 4) if rows else None,
            "open_used": sum(r["search"] == "open" for r in rows),
            "median_decode_s": round(statistics.median(decode), 3) if decode else None,
            "real_time_factor": round(sum(decode) / audio, 3) if audio else None}


def _group(rows, factor):
    out = defaultdict(list)
    for r in rows:
        out[str(r[factor])].append(r)
    return out


def _group2(rows):
    out = defaultdict(list)
    for r in rows:
        out[(r["noise"], r["kind"])].append(r)
    return out

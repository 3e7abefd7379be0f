"""`assistant eval speech`: the test set's making (noise, SNR, sentences) and the scoring."""

import json
import shutil

import numpy as np
import pytest

from assistant.eval.speech import summarise, word_errors
from assistant.eval.speech_data import household_noise, items, mix_at_snr, sentences


def test_word_errors_count_substitutions_deletions_insertions():
    assert word_errors("where is my mug", "where is my mug") == 0
    assert word_errors("where is my mug", "where is the mug") == 1
    assert word_errors("where is my mug", "where my mug now") == 2
    assert word_errors("stop", "") == 1


def test_noise_is_seeded_and_mixed_at_the_asked_snr():
    a, b, c = household_noise(16000, 7), household_noise(16000, 7), household_noise(16000, 8)
    assert np.array_equal(a, b) and not np.array_equal(a, c)
    assert abs(float(np.mean(a ** 2)) - 1.0) < 1e-3
    t = np.arange(32000) / 16000.0
    speech = np.concatenate([np.zeros(8000), 0.1 * np.sin(2 * np.pi * 220 * t), np.zeros(8000)]).astype(np.float32)
    noise = household_noise(len(speech), 1)
    for snr in (20.0, 10.0):
        mixed = mix_at_snr(speech, noise, snr)
        added = mixed - speech
        measured = 10 * np.log10(np.mean(speech[8000:-8000] ** 2) / np.mean(added ** 2))
        assert abs(measured - snr) < 0.5


def test_sentences_and_rotation_cover_kinds_voices_rates():
    said = sentences()
    kinds = {k for _, k, _ in said}
    from assistant.language.corpus import repo_root

    dev = [json.loads(line) for line in (repo_root() / "corpus" / "fetch_dev.jsonl").read_text().splitlines()
           if line.strip()]
    distinct = {(d["text"], d.get("world", "apartment")) for d in dev}
    assert len(distinct) < len(dev)  # the dev set repeats commands in other scenes and seeds
    assert kinds == {"command", "where", "chat"} and sum(k == "command" for _, k, _ in said) == len(distinct)
    assert len(set(said)) == len(said)  # each sentence once
    assert not any(t.strip() in ("asdfgh", "blorp zing wibble") for t, _, _ in said)  # garbled turns left out
    # the chat sentences are a fixed list: a scripted conversation added since is not in it
    assert sum(k == "chat" for _, k, _ in said) == 225 and ("go to couch", "chat", "apartment") not in said
    all_items = items(snrs_db=(None,))
    assert {(i.voice, i.rate) for i in all_items} == {(v, r) for v in ("en-us", "en-us+f3", "en-us+m3", "en-us-nyc")
                                                      for r in (140, 175)}
    quick = items(per_kind=4)
    assert len(quick) == 36 and {i.noise for i in quick} == {"clean", "20 dB", "10 dB"}


def test_summary_counts_plans_only_where_there_are_plans():
    rows = [{"words": 4, "errors": 1, "plan_equal": True, "intent_equal": True, "would_confirm": False,
             "search": "home", "audio_s": 2.0, "decode_s": 0.4},
            {"words": 2, "errors": 0, "plan_equal": None, "intent_equal": False, "would_confirm": True,
             "search": "open", "audio_s": 1.0, "decode_s": 0.2}]
    s = summarise(rows)
    assert s["wer"] == round(1 / 6, 4) and s["plan_equal"] == 1.0 and s["planned"] == 1
    assert s["intent_equal"] == 0.5 and s["open_used"] == 1 and s["real_time_factor"] == 0.2


@pytest.mark.skipif(shutil.which("espeak-ng") is None, reason="espeak-ng is not installed")
def test_quick_evaluation_of_where_questions_gives_rows_and_groups():
    pytest.importorskip("pocketsphinx")
    from assistant.eval.speech import evaluate_speech

    report = evaluate_speech(per_kind=4, kinds=["where"], snrs_db=(None, 10.0), open_fallback=False)
    assert report["utterances"] == 8 and len(report["rows"]) == 8
    assert set(report["groups"]["noise"]) == {"clean", "10 dB"}
    row = report["rows"][0]
    assert row["plan_equal"] in (True, False) and row["decode_s"] > 0 and row["reference"] == "where is my mug"
    json.dumps(report)  # the --json output is plain JSON
    # the voices rotate: en-us (a man's pitch) is not warped, en-us+f3 (a woman's) is
    warps = {r["voice"]: r["warp"] for r in report["rows"]}
    assert report["vtln"] and report["recogniser"]["vtln"] and warps["en-us"] == 1.0 and warps["en-us+f3"] > 1.0
    plain = evaluate_speech(per_kind=2, kinds=["where"], snrs_db=(None,), open_fallback=False, vtln=False)
    assert not plain["vtln"] and {r["warp"] for r in plain["rows"]} == {1.0}


def test_where_questions_are_compared_as_the_dialogue_reads_them():
    from assistant.eval.speech import _Parsers, request_of

    parser = _Parsers()("apartment")
    keys = request_of(parser, "have you seen my keys")
    assert keys == {"intent": "where", "object": ("keys", None)}  # the parser alone finds no object here
    assert request_of(parser, "where are my keys") == request_of(parser, "where is my key") == keys
    assert request_of(parser, "where is my mug") != request_of(parser, "where is my money")
    assert request_of(parser, "where is my wallet")["object"] == ("wallet", None)  # any thing can be asked for
    assert request_of(parser, "how do i get to my mug")["intent"] == "where_dynamic"
    command = request_of(parser, "go into the bedroom and turn left the mug is on the table")
    assert command["intent"] == "command" and command["object"] == "mug" and command["nodes"]
    assert request_of(parser, "where leave my statue")["intent"] == "command"  # not heard as a question


def test_enrolment_is_refused_for_an_engine_without_it():
    from assistant.errors import AssistantError
    from assistant.eval.speech import evaluate_speech

    with pytest.raises(AssistantError, match="vosk has no enrolment"):
        evaluate_speech("vosk", "/nowhere", per_kind=1, enrol=10)

import argparse

import pytest

from assistant.eval.dialogue import check, load_conversations
from assistant.dialogue.manager import Turn
from assistant.dialogue.memory import ObjectMemory
from assistant.errors import DataFileError


def test_corpus_is_large_and_covers_every_intent():
    conversations = load_conversations()
    assert len(conversations) >= 40
    covered = {c for conv in conversations for c in conv.get("covers", [])}
    assert {"fetch", "where", "where_dynamic", "teach", "control", "clarify", "memory", "interrupt",
            "nonsense", "rudeness", "unknown_word"} <= covered


def test_bad_file_names_the_key(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("conversations:\n  - name: x\n    turns:\n      - say: hi\n        expect: {intnt: greet}\n")
    with pytest.raises(DataFileError, match=r"turns\[0\]\.intnt"):
        load_conversations([bad])


def test_check_reports_each_problem():
    turn = Turn("hi", "greet", "Hello!", "answer", "answered")
    memory = ObjectMemory(None)
    assert check(turn, {"intent": "greet", "reply_has": ["hello"]}, memory, "apartment") == []
    problems = check(turn, {"intent": "help", "reply_has": ["bye"], "memory": {"mug": "bedroom"}}, memory, "apartment")
    assert len(problems) == 3
    assert check(None, {}, memory, "apartment")


def test_eval_module_contract():
    from assistant.cli import eval_dialogue

    parser = argparse.ArgumentParser()
    eval_dialogue.add_arguments(parser)
    args = parser.parse_args(["--only", "greet"])
    assert args.perception == "oracle" and callable(eval_dialogue.run)


def test_topics_count_conversations_and_those_as_expected():
    from assistant.eval.dialogue import by_topic

    records = [{"covers": ["where", "fetch"], "ok": True}, {"covers": ["where"], "ok": False},
               {"covers": [], "ok": False}]
    assert by_topic(records) == {"fetch": {"conversations": 1, "as_expected": 1},
                                 "where": {"conversations": 2, "as_expected": 1}}

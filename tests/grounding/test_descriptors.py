"""Size, shape and kind words said with the target furniture are kept on its node."""

from __future__ import annotations

import pytest

from assistant.grounding import CombinedGrounder, CommandParser
from assistant.grounding.vocabulary import said_descriptors


def test_said_descriptors_are_canonical_and_ordered():
    assert said_descriptors("on the little round table".split()) == ("small", "round")
    assert said_descriptors("on the big long dining table".split()) == ("large", "dinner")
    assert said_descriptors("on the table".split()) == ()


@pytest.fixture(scope="module")
def parser(corpus_labels):
    from assistant.language import LanguageModel

    return CommandParser(LanguageModel.load(), CombinedGrounder().fit(corpus_labels.records, corpus_labels.groundings))


@pytest.mark.parametrize("text, descriptors", [
    ("go to the office, the fork is on the round table", ("round",)),
    ("go into the living room, the fork is on the little round table behind the couch", ("small", "round")),
    ("go to the meeting room, the laptop is on the big table", ("large",)),
    ("go into the bedroom, the statue is on the table to the right of the bed", ()),
])
def test_the_target_node_keeps_the_words_said_about_it(parser, text, descriptors):
    plan = parser.parse(text).plan
    node = [n for n in plan.nodes if n.target == "table"][-1]
    assert node.descriptors == descriptors
    assert node.to_dict()["descriptors"] == list(descriptors)

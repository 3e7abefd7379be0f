"""The object words' small grammar: the indefinite article, and which words name a thing."""

import pytest

from assistant.grounding.objects import article, object_phrase


@pytest.mark.parametrize("word, said", [("envelope", "an"), ("mug", "a"), ("unicorn", "a"), ("umbrella", "an"),
                                        ("usb stick", "a"), ("hour", "an"), ("hat", "a"), ("one", "a")])
def test_the_indefinite_article_follows_the_sound(word, said):
    assert article(word) == said


@pytest.mark.parametrize("words, tags, kind", [
    ("where is my hearing aid", "WRB VBZ PRP NN NN", "hearing aid"),
    ("the walking stick is by the door", "DT NN NN VBZ IN DT STR", "walking stick"),
    ("a frying pan on the table", "DT NN NN ON DT FUR", "frying pan"),
    ("where is my knitting", "WRB VBZ PRP NN", "knitting"),
])
def test_a_compound_of_an_ing_word_is_one_thing(words, tags, kind):
    assert object_phrase(words.split(), tags.split()).kind == kind


@pytest.mark.parametrize("words, tags", [
    ("go to the living room", "VB TO DT NN RM"),
    ("turn left after the following door", "VB DIR IN DT NN STR"),
    ("go to the remaining chair", "VB TO DT NN FUR"),
    ("keep going straight to the table", "VB VBG RB TO DT FUR"),
])
def test_an_ing_word_before_a_room_or_a_landmark_is_no_thing(words, tags):
    assert object_phrase(words.split(), tags.split()) is None

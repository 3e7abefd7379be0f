"""Which thing a question names (``clarify.named_object``) and whose it is (``owner_phrase``)."""

import pytest

from assistant.dialogue.clarify import known_spelling, named_object, owner_phrase
from assistant.world import load_world


@pytest.fixture(scope="module")
def lived_in():
    return load_world("training-home")


@pytest.mark.parametrize("asked, thing", [
    ("wheres the clicker for the telly", "remote"),     # had been "telly"
    ("where are the keys to the car", "keys"),          # had been "car"
    ("where is my hearing aid", "hearing aid"),         # had been "aid"
    ("where is my glasses case", "glasses case"),
])
def test_the_thing_asked_about(lived_in, asked, thing):
    assert named_object(asked, lived_in)[0] == thing


def test_a_misspelling_one_letter_too_long_is_the_thing_but_a_plural_is_not():
    assert known_spelling("wallett", ["wallet", "laptop"]) == "wallet"  # had been refused as "longer"
    assert known_spelling("laptops", ["wallet", "laptop"]) is None


@pytest.mark.parametrize("asked, owner", [
    ("where is johns phone", "John's"), ("wheres grandmas glasses", "Grandma's"), ("where is his mug", "his"),
    ("where is my glasses case", None), ("where are my keys", None),
])
def test_whose_thing(asked, owner):
    assert owner_phrase(asked) == owner

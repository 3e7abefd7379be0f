"""Words a person takes back in the same breath are replaced by the correction."""

import pytest

from assistant.language.retractions import without_retractions


@pytest.mark.parametrize("said, meant", [
    ("go into the bedroom, no wait, the living room, the fork is on the small round table",
     "go into the living room, the fork is on the small round table"),
    ("go to the living room no sorry i mean the office, the laptop is on the desk",
     "go to the office, the laptop is on the desk"),
    ("the mug is on the table, no wait, on the desk", "the mug is on the desk"),
    ("turn left, no, turn right", "turn right"),
    ("the mug is in the office, in front of the sofa - wait no, its on the desk. no actually it IS on the coffee "
     "table sorry", "the mug is in the office, on the coffee table"),
    ("head to the kitchen, oops, the living room", "head to the living room"),
    # a side, an end or an order taken back: only that word and what follows it
    ("the keys are in the room on the left i mean right by the lamp", "the keys are in the room on the right by the lamp"),
    ("turn left no sorry right and go through the door", "turn right and go through the door"),
    ("it's on the second shelf, wait no, first", "it's on the first"),
])
def test_the_correction_replaces_what_it_corrects(said, meant):
    assert without_retractions(said) == meant


@pytest.mark.parametrize("said", [
    "the keys are on the coffee table in the living room", "no, the other one", "no wait",
    "there is no table by the couch, no", "go to the kitchen and then to the bedroom",
])
def test_words_that_take_nothing_back_stay(said):
    assert without_retractions(said) == said


def test_a_leading_marker_is_left_to_the_dialogue_when_asked():
    for said in ("no wait, the living room", "sorry, I meant the bedroom", "oh no wait, the couch"):
        assert without_retractions(said, leading=False) == said
    assert without_retractions("no wait, the living room") == "the living room"


def test_i_mean_it_takes_nothing_back():
    assert without_retractions("go to the couch, I mean it") == "go to the couch"

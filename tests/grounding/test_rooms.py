"""Rooms named in so many words override the grounder's guess among the trained room values."""

from __future__ import annotations

import pytest

from assistant.grounding import ChunkGrounding, ChunkRecord, CommandParser, CombinedGrounder, ScoredGrounder
from assistant.grounding.rooms import named_room, named_room_groundings, room_names_of


def test_named_room_finds_the_first_room_said():
    rooms = ["living room", "meeting room", "bedroom", "hallway", "office"]
    assert named_room("go to the office".split(), rooms) == "office"
    assert named_room("Go to the Living Room".split(), rooms) == "living room"
    assert named_room("go into the bed room".split(), rooms) == "bedroom"
    assert named_room("walk past the bedroom door and go into the office".split(), rooms) == "office"
    assert named_room("go into the bedroom past the office".split(), rooms) == "bedroom"
    assert named_room("go to the room on the right".split(), rooms) is None
    # the way is not the goal
    assert named_room("go down the hallway and turn right into the living room".split(), rooms) == "living room"
    assert named_room("walk to the end of the uh hallway".split(), rooms) is None
    assert named_room([], rooms) is None


def test_room_names_longest_first(all_worlds):
    names = room_names_of(all_worlds["two-bedrooms-house"])
    assert names.index("living room") < names.index("bedroom")
    assert room_names_of(None) == []


def test_groundings_take_the_named_room(all_worlds):
    world = all_worlds["two-bedrooms-house"]
    records = [ChunkRecord("ORMTP", ("go", "to", "the", "office"), ("VB", "TO", "DT", "RM")),
               ChunkRecord("ORMTP", ("go", "to", "the", "hallway"), ("VB", "TO", "DT", "RM")),
               ChunkRecord("OBTP", ("the", "bedroom"), ("DT", "RM")),
               ChunkRecord("FURRP", ("next", "to", "the", "bedroom", "door"), ("JJ", "TO", "DT", "RM", "STR")),
               ChunkRecord("IRMRP", ("turn", "toward", "the", "office"), ("VB", "IN", "DT", "RM"))]
    guessed = [ChunkGrounding(room="living room"), ChunkGrounding(), ChunkGrounding(object="mug"),
               ChunkGrounding(reference="door", direction="beside"), ChunkGrounding(reference="move", direction="front")]
    fixed = named_room_groundings(records, guessed, world)
    assert fixed[0].room == "office"  # a wrong guess among trained rooms is replaced
    assert fixed[1].room == "hallway"  # an empty room phrase gets the room it names
    assert fixed[2] == ChunkGrounding(room="bedroom")  # "go to [OBTP the bedroom]": no mug was said
    assert fixed[3] == guessed[3] and fixed[4] == guessed[4]  # landmarks and steps stay
    assert named_room_groundings(records, guessed, None) == guessed


@pytest.fixture(scope="module")
def language():
    from assistant.language import LanguageModel

    return LanguageModel.load()


@pytest.mark.parametrize("grounder", [ScoredGrounder, CombinedGrounder], ids=lambda c: c.__name__)
def test_go_to_each_room_of_every_home(grounder, language, corpus_labels, all_worlds):
    fitted = grounder().fit(corpus_labels.records, corpus_labels.groundings)
    for world in all_worlds.values():
        parser = CommandParser(language, fitted, world)
        for room in world.floorplan.rooms:
            for text in (f"go to the {room.name}", f"Go into the {room.name}, the mug is on the table.",
                         f"the mug is in the {room.name}"):
                assert parser.parse(text).plan.room == room.name, (world.name, text)


def test_a_room_named_only_in_a_place_phrase_is_the_target_room(language, corpus_labels, all_worlds):
    fitted = CombinedGrounder().fit(corpus_labels.records, corpus_labels.groundings)
    parser = CommandParser(language, fitted, all_worlds["hk-studio"])
    plan = parser.parse("The laptop is on the big table in the middle of the meeting room.").plan
    assert plan.room == "meeting room" and plan.object == "laptop"


@pytest.mark.parametrize("text, room", [
    # a side said before the room named: the room named ("turn left" was guessed the bedroom)
    ("go out the door, turn left, then go into the living room and stop at the couch", "living room"),
    ("turn right and go into the bedroom", "bedroom"),
    ("go into the room on your right", "living room"),  # no room named: the side decides
])
def test_a_room_named_anywhere_beats_a_guess(language, corpus_labels, all_worlds, text, room):
    fitted = CombinedGrounder().fit(corpus_labels.records, corpus_labels.groundings)
    parser = CommandParser(language, fitted, all_worlds["apartment"])
    assert parser.parse(text).plan.room == room


def test_the_room_on_a_side_comes_from_the_floor_plan():
    from assistant.grounding.rooms import side_room_groundings
    from assistant.grounding.types import ChunkGrounding, ChunkRecord
    from assistant.world import load_world

    records = [ChunkRecord("ORMTP", ("go", "into", "the", "room", "on", "your", "right"),
                           ("VB", "IN", "DT", "RM", "ON", "PRP", "DIR"))]
    guess = [ChunkGrounding(room="bedroom")]
    # one-bedroom-house: the living room opens on the right of the start, the office on the left
    assert side_room_groundings(records, guess, load_world("one-bedroom-house"))[0].room == "living room"
    assert side_room_groundings(records, guess, load_world("apartment"))[0].room == "living room"
    # said after a move elsewhere ("the end of the hallway"), the words alone cannot tell
    before = [ChunkRecord("ORMTP", ("go", "to", "the", "end", "of", "the", "hall"), ("VB",) * 7)]
    assert side_room_groundings(before + records, [ChunkGrounding()] + guess,
                                load_world("one-bedroom-house"))[1].room == "bedroom"


def test_other_names_of_a_room_name_the_homes_room(all_worlds):
    from assistant.grounding.rooms import named_room, room_aliases, room_names_of, unknown_room_named

    rooms = room_names_of(all_worlds["two-bedrooms-house"])
    assert named_room("go to the sitting room".split(), rooms) == "living room"
    assert named_room("into the lounge please".split(), rooms) == "living room"
    assert named_room("go to the conference room".split(), rooms) == "meeting room"
    assert unknown_room_named("go to the sitting room".split(), all_worlds["two-bedrooms-house"]) is None
    # "hall" is part of the inner hall's name there: no other name of the hallway
    assert "hall" not in room_aliases(rooms)
    assert unknown_room_named("go to the kitchen".split(), all_worlds["two-bedrooms-house"]) == "kitchen"


def test_a_bed_says_its_room_when_no_room_is_named():
    """"the statue is on the round table next to the bed" went to the living room's round table
    with fetch (the chat found the bedroom); a couch says nothing (an office has one)."""
    from assistant.grounding.rooms import furniture_room
    from assistant.grounding.types import RDTNode
    from assistant.world import load_world

    apartment, studio = load_world("apartment"), load_world("hk-studio")
    assert furniture_room([RDTNode("table", (("bed", "beside"),))], apartment) == "bedroom"
    assert furniture_room([RDTNode("bed", ())], apartment) == "bedroom"
    assert furniture_room([RDTNode("table", (("couch", "front"),))], apartment) is None
    assert furniture_room([RDTNode("bed", ())], studio) is None  # no bedroom in the studio flat


def test_a_route_that_names_where_it_ends_goes_there():
    from assistant.grounding.rooms import identified_room
    from assistant.world import load_world

    house = load_world("two-bedrooms-house")
    said = "go through the living room to the inner hall, then the first door on your left, that's the office"
    assert identified_room(said, house) == "office"  # had been the inner hall, the first room said
    assert identified_room("the door on the right, which is the bedroom", house) == "bedroom"
    assert identified_room("go to the inner hall and then the office", house) is None
    assert identified_room("that's the kitchen", house) is None  # no kitchen in this house

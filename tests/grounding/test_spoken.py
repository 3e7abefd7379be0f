"""Open-vocabulary objects, object landmarks and the families of real spoken phrasing."""

from __future__ import annotations

import pytest

from assistant.grounding.labels import label_value
from assistant.grounding.objects import object_kind, object_phrase, plural, singular
from assistant.grounding.spoken import STOP, spoken_groundings
from assistant.grounding.types import ChunkGrounding, ChunkRecord


def rec(label: str, content: str) -> ChunkRecord:
    parts = content.split()
    return ChunkRecord(label, tuple(parts[1::2]), tuple(parts[0::2]))


@pytest.mark.parametrize("content,kind,adjectives", [
    ("DT the NNS keys VBP are", "keys", ()),
    ("DT the NN key VBZ is", "keys", ()),
    ("PRP your NN cell NN phone MD will VB be RB there", "cell phone", ()),
    ("DT the NN phone VBD was", "cell phone", ()),
    ("DT the NNS glasses NN case VBZ is", "glasses case", ()),
    ("DT the NN glass NN case VBZ is", "glasses case", ()),
    ("DT the NN case VBD was", "glasses case", ()),
    ("MD should VB be DT a NN ring IN of NNS keys", "keys", ()),
    ("DT the JJ yellow NN notepad VBZ is", "notepad", ("yellow",)),
    ("DT the NN pho CC and DT the NN cell NN phone VBZ is", "cell phone", ()),
    ("DT the NN wallet VBZ is IN in", "wallet", ()),
    ("DT the NNS tissue NNS boxes VBP are", "tissue box", ()),
    ("PRP you MD will VB find DT the NN laptop", "laptop", ()),
    ("DT the NN coffee NN cup VBZ is", "mug", ()),
])
def test_object_phrase_names_any_object(content, kind, adjectives):
    r = rec("OBTP", content)
    found = object_phrase(r.words, r.pos)
    assert found is not None and found.kind == kind and found.adjectives == adjectives


@pytest.mark.parametrize("content", ["VB look RB down", "PRP you VBP 're ON on DT the NN object",
                                     "PRP it VBZ 's VBR gon VBR na VB be", "VB take CD 2 NNS steps RB forward"])
def test_no_object_in_places_counts_and_pronouns(content):
    r = rec("OBTP", content)
    assert object_phrase(r.words, r.pos) is None


def test_singular_plural():
    assert singular("boxes") == "box" and singular("batteries") == "battery" and singular("glass") == "glass"
    assert plural("key") == "keys" and plural("box") == "boxes" and plural("keys") == "keys"
    assert object_kind("car keys") == "keys" and object_kind("lamps") == "lamp"


def test_annotation_variants_score_alike():
    assert label_value("target object", "glass case") == label_value("target object", "glasses case")
    assert label_value("target object", "key") == "keys"
    assert label_value("reference", "computer") == "laptop"
    assert label_value("reference", "couch") == "couch" and label_value("reference", "stop") == STOP


def ground(label: str, content: str, guess: ChunkGrounding, before=()) -> ChunkGrounding:
    records = [r for r, _ in before] + [rec(label, content)]
    groundings = [g for _, g in before] + [guess]
    return spoken_groundings(records, groundings)[-1]


def test_object_landmarks():
    assert ground("OBRP", "IN with DT the FUR lamp", ChunkGrounding()) == ChunkGrounding(reference="lamp", direction="beside")
    assert ground("OBRP", "RB next TO to DT the NN computer", ChunkGrounding()) == \
        ChunkGrounding(reference="laptop", direction="beside")
    assert ground("OBRP", "TO to DT the DIR left IN of DT the NN lamp", ChunkGrounding()) == \
        ChunkGrounding(reference="lamp", direction="left")
    assert ground("OBRP", "DIR right RB next TO to PRP it", ChunkGrounding(reference="table")) == ChunkGrounding()
    # a furniture reference stays the grounder's
    furniture = ChunkGrounding(reference="bed", direction="beside")
    assert ground("FURRP", "RB next TO to DT the FUR bed", furniture) == furniture


def test_listener_side_is_no_room():
    assert ground("PERS", "ON on PRP your DIR right", ChunkGrounding(room="living room")) == \
        ChunkGrounding(reference="robot", direction="right")


def test_room_phrase_without_room_or_side_after_a_room():
    before = [(rec("ORMRP", "VB turn DIR right"), ChunkGrounding(room="living room"))]
    assert ground("ORMRP", "VB walk RB straight IN into", ChunkGrounding(room="bedroom"), before) == ChunkGrounding()
    # said first, or with a side, it stays
    assert ground("ORMRP", "VB walk RB straight IN into", ChunkGrounding(room="bedroom")).room == "bedroom"
    assert ground("ORMRP", "TO to PRP your DIR left", ChunkGrounding(room="bedroom"), before).room == "bedroom"


def test_motion_families():
    move = ChunkGrounding(reference="move", direction="front")
    assert ground("IRMRP", "NN stop", move) == ChunkGrounding(reference=STOP)
    assert ground("IRMRP", "VB stop RB there", move) == ChunkGrounding(reference=STOP)
    assert ground("IRMRP", "VB go RB forward RB halfway IN into DT the RM room", move) == \
        ChunkGrounding(reference="room", direction="center")
    assert ground("IRMRP", "NN side NN step DIR left DT a NN couple IN of NNS steps", move).direction == "left"
    assert ground("IRMRP", "WRB once PRP you VBP 're IN in DT the RM room VB turn DIR right RB again",
                  move).direction == "right"
    far = ground("IRMRP", "VB walk DT all DT the NN way TO to DT the JJ other NN side IN of DT the RM room",
                 ChunkGrounding(reference="room", direction="front"))
    assert far == ChunkGrounding(reference="room", direction="back")
    assert ground("FURRP", "NN pass DT the FUR couch", ChunkGrounding(reference="couch", direction="beside")) == \
        ChunkGrounding(reference="couch", direction="back")
    # "pass the sofa" chunked as a room phrase that names no room: still passing it
    assert ground("ORMTP", "VB pass DT the FUR sofa", ChunkGrounding()) == \
        ChunkGrounding(reference="couch", direction="back")
    # a room named on the way stays the room ("go past the big table into the living room")
    into = ChunkGrounding(room="living room")
    assert ground("ORMTP", "VB go JJ past DT the FUR table IN into DT the NN living RM room", into) == into


def test_right_next_to_is_beside():
    assert ground("OBRP", "RB right RB next TO to DT the JJ yellow NN book", ChunkGrounding()) == \
        ChunkGrounding(reference="book", direction="beside")


def test_amounts_of_steps_and_turns():
    from assistant.grounding.amounts import STEP_M, said_amount

    assert said_amount("take 2 steps forward".split()).distance_m == pytest.approx(2 * STEP_M)
    assert said_amount("about 4 er 5 steps forward".split()).distance_m == pytest.approx(4.5 * STEP_M)
    assert said_amount("side step left a couple of steps".split()).distance_m == pytest.approx(2 * STEP_M)
    assert said_amount("take a step forward".split()).distance_m == pytest.approx(STEP_M)
    assert said_amount("turn left 90 degrees".split()).degrees == 90
    assert said_amount("walk in about a 45 degree angle".split()).degrees == 45
    assert said_amount("make another ninety degree turn".split()).degrees == 90
    assert not said_amount("step forward to the desk".split())


def test_loose_moves_outside_chunks():
    from assistant.grounding.loose import loose_moves

    assert [m for m, _ in loose_moves("um go forward and".split())] == [("move", "front")]
    assert [m for m, _ in loose_moves("ok left left".split())] == [("move", "left"), ("move", "left")]
    assert [m for m, _ in loose_moves("go straight go ahead and".split())] == [("move", "front")]
    assert [m for m, _ in loose_moves("stop".split())] == [("stop", "center")]
    assert loose_moves("and it is right there on the left".split()) == []

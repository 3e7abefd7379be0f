"""What the words say beats a grounder's guess (``grounding.said``)."""

from assistant.grounding.said import said_reference_groundings
from assistant.grounding.types import ChunkGrounding, ChunkRecord


def _record(words, pos):
    return ChunkRecord("OBRP", tuple(words), tuple(pos))


def test_a_thing_reference_nobody_named_becomes_the_furniture_said():
    # "the table near the bed" grounded as keys-beside-table: "near the …" in an object chunk
    # mostly comes with a thing in the corpus
    near_bed = _record(["near", "the", "bed"], ["IN", "DT", "FUR"])
    guess = ChunkGrounding(reference="keys", direction="beside")
    assert said_reference_groundings([near_bed], [guess])[0].reference == "bed"
    # a thing that is said stays; so does a guess where no furniture is said
    by_keys = _record(["near", "the", "keys", "by", "the", "bed"], ["IN", "DT", "NNS", "IN", "DT", "FUR"])
    assert said_reference_groundings([by_keys], [guess])[0].reference == "keys"
    nothing = _record(["over", "there"], ["IN", "RB"])
    assert said_reference_groundings([nothing], [guess])[0].reference == "keys"


def test_an_unnamed_furniture_reference_of_a_listener_chunk_is_the_robot():
    ahead = _record(["just", "ahead", "of", "you"], ["RB", "RB", "IN", "PRP"])
    assert said_reference_groundings([ahead], [ChunkGrounding(reference="couch", direction="front")])[0].reference \
        == "robot"

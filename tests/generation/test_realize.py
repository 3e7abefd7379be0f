"""Surface realization: chunk choice, Algorithm 1, in-order traversal and the guards."""

from __future__ import annotations

from assistant.generation.realize import acceptable, build_tree, realize, repeated_phrases
from assistant.generation.types import ChunkNode, ContentNode


def _t(text, tags):
    return tuple(zip(text.split(), tags.split()))


def test_repeated_phrases_are_found():
    assert repeated_phrases("the mug is on the table against the left wall against the left wall")
    assert repeated_phrases("on the table in front of the couch in front of the chair")
    assert not repeated_phrases("the mug is on the table in front of the couch in the living room")


def test_guards_reject_motion_fillers_and_unsafe_words_in_static_chunks():
    assert not acceptable("IRMRP", _t("about halfway in", "IN NN IN"), "room-center", "static")
    assert not acceptable("IRMRP", _t("move halfway in", "VB NN IN"), "room-center", "static")
    assert not acceptable("FURRP", _t("by the um {ref}", "IN DT IGN FUR"), "furniture-beside", "static")
    assert not acceptable("FURTP", _t("on the small {support}", "ON DT JJ FUR"), "support", "static")
    assert not acceptable("IRMRP", _t("on your left", "ON PRP DIR"), "robot-left", "static")
    assert not acceptable("IRMRP", _t("against the the left wall", "IN DT DT DIR STR"), "wall-left", "static")
    assert acceptable("FURRP", _t("in front of the {ref}", "IN DIR IN DT FUR"), "furniture-front", "static")
    assert acceptable("OBTP", _t("the {object} is", "DT NN VBZ"), "object", "static")
    assert not acceptable("OBTP", _t("the {object} might be", "DT NN MD VB"), "object", "static")
    assert acceptable("IRMRP", _t("turn right", "VB DIR"), "move-right", "dynamic")
    assert not acceptable("IRMRP", _t("go straight to", "VB RB TO"), "move-front", "dynamic")


class FixedRelations:
    """Stand-in model: FURRP is CR of FURTP, FURTP CR of OBTP, ORMTP NR of FURTP."""

    table = {("FURRP", "FURTP"): ("CR", 0.9), ("FURTP", "OBTP"): ("CR", 0.8),
             ("ORMTP", "FURTP"): ("NR", 0.6)}

    def relation(self, a, b, style="static"):
        if (a, b) in self.table:
            return self.table[(a, b)]
        if (b, a) in self.table:
            v, p = self.table[(b, a)]
            return {"CR": "PR", "CL": "PL", "NR": "NL", "NL": "NR", "PR": "CR", "PL": "CL"}[v], p
        return None, 0.0

    def relation_probability(self, a, b, v, style="static"):
        got = self.relation(a, b, style)
        return got[1] if got[0] == v else 0.0


def test_algorithm_1_builds_the_tree_from_the_object_chunk():
    root = ChunkNode("OBTP", ["the", "mug", "is"])
    room = ChunkNode("ORMTP", ["in", "the", "living", "room"])
    ref = ChunkNode("FURRP", ["in", "front", "of", "the", "couch"])
    sup = ChunkNode("FURTP", ["on", "the", "table"])
    top = build_tree(FixedRelations(), root, [room, ref, sup], "static")
    assert top == [root]
    assert " ".join(root.in_order()) == \
        "the mug is on the table in front of the couch in the living room"


def test_realize_with_the_corpus_model(generation_model):
    nodes = [ContentNode("support", "support", "room-center-table", 1.0, {"support": "table"}),
             ContentNode("relation", "furniture-front", "couch-front-table", 0.8,
                         {"ref": "couch", "direction": "front"}),
             ContentNode("room", "room", None, 1.0, {"room": "living room"})]
    text, top, said = realize(generation_model, nodes, "glasses case")
    assert text.startswith("The glasses case is")
    for phrase in ("on the table", "in front of the couch", "in the living room"):
        assert phrase in text
    assert text.endswith(".") and not repeated_phrases(text)
    assert len(said) == 3

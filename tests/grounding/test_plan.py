"""Assembling plans from chunk trees: nodes, pairs, implied targets, kinds, flags."""

from __future__ import annotations

import pytest

from assistant.grounding import RDT, ChunkGrounding, GroundingPlan, RDTNode, assemble_plan
from assistant.grounding.plan import count_furniture, finish_flags, unused_words
from assistant.language.tree import Chunk, ChunkTree, Token


def chunk(label: str, *items) -> Chunk:
    out = []
    for item in items:
        if isinstance(item, str):
            out.extend(Token(w, p) for w, p in (pair.rsplit("/", 1) for pair in item.split()))
        else:
            out.append(item)
    return Chunk(label, out)


G = ChunkGrounding


def test_furtp_with_nested_references_is_one_node_with_pairs_in_order():
    # "the fork is on the table to the right side behind the couch"
    tree = ChunkTree([chunk("OBTP", "the/DT fork/NN is/VBZ",
                            chunk("FURTP", "on/ON the/DT table/FUR",
                                  chunk("IRMRP", "to/TO the/DT right/DIR side/NN"),
                                  chunk("FURRP", "behind/IN the/DT couch/FUR")))])
    plan = assemble_plan(tree, [G(object="fork"), G(target="table"), G(reference="robot", direction="right"),
                                G(reference="couch", direction="back")])
    assert plan.object == "fork"
    assert [n.pairs for n in plan.nodes] == [(("robot", "right"), ("couch", "back"))]
    assert plan.node_strings == ["robot-right-table"]
    assert [str(r) for r in plan.nodes[0].rdts] == ["robot-right-table", "couch-back-table"]
    assert plan.kind == "static" and plan.support == "table"


def test_target_without_reference_still_yields_the_target():
    tree = ChunkTree([chunk("OBTP", "the/DT mug/NN is/VBZ", chunk("FURTP", "on/ON the/DT table/FUR"))])
    plan = assemble_plan(tree, [G(object="mug"), G(target="table")])
    assert [n.target for n in plan.nodes] == ["table"] and not plan.nodes[0].referenced
    assert "unreferenced_target:table" in plan.flags


def test_dynamic_phrases_give_move_nodes_in_order():
    tree = ChunkTree([chunk("ORMTP", "go/VB to/TO the/DT bedroom/RM"), Token("and", "CC"),
                      chunk("IRMRP", "move/VB about/IN halfway/NN in/IN"),
                      chunk("IRMRP", "turn/VB left/DIR"),
                      chunk("OBTP", "you/PRP will/MD find/VB the/DT mug/NN")])
    plan = assemble_plan(tree, [G(room="bedroom"), G(reference="room", direction="center"),
                                G(reference="move", direction="left"), G(object="mug")])
    assert plan.room == "bedroom" and plan.object == "mug"
    assert plan.node_strings == ["room-center-non", "move-left-non"]
    assert plan.kind == "dynamic" and plan.support is None


def test_mixed_plan_and_the_word_said_is_the_support():
    tree = ChunkTree([chunk("IRMRP", "turn/VB left/DIR"),
                      chunk("OBTP", "the/DT statue/NN is/VBZ",
                            chunk("FURTP", "on/ON the/DT nightstand/FUR",
                                  chunk("FURRP", "to/TO the/DT left/DIR of/IN the/DT bed/FUR")))])
    plan = assemble_plan(tree, [G(reference="move", direction="left"), G(object="statue"), G(target="table"),
                                G(reference="bed", direction="left")])
    assert plan.node_strings == ["move-left-non", "bed-left-table"]
    assert plan.kind == "mixed" and plan.support == "nightstand"


def test_reference_without_a_target_implies_a_table():
    # "the fork will be on the right"
    tree = ChunkTree([chunk("OBTP", "the/DT fork/NN will/MD be/VB", chunk("IRMRP", "on/ON the/DT right/DIR"))])
    plan = assemble_plan(tree, [G(object="fork"), G(reference="robot", direction="right")])
    assert plan.node_strings == ["robot-right-table"]
    assert plan.nodes[0].implied_target and "implied_target:table" in plan.flags
    assert plan.support is None


def test_move_step_inside_a_target_chunk_comes_first():
    # "walk straight until you are at the table at the back"
    tree = ChunkTree([chunk("FURTP", chunk("IRMRP", "walk/VB straight/RB until/IN you/PRP are/VBP at/IN"),
                            "the/DT table/FUR", chunk("IRMRP", "at/IN the/DT back/NN"))])
    plan = assemble_plan(tree, [G(target="table"), G(reference="move", direction="front"),
                                G(reference="room", direction="back")])
    assert plan.node_strings == ["move-front-non", "room-back-table"]


def test_missing_direction_gets_a_default_and_a_flag():
    tree = ChunkTree([chunk("IRMRP", "go/VB forward/RB to/TO")])
    plan = assemble_plan(tree, [G(reference="move")])
    assert plan.node_strings == ["move-front-non"] and "missing_direction:move" in plan.flags


def test_grounding_count_must_match_the_tree():
    tree = ChunkTree([chunk("IRMRP", "turn/VB left/DIR")])
    with pytest.raises(ValueError, match="1 chunks but 0 groundings"):
        assemble_plan(tree, [])


def test_flags_for_empty_and_not_understood_and_missing_parts():
    empty = finish_flags(GroundingPlan(), words=0)
    assert empty.flags == ["empty"]
    nothing = finish_flags(GroundingPlan(), words=3)
    assert nothing.flags[:3] == ["not_understood", "no_object", "no_room"]


def test_ambiguous_target_needs_a_world_with_several_tables(apartment):
    assert count_furniture(apartment, "table", "living room") == 3
    assert count_furniture(apartment, "couch", "living room") == 1
    plan = GroundingPlan(room="living room", nodes=[RDTNode("table")], object="mug")
    assert "ambiguous_target:table:3" in finish_flags(plan, words=6, world=apartment).flags
    referenced = GroundingPlan(room="living room", nodes=[RDTNode("table", (("couch", "front"),))], object="mug")
    assert not any(f.startswith("ambiguous") for f in finish_flags(referenced, words=9, world=apartment).flags)


def test_unused_words_are_unknown_or_outside_chunks_not_fillers():
    tree = ChunkTree([Token("um", "UH"), Token("please", "UH"), Token("zorp", "NN"),
                      chunk("IRMRP", "turn/VB left/DIR blorp/NN")])
    assert unused_words(tree, {"turn", "left"}, unknown=["blorp"]) == ["zorp", "blorp"]


def test_rdt_string_form_round_trips():
    for text in ("couch-front-table", "move-left-non", "room-center-non", "wall-front-non",
                 "robot-right-table", "chair-beside-table"):
        assert str(RDT.parse(text)) == text
    assert RDT.parse("move-left-non").dynamic and not RDT.parse("couch-front-table").dynamic
    with pytest.raises(ValueError, match="reference-direction-target"):
        RDT.parse("couch-front")
    node = RDTNode("table", (("robot", "right"), ("couch", "back")))
    assert node.to_dict()["alternatives"] == ["robot-right-table", "couch-back-table"]


def test_a_reference_said_right_after_the_target_is_a_pair_of_its_node():
    # "the fork is [on the little table] [next to the keys]": one node, the table's, with the pair
    tree = ChunkTree([chunk("OBTP", "the/DT fork/NN is/VBZ", chunk("FURTP", "on/ON the/DT little/JJ table/FUR"),
                            chunk("OBRP", "next/JJ to/TO the/DT keys/NNS"))])
    plan = assemble_plan(tree, [G(object="fork"), G(target="table"), G(reference="keys", direction="beside")])
    assert [n.pairs for n in plan.nodes] == [(("keys", "beside"),)]
    assert not plan.nodes[0].implied_target and plan.nodes[0].descriptors == ("small",)
    assert not any(f.startswith(("implied_target", "unreferenced_target")) for f in plan.flags)
    # with a chunk between them the reference is a node of its own, its table implied
    tree = ChunkTree([chunk("FURTP", "go/VB to/TO the/DT table/FUR"), chunk("OBTP", "the/DT fork/NN is/VBZ"),
                      chunk("OBRP", "next/JJ to/TO the/DT keys/NNS")])
    plan = assemble_plan(tree, [G(target="table"), G(object="fork"), G(reference="keys", direction="beside")])
    assert len(plan.nodes) == 2 and plan.nodes[1].implied_target

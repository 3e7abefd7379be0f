"""The describer end to end on the study homes (oracle search and environment)."""

from __future__ import annotations

import dataclasses

import pytest

from assistant.errors import AssistantError
from assistant.generation import (not_found_description, oracle_environment, oracle_sighting,
                                  repeated_phrases, style_for_question)
from assistant.geometry import Pose2D


def _describe(describer, world, name, scene="original", **kw):
    env = oracle_environment(world, scene)
    return describer.describe(oracle_sighting(world, scene, name), env, world.floorplan, **kw)


def test_static_description_of_the_glasses_case(describer, apartment):
    r = _describe(describer, apartment, "glasses case")
    assert r.found and r.description.startswith("The glasses case is")
    assert "in the living room" in r.description and "on the table" in r.description
    assert not repeated_phrases(r.description)
    assert r.nodes and all(n.endswith("-table") for n in r.nodes)
    assert r.tree.label == "OBTP"
    assert 0 < r.composition_seconds < 5
    d = r.to_dict()
    for field in ("found", "description", "nodes", "seen_at", "selected", "tree"):
        assert field in d


def test_the_room_is_not_said_to_a_listener_in_it(describer, apartment):
    inside = Pose2D(3.0, 5.0, 0.0)      # living room
    r = _describe(describer, apartment, "glasses case", listener_pose=inside)
    assert "living room" not in r.description
    assert all(n.kind != "room" for n in r.selected)
    elsewhere = Pose2D(0.0, -4.0, 0.0)  # bedroom
    r = _describe(describer, apartment, "glasses case", listener_pose=elsewhere)
    assert "in the living room" in r.description


def test_several_tables_in_the_room_are_told_apart(describer, apartment):
    # the living room has four tables: the fork's is the one behind the couch
    r = _describe(describer, apartment, "fork")
    assert not r.ambiguous
    assert any(n.kind == "relation" for n in r.selected)


def test_how_to_find_description_from_the_start(describer, apartment):
    r = _describe(describer, apartment, "glasses case", listener_pose=apartment.start, style="dynamic")
    assert r.description.startswith("Go into the living room, turn right, ")
    assert "glasses case is on the table" in r.description
    assert "in the living room" not in r.description      # the route already says it
    with pytest.raises(AssistantError):
        _describe(describer, apartment, "glasses case", style="dynamic")


def test_question_picks_the_style():
    assert style_for_question("How do I get to my mug?") == "dynamic"
    assert style_for_question("where is my mug") == "static"


def test_unknown_and_missing_objects(apartment):
    # any thing may be asked about (issue 16): a thing the scene does not hold is not there
    assert oracle_sighting(apartment, "original", "stapler") is None
    scene = apartment.scene("original")
    bare = dataclasses.replace(scene, objects=tuple(o for o in scene.objects if o.name != "mug"))
    world = dataclasses.replace(apartment, scenes={**apartment.scenes, "original": bare})
    assert oracle_sighting(world, "original", "mug") is None
    text = not_found_description("mug", ["living room", "bedroom"]).description
    assert text == "I looked in the living room and the bedroom and did not find a mug."
    # plurals and mass nouns read as English
    assert not_found_description("keys", ["bedroom"]).description == "I looked in the bedroom and did not find any keys."
    assert not_found_description("mail", []).description.endswith("did not find any mail.")
    assert not_found_description("envelope", []).description.endswith("an envelope.")


def test_all_48_study_descriptions_are_true_and_unrepeated(generation_model):
    from assistant.eval.generation import evaluate

    report = evaluate(corpus_paths=None, parse=False)
    rows = report["rows"]
    assert len(rows) == 48
    assert [r for r in rows if not r["true"]] == []
    assert [r for r in rows if r["repeated"]] == []
    # the ≤ 16-word target is measured on the robot's own search (`assistant eval generation`,
    # docs/generation.md); on the world file's furniture, composed for a listener at the start
    # pose, the median is 16.5 (two-relation wordings where a look-alike stands by)
    assert report["summary"]["median_words"] <= 17

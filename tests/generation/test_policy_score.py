"""P_Γ(y) from the learned policy models: the reference↔target part of an RDT's model."""

from __future__ import annotations

import pytest

from assistant.generation.policy_score import RELATION_SRVS, PolicyRelationScore
from assistant.spatial import dir_srv, dist_srv


@pytest.fixture(scope="module")
def scorer():
    return PolicyRelationScore()


def _pair(world, ref_id, tar_id):
    from assistant.world import furniture_entities, world_grid

    items = {e.id: e for e in furniture_entities(world, "original", world_grid(world, 0.05))}
    ref, tar = items[ref_id], items[tar_id]
    return {"dir:ref->tar": dir_srv(ref, tar), "dist:ref->tar": dist_srv(ref, tar),
            "dist:tar->ref": dist_srv(tar, ref)}


def test_a_true_relation_scores_near_the_demonstrations_and_a_false_one_low(scorer, apartment):
    # the apartment's coffee table stands in front of the couch; the round table behind it
    front = _pair(apartment, "couch_1", "coffeetable_1")
    behind = _pair(apartment, "couch_1", "roundtable_1")
    assert scorer.score("couch-front-table", front) > 0.8
    assert scorer.score("couch-front-table", behind) < 0.3
    assert scorer.used["couch-front-table"] == "couch-front-table"


def test_an_rdt_without_a_model_of_its_own_takes_the_nearest(scorer, apartment):
    # no "chair-front-table" demonstrations: the couch's front model scores it
    srvs = _pair(apartment, "bluechair_1", "dinnertable_1")
    assert 0.0 < scorer.score("chair-front-table", srvs) <= 1.0
    assert scorer.used["chair-front-table"] == "couch-front-table"


def test_no_relation_srvs_no_score(scorer):
    assert scorer.score("couch-front-table", {name: None for name in RELATION_SRVS}) is None


def test_the_describer_can_weigh_relations_by_the_policy_models(apartment):
    from assistant.generation import Describer, oracle_environment, oracle_sighting

    sighting = oracle_sighting(apartment, "original", "glasses case")
    env = oracle_environment(apartment, "original")
    plain = Describer().describe(sighting, env, apartment.floorplan)
    weighed = Describer(policies="default").describe(sighting, env, apartment.floorplan)
    p = {n.rdt: n.probability for n in plain.candidates if n.kind == "relation"}
    q = {n.rdt: n.probability for n in weighed.candidates if n.kind == "relation"}
    assert set(p) == set(q) and "couch-front-table" in p
    assert q != p  # the learned models moved the probabilities
    assert all(0.0 <= v <= 1.0 for v in q.values())

"""Content selection: equation (2) and its exact maximisation under the constraints."""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from assistant.generation.content import Candidate, objective_values, select_content
from assistant.generation.types import ContentNode


class FlatModel:
    """Stand-in: every pair of different keys co-occurs with weight ``v``."""

    def __init__(self, v):
        self.v = v

    def cooccurrence(self, a, b):
        return self.v


def _direct(w, p, v, alpha):
    w = np.asarray(w, float)
    k = len(p)
    first = (w @ p) / w.sum()
    second = sum(v[i, j] * w[i] * w[j] * p[i] * p[j] for i, j in itertools.combinations(range(k), 2))
    return first + second - alpha * w.sum() / k


def test_objective_matches_equation_2():
    rng = np.random.default_rng(0)
    p = rng.uniform(0.2, 1.0, 5)
    v = rng.uniform(0, 1, (5, 5))
    v = (v + v.T) / 2
    masks = np.array([[1, 0, 1, 1, 0], [1, 1, 1, 1, 1], [0, 0, 0, 1, 0]])
    got = objective_values(masks, p, v, 0.1)
    want = [_direct(m, p, v, 0.1) for m in masks]
    assert got == pytest.approx(want)


def _cand(key, p, group, forced=False, holds=lambda x: True):
    return Candidate(ContentNode("relation" if not forced else "support", key, key, p), holds,
                     group, forced)


def test_selection_is_the_exact_maximum_over_subsets():
    cands = [_cand("support", 1.0, "s", forced=True)] + \
        [_cand(f"k{i}", p, f"g{i}") for i, p in enumerate([0.9, 0.3, 0.7, 0.55])]
    model = FlatModel(0.05)
    chosen, value, ambiguous = select_content(cands, model, [])
    p = np.array([c.node.probability for c in cands])
    v = np.full((5, 5), 0.05)
    best = max((_direct((1,) + rest, p, v, 0.1), rest) for rest in itertools.product((0, 1), repeat=4))
    assert value == pytest.approx(best[0])
    assert [c.node.key for c, bit in zip(cands[1:], best[1]) if bit] == \
        [n.key for n in chosen if n.key != "support"]
    assert not ambiguous


def test_one_node_per_group_and_the_support_always_said():
    cands = [_cand("support", 1.0, "s", forced=True), _cand("a", 0.9, "couch"),
             _cand("b", 0.9, "couch")]
    chosen, _, _ = select_content(cands, FlatModel(0.5), [])
    keys = [n.key for n in chosen]
    assert "support" in keys and not {"a", "b"} <= set(keys)


def test_the_selection_singles_the_support_out():
    # "b" is likelier, but only "a" is false for the other table
    cands = [_cand("support", 1.0, "s", forced=True),
             _cand("a", 0.5, "ga", holds=lambda x: False),
             _cand("b", 0.95, "gb", holds=lambda x: True)]
    chosen, _, ambiguous = select_content(cands, FlatModel(0.0), ["other table"])
    assert "a" in [n.key for n in chosen] and not ambiguous
    # nothing rules the other table out: flagged, best effort kept
    cands = [_cand("support", 1.0, "s", forced=True), _cand("b", 0.95, "gb")]
    _, _, ambiguous = select_content(cands, FlatModel(0.0), ["other table"])
    assert ambiguous


def test_a_size_word_tells_a_small_table_from_desks(describer):
    from assistant.generation import oracle_environment, oracle_sighting
    from assistant.world import load_world

    world = load_world("hk-studio")
    env = oracle_environment(world, "modified")
    answer = describer.describe(oracle_sighting(world, "modified", "monitor"), env, world.floorplan)
    assert "on the end table" in answer.description
    assert any(n.kind == "size" for n in answer.selected)
    # no table of the other size in the room: no size word
    world = load_world("apartment")
    answer = describer.describe(oracle_sighting(world, "original", "mug"),
                                oracle_environment(world, "original"), world.floorplan)
    assert "end table" not in answer.description


def test_the_uniqueness_term_prefers_selections_that_rule_out_look_alikes(generation_model):
    import numpy as np

    from assistant.generation.content import Candidate, select_content
    from assistant.generation.types import ContentNode

    class Thing:
        def __init__(self, name):
            self.name = name

    a, b = Thing("table"), Thing("table")
    cands = [
        Candidate(ContentNode("support", "support", "room-center-table", 1.0, {"support": "table"}),
                  lambda x: True, "support", forced=True),
        # very probable, but true of both look-alikes
        Candidate(ContentNode("relation", "furniture-beside", "bed-beside-table", 0.9,
                              {"ref": "bed", "direction": "beside"}), lambda x: True, "ref:bed"),
        # less probable, rules out one of them
        Candidate(ContentNode("relation", "wall-left", "wall-left-table", 0.5, {"direction": "left"}),
                  lambda x: x is b, "wall"),
    ]
    chosen, _, ambiguous = select_content(cands, generation_model, [a, b])
    assert ambiguous  # nothing rules out b
    assert any(n.key == "wall-left" for n in chosen)
    assert np.isfinite(_)


def test_an_open_plan_room_is_entered_the_way_the_listener_walks_in(all_worlds):
    import math

    from assistant.generation.entry import entry_heading

    world = all_worlds["two-bedrooms-house"]
    # from the start (the hallway, north) the way into the living room is through the meeting
    # room: walking south, so its back wall is the south one
    assert entry_heading(world.floorplan, "living room", world.start) == pytest.approx(-math.pi / 2)
    # with nobody placed, the room's own door (from the inner hall, east) is the way in
    assert entry_heading(world.floorplan, "living room") == pytest.approx(math.pi)

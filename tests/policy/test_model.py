"""The policy model (equations 5-12 … 5-16) and the move-to search (5.5.4)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from assistant.geometry import Pose2D
from assistant.policy.demonstration import environment_from_world, load_demonstrations
from assistant.policy.freespace import FreeSpace
from assistant.policy.model import NotFittedError, PolicyModel, rotation_memberships, srv_vectors
from assistant.policy.teacher import teacher_goal

CORPUS = Path(__file__).resolve().parents[2] / "corpus" / "demonstrations"


@pytest.fixture(scope="module")
def couch_demos():
    return load_demonstrations(CORPUS, "couch-front-table")


@pytest.fixture(scope="module")
def modified():
    from assistant.world import load_world

    env = environment_from_world(load_world("training-home"), "modified")
    return env, FreeSpace(env)


def test_weights_follow_equations_5_12_and_5_13(couch_demos):
    model = PolicyModel("couch-front-table", unrelated_threshold=1.1).fit(couch_demos)
    expected = {}
    for demo in couch_demos:
        _, last = model.demonstration_features(demo)
        for name, phi in srv_vectors(last).items():
            expected[name] = np.maximum(expected.get(name, 0), phi)
    assert set(model.weights_) == set(expected)
    for name, v in expected.items():
        np.testing.assert_allclose(model.weights_[name], v / v.max())
        assert model.weights_[name].max() == pytest.approx(1.0)


def test_unrelated_srvs_are_removed(couch_demos):
    keep_all = PolicyModel("couch-front-table", unrelated_threshold=1.1).fit(couch_demos)
    model = PolicyModel("couch-front-table").fit(couch_demos)
    assert model.removed_ and set(model.removed_).isdisjoint(model.weights_)
    for name in model.removed_:
        v = keep_all.weights_[name]
        assert v[v > 1e-9].mean() > 0.8
    literal = PolicyModel("couch-front-table", unrelated_over="all").fit(couch_demos)
    for name, u in literal.unrelated_.items():
        assert u == pytest.approx(keep_all.weights_[name].mean())
    nothing = PolicyModel("couch-front-table", unrelated_threshold=-1).fit(couch_demos)
    assert not nothing.weights_ and nothing.score(model.demonstration_features(couch_demos[0])[1]) == 1.0


def test_scores_separate_goal_from_start(couch_demos):
    model = PolicyModel("couch-front-table").fit(couch_demos)
    assert model.separation_ == 1.0
    first, last = model.demonstration_features(couch_demos[0])
    assert 0.0 <= model.score(first) < model.score(last) <= 1.0
    assert model.score(last) == pytest.approx(np.prod(list(model.score_parts(last).values())))


def test_estimator_conventions(couch_demos):
    model = PolicyModel("couch-front-table")
    with pytest.raises(NotFittedError, match="fit"):
        model.score(None)
    assert model.fit(couch_demos) is model
    assert model.set_params(min_step_m=0.2).get_params()["min_step_m"] == 0.2
    with pytest.raises(ValueError, match="unknown parameter"):
        model.set_params(bogus=1)
    other = load_demonstrations(CORPUS, "move-left-non")
    with pytest.raises(ValueError, match="move-left-non"):
        PolicyModel("couch-front-table").fit(couch_demos + other)


def test_rotation_memberships():
    np.testing.assert_allclose(rotation_memberships(0.0), [1, 0, 0, 0], atol=1e-12)
    np.testing.assert_allclose(rotation_memberships(math.pi / 2), [0, 1, 0, 0], atol=1e-12)
    np.testing.assert_allclose(rotation_memberships(-math.pi / 4), [0.5, 0, 0, 0.5], atol=1e-12)
    assert rotation_memberships(2.0).sum() == pytest.approx(1.0)


def test_move_to_in_a_changed_layout(couch_demos, modified):
    env, free = modified
    model = PolicyModel("couch-front-table").fit(couch_demos)
    start = Pose2D(8.5, 2.0, math.pi)
    goal = teacher_goal("couch-front-table", env, start, free)
    result = model.infer_move_to(env, start, goal.reference_id, goal.target_id, free=free)
    assert math.hypot(result.pose.x - goal.goal.x, result.pose.y - goal.goal.y) < 0.6
    assert len(result.poses) == len(result.scores) > 50
    assert result.score == pytest.approx(result.scores.max())
    assert (free.clearance(result.poses[:, :2]) >= 0.25).all()  # no colliding candidate
    reachable = PolicyModel("couch-front-table", reachable_only=True).fit(couch_demos).infer_move_to(
        env, start, goal.reference_id, goal.target_id, free=free)
    reach = free.reachable_from(start.x, start.y, 0.25)
    cells = free.grid.world_to_cell(reachable.poses[:, :2])
    assert reach[cells[:, 0], cells[:, 1]].all()  # none in a pocket the robot cannot reach
    assert result.rounds >= 3  # 1 m → 0.5 → 0.25 → 0.125
    literal = model.set_params(stop_rule="score-falls").infer_move_to(env, start, goal.reference_id,
                                                                       goal.target_id, free=free)
    assert len(literal.scores) <= len(result.scores)
    d = result.to_dict()
    assert d["candidates"][0][:3] == [round(float(v), 3 if i < 2 else 4) for i, v in enumerate(result.poses[0])]


def test_move_forward(modified):
    env, free = modified
    model = PolicyModel("move-front-non").fit(load_demonstrations(CORPUS, "move-front-non"))
    start = Pose2D(2.0, 2.6, 0.0)
    result = model.infer_move_to(env, start, free=free)
    assert math.hypot(result.pose.x - 3.0, result.pose.y - 2.6) < 0.3
    assert abs(result.pose.theta) < 0.3

"""Where the fetch looks again from: how much of a room its look-arounds have covered."""

from __future__ import annotations

import math
from types import SimpleNamespace

from assistant.executor.survey import Surveyor
from assistant.geometry import Pose2D


def _surveyor(world, looked_from) -> Surveyor:
    # the coverage reads only the floor plan (ctx.world) and the poses looked around from
    return Surveyor(SimpleNamespace(world=world), on_frame=None, looked_from=list(looked_from))


def test_a_large_room_seen_from_its_door_is_surveyed(all_worlds):
    studio = _surveyor(all_worlds["hk-studio"], [Pose2D(-2.1, 0.3, math.pi / 2)])
    points = studio.room_points("studio")
    assert len(points) > 100
    assert studio.unseen(points, studio.survey_range_m).mean() > studio.max_unseen_share  # most of it is far
    bedroom = _surveyor(all_worlds["one-bedroom-house"], [Pose2D(3.1, 5.7, math.pi / 2)])
    assert bedroom.unseen(bedroom.room_points("bedroom"), bedroom.survey_range_m).mean() <= bedroom.max_unseen_share


def test_looking_from_more_places_leaves_less_unseen(all_worlds):
    door = Pose2D(-2.1, 0.3, math.pi / 2)
    one = _surveyor(all_worlds["hk-studio"], [door])
    points = one.room_points("studio")
    two = _surveyor(all_worlds["hk-studio"], [door, Pose2D(-6.0, 4.0, 0.0)])
    assert two.unseen(points, 4.5).sum() < one.unseen(points, 4.5).sum()
    assert _surveyor(all_worlds["hk-studio"], []).unseen(points, 4.5).all()
    assert one.room_points("no such room").shape == (0, 2)

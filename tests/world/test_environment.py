import math

import numpy as np
import pytest

from assistant.geometry import Pose2D, rectangle
from assistant.world.entity import Entity, EntityKind
from assistant.world.environment import EnvironmentModel


def seen(model, x, y, length, width, category, facing=None, confidence=0.9):
    poly = rectangle(Pose2D(x, y, 0.0), length, width)
    return Entity.from_polygon("d", category, EntityKind.SHORT_TERM, poly, model.grid, facing,
                               category=category, confidence=confidence)


def test_detections_fuse_into_entities_with_the_floor_plan(apartment):
    model = EnvironmentModel(apartment)
    model.update([seen(model, 4.5, 3.0, 2.0, 0.7, "couch", 1.5), seen(model, 4.5, 4.0, 0.7, 0.7, "small table")])
    model.update([seen(model, 4.55, 3.05, 2.0, 0.7, "couch", 1.6), seen(model, 4.45, 4.0, 0.7, 0.7, "small table")])
    furniture = model.furniture()
    assert len(furniture) == 2
    couch = next(e for e in furniture if e.category == "couch")
    assert couch.name == "couch" and couch.room == "living room"
    assert couch.orientation_rad == pytest.approx(1.55, abs=0.01)
    assert couch.centroid_m == pytest.approx([4.5, 3.0], abs=0.1)
    assert couch.attributes["seen"] == 2
    table = next(e for e in furniture if e.category == "small table")
    assert table.name == "table" and table.orientation_rad is None
    kinds = {e.name for e in model.entities()}
    assert {"room", "wall", "door", "couch", "table"} <= kinds


def test_category_votes_and_moved_furniture_is_forgotten(apartment):
    model = EnvironmentModel(apartment)
    model.update([seen(model, 4.5, 5.0, 0.6, 0.6, "chair", 0.0, 0.9)])
    model.update([seen(model, 4.5, 5.0, 0.6, 0.6, "small table", None, 0.4)])
    assert [e.category for e in model.furniture()] == ["chair"]
    robot = Pose2D(2.3, 5.0, 0.0)  # 2.2 m away, looking straight at it
    for _ in range(3):
        model.update([], robot)
    assert model.furniture() == []


def test_an_item_only_seen_unsure_is_unsure_until_a_sure_view_names_it(apartment):
    """Issue 20: the detector's ``unsure`` flag reaches the fused entity, so a task can look
    again before acting on it; one sure view of the same category clears it."""
    import dataclasses

    model = EnvironmentModel(apartment)

    def unsure(entity):
        return dataclasses.replace(entity, attributes={**entity.attributes, "unsure": True})

    model.update([unsure(seen(model, 4.5, 3.0, 2.0, 1.4, "bed", 0.0, 0.6)), seen(model, 4.5, 5.0, 0.6, 0.6, "chair")])
    by_category = {e.category: e for e in model.furniture()}
    assert by_category["bed"].attributes["unsure"] is True
    assert by_category["chair"].attributes["unsure"] is False
    model.update([unsure(seen(model, 4.5, 3.0, 2.0, 1.4, "bed", 0.0, 0.65))])
    assert next(e for e in model.furniture() if e.category == "bed").attributes["unsure"] is True
    model.update([seen(model, 4.5, 3.0, 2.0, 1.4, "bed", 0.0, 0.9)])
    assert next(e for e in model.furniture() if e.category == "bed").attributes["unsure"] is False


def test_a_detection_on_another_grid_is_regridded(apartment):
    from assistant.geometry import GridMap

    model = EnvironmentModel(apartment)
    other = GridMap.covering(3.0, 2.0, 6.0, 5.0, resolution_m=0.1)
    det = Entity.from_polygon("d", "couch", EntityKind.SHORT_TERM,
                              rectangle(Pose2D(4.5, 3.0, 0.0), 2.0, 0.7), other, 1.57, category="couch")
    model.update([det])
    assert model.furniture()[0].centroid_m == pytest.approx([4.5, 3.0], abs=0.1)
    assert model.furniture()[0].grid == model.grid


def _l_view(model, confidence=0.9):
    """One detection covering two couches that meet in an L (as one sample): facing between."""
    a = rectangle(Pose2D(4.0, 3.0, 0.0), 2.0, 0.8)  # along x, facing +y (90°)
    b = rectangle(Pose2D(5.4, 4.4, math.pi / 2), 2.0, 0.8)  # along y at a's east end, facing west
    cells = np.vstack([Entity.from_polygon("a", "couch", EntityKind.SHORT_TERM, a, model.grid).cells,
                       Entity.from_polygon("b", "couch", EntityKind.SHORT_TERM, b, model.grid).cells])
    return Entity("d", "couch", EntityKind.SHORT_TERM, model.grid, np.unique(cells, axis=0),
                  math.radians(135), category="couch", confidence=confidence)


def test_a_track_of_two_couches_is_split_when_each_is_seen_facing_its_own_way(apartment):
    model = EnvironmentModel(apartment)
    model.update([_l_view(model)])  # the first view: one sample, one track
    assert len(model.furniture()) == 1
    model.update([seen(model, 4.0, 3.0, 2.0, 0.8, "couch", math.pi / 2)])  # then the first couch alone
    model.update([seen(model, 5.4, 4.4, 0.8, 2.0, "couch", math.pi)])      # and the second
    couches = sorted(model.furniture(), key=lambda e: e.centroid_m[0])
    assert len(couches) == 2
    assert couches[0].orientation_rad == pytest.approx(math.pi / 2, abs=0.05)
    assert abs(math.remainder(couches[1].orientation_rad - math.pi, 2 * math.pi)) < 0.05
    assert couches[0].centroid_m == pytest.approx([4.0, 3.0], abs=0.25)
    assert couches[1].centroid_m == pytest.approx([5.4, 4.4], abs=0.25)


def test_one_couch_seen_once_with_its_front_wrong_is_not_split(apartment):
    model = EnvironmentModel(apartment)
    for _ in range(3):
        model.update([seen(model, 4.5, 3.0, 2.0, 0.7, "couch", math.pi / 2)])
    # a partial view of its end, read facing the other way round
    model.update([seen(model, 5.2, 3.0, 0.6, 0.7, "couch", -math.pi / 2)])
    assert len(model.furniture()) == 1


def test_a_bed_seen_in_parts_with_one_front_wrong_stays_one_bed(apartment):
    model = EnvironmentModel(apartment)
    for _ in range(2):
        model.update([seen(model, 5.0, -3.0, 2.1, 1.2, "bed", -math.pi / 2)])
    # a view of its head end read as a couch facing sideways: not a second item
    model.update([seen(model, 5.0, -2.3, 1.2, 0.8, "couch", 0.0)])
    assert len(model.furniture()) == 1


def cut(model, x, y, length, width, category, facing=None, confidence=0.5, centre=None):
    """A detection whose view ran out of the image (``partial``), with the detector's centre."""
    e = seen(model, x, y, length, width, category, facing, confidence)
    cx, cy = centre or (x, y)
    e.attributes.update({"partial": True, "x": cx, "y": cy})
    return e


def test_a_couchs_ends_seen_alone_do_not_make_it_two_chairs(apartment):
    """The apartment couch (2 m) behind the coffee table: every view is cut by the image border;
    the two ends, each seen alone, look like chairs and are read as chairs with more weight
    than the couch views. The couch stays one couch, centred and facing by its couch views."""
    model = EnvironmentModel(apartment)
    model.update([cut(model, 4.5, 3.0, 2.0, 0.8, "couch", math.pi / 2, 0.17, centre=(4.5, 3.0))])
    model.update([cut(model, 4.5, 3.0, 2.0, 0.8, "couch", math.pi / 2, 0.17, centre=(4.45, 3.0))])
    for _ in range(3):  # the left end, as a chair facing away, again and again
        model.update([cut(model, 3.85, 3.05, 0.7, 0.7, "chair", -math.pi / 2, 0.49)])
    model.update([cut(model, 5.2, 3.05, 0.7, 0.7, "chair", -math.pi / 2, 0.49)])  # the right end
    furniture = model.furniture()
    assert [e.category for e in furniture] == ["couch"]
    couch = furniture[0]
    assert couch.attributes["x"] == pytest.approx(4.475, abs=0.01)  # the couch views' centres
    assert couch.orientation_rad == pytest.approx(math.pi / 2, abs=0.01)


def test_a_chair_sized_track_stays_what_most_views_said(apartment):
    other = EnvironmentModel(apartment)
    other.update([seen(other, 4.5, 5.0, 0.6, 0.6, "chair", 0.0, 0.8)])
    other.update([seen(other, 4.5, 5.0, 0.6, 0.6, "couch", 0.0, 0.5)])
    assert [e.category for e in other.furniture()] == ["chair"]


def test_a_category_too_small_for_the_floor_a_track_covers_loses_the_vote(apartment):
    model = EnvironmentModel(apartment)
    model.update([seen(model, 4.5, 3.0, 2.0, 0.9, "chair", 0.0, 0.9)])   # 1.8 m²: no chair is that big
    model.update([seen(model, 4.5, 3.0, 2.0, 0.9, "couch", 0.0, 0.5)])
    assert [e.category for e in model.furniture()] == ["couch"]
    lone = EnvironmentModel(apartment)  # with nothing else said, the vote stands
    lone.update([seen(lone, 4.5, 3.0, 2.0, 0.9, "chair", 0.0, 0.9)])
    assert [e.category for e in lone.furniture()] == ["chair"]


def test_two_couches_in_an_l_split_when_the_views_of_each_are_cut_by_the_image_border(apartment):
    """As in the two-bedroom house: the first view of the L and every later view of each couch
    run out of the image."""
    model = EnvironmentModel(apartment)
    first = _l_view(model, confidence=0.45)
    first.attributes["partial"] = True
    model.update([first])
    model.update([cut(model, 4.0, 3.0, 2.0, 0.8, "couch", math.pi / 2, 0.45)])
    model.update([cut(model, 5.4, 4.4, 0.8, 2.0, "couch", math.pi, 0.45)])
    couches = sorted(model.furniture(), key=lambda e: e.centroid_m[0])
    assert [e.category for e in couches] == ["couch", "couch"]
    assert couches[0].orientation_rad == pytest.approx(math.pi / 2, abs=0.05)


def test_the_weighted_median_ignores_one_glimpse_far_off():
    from assistant.world.environment import _weighted_median

    values, weights = np.array([2.94, 2.07, 1.96, 2.21]), np.array([0.17, 0.64, 0.4, 0.37])
    assert _weighted_median(values, weights) == pytest.approx(2.07)
    assert _weighted_median(np.array([1.0, 3.0]), np.array([1.0, 1.0])) == pytest.approx(2.0)
    assert _weighted_median(np.array([5.0]), np.array([0.2])) == 5.0

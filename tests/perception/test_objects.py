"""The object detector interface and its simulator model (hit ids → sightings)."""

import math

import numpy as np
import pytest

from assistant.geometry import Pose2D
from assistant.perception.objects import ObjectDetector, Sighting, SimObjectDetector
from assistant.sim.renderer import DepthRenderer


def _facing(obj, distance_m=1.5):
    """A robot pose ``distance_m`` west of ``obj``, facing it."""
    return Pose2D(obj.x - distance_m, obj.y, 0.0)


@pytest.fixture(scope="module")
def laptop_view(apartment):
    scene = apartment.scene("original")
    laptop = next(o for o in scene.objects if o.name == "laptop")
    frame = DepthRenderer(apartment, "original").render(_facing(laptop))
    return scene, laptop, frame


def test_sim_detector_is_an_object_detector(apartment):
    assert isinstance(SimObjectDetector.for_scene(apartment.scene("original")), ObjectDetector)


def test_sees_the_object_in_front_and_places_it(laptop_view):
    scene, laptop, frame = laptop_view
    sightings = SimObjectDetector.for_scene(scene).detect(frame)
    names = [s.name for s in sightings]
    assert "laptop" in names
    seen = sightings[names.index("laptop")]
    assert isinstance(seen, Sighting)
    assert math.hypot(seen.x_m - laptop.x, seen.y_m - laptop.y) < 0.25
    assert 1.0 < seen.distance_m < 2.0 and seen.pixels >= 50
    assert seen.to_dict()["name"] == "laptop"


def test_thresholds_and_unknown_names_hide_objects(laptop_view):
    scene, _, frame = laptop_view
    assert SimObjectDetector(["laptop"], max_range_m=0.5).detect(frame) == []
    assert SimObjectDetector(["laptop"], min_pixels=10**7).detect(frame) == []
    assert SimObjectDetector(["stapler"]).detect(frame) == []


def test_miss_rate_is_seeded_and_drops_about_that_share(laptop_view):
    _, _, frame = laptop_view
    runs = [len(SimObjectDetector(["laptop"], miss_rate=0.5, seed=3).detect(frame)) for _ in range(3)]
    assert len(set(runs)) == 1  # same seed, same first draw
    detector = SimObjectDetector(["laptop"], miss_rate=0.5, seed=1)
    seen = sum(len(detector.detect(frame)) for _ in range(200))
    assert 70 < seen < 130


def test_a_frame_without_hit_ids_reports_nothing(laptop_view):
    import dataclasses

    _, _, frame = laptop_view
    real = dataclasses.replace(frame, hit_ids=None, hit_names=())
    assert SimObjectDetector(["laptop"]).detect(real) == []


def test_bad_parameters_are_refused():
    with pytest.raises(ValueError, match="miss_rate"):
        SimObjectDetector(["mug"], miss_rate=1.0)
    with pytest.raises(ValueError, match="min_pixels"):
        SimObjectDetector(["mug"], min_pixels=0)

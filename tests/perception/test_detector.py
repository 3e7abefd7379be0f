import math

import numpy as np
import pytest

from assistant.geometry import Pose2D
from assistant.perception import FurnitureDetector
from assistant.perception.database import ItemRenderer, study_items
from assistant.robot.frames import CameraIntrinsics, CameraMount, DepthFrame
from assistant.world import EntityKind


def frame_of(depth):
    k = CameraIntrinsics.kinect_v1()
    return DepthFrame(np.asarray(depth, dtype=np.float32), k, CameraMount(), Pose2D(0, 0, 0))


@pytest.mark.parametrize("what, depth", [
    ("zeros", np.zeros((480, 640))),
    ("nan", np.full((480, 640), np.nan)),
    ("wall", np.full((480, 640), 0.9)),
    ("inf", np.full((480, 640), np.inf)),
])
def test_bad_frames_give_reasons_not_exceptions(tiny_models, what, depth):
    result = FurnitureDetector(tiny_models).analyse(frame_of(depth))
    assert result.detections == []
    assert result.reason
    assert result.to_dict()["detections"] == []


def test_a_chair_is_detected_where_it_stands(tiny_models):
    item = next(i for i in study_items() if i.name == "wood chair")
    renderer = ItemRenderer(item.mesh(), intrinsics=CameraIntrinsics.kinect_v1())
    facing = 2.5  # turned towards the robot, a little to the side
    pose = Pose2D(2.2, 0.3, facing - item.front_offset_rad)
    robot = Pose2D(1.0, -2.0, 0.5)
    frame = renderer.render(pose, seed=3)
    frame = DepthFrame(frame.depth_m, frame.intrinsics, frame.mount, robot)
    result = FurnitureDetector(tiny_models).analyse(frame)
    assert result.floor is not None and result.floor.height_m == pytest.approx(1.05, abs=0.02)
    chairs = [d for d in result.detections if d.category == "chair"]
    assert len(chairs) == 1
    expected = robot.transform_points(pose.xy[None])[0]
    assert math.hypot(chairs[0].x - expected[0], chairs[0].y - expected[1]) < 0.15
    assert abs((chairs[0].facing - (facing + robot.theta) + math.pi) % (2 * math.pi) - math.pi) < math.radians(8)
    entities = FurnitureDetector(tiny_models).detect(frame)
    assert entities[0].kind is EntityKind.SHORT_TERM and entities[0].name == "chair"
    assert entities[0].orientation_rad is not None


def test_unknown_orientation_method_is_named(tiny_models):
    from assistant.errors import UnknownNameError

    with pytest.raises(UnknownNameError, match="plane"):
        FurnitureDetector(tiny_models, orientation="compass")


def test_view_coverage_weighs_whole_views_above_glimpses():
    from assistant.perception.detector import typical_area_m2, view_coverage

    couch = typical_area_m2("couch")
    assert couch == pytest.approx(0.73 * 2.06)
    assert view_coverage(2 * couch, "couch", partial=False) == 1.0
    assert view_coverage(couch / 2, "couch", partial=False) == pytest.approx(0.5)
    assert view_coverage(couch / 2, "couch", partial=True) == pytest.approx(0.25)
    assert view_coverage(0.01, "couch", partial=False) == pytest.approx(0.2)  # never nothing


def test_entities_carry_confidence_times_coverage(tiny_models):
    item = next(i for i in study_items() if i.name == "coffee table")
    renderer = ItemRenderer(item.mesh(), intrinsics=CameraIntrinsics.kinect_v1())
    frame = renderer.render(Pose2D(2.3, 0.0, 0.3), seed=2)
    detector = FurnitureDetector(tiny_models)
    dets = detector.analyse(frame).detections
    assert dets and 0 < dets[0].coverage <= 1
    entity = detector.detect(frame)[0]
    assert entity.confidence == pytest.approx(dets[0].confidence * dets[0].coverage)
    assert entity.attributes["coverage"] == pytest.approx(dets[0].coverage)
    assert "coverage" in dets[0].to_dict()

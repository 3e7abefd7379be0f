import math

import numpy as np
import pytest
from sklearn.exceptions import NotFittedError

from assistant.geometry import Pose2D
from assistant.perception.features import estimate_normals, orientation_features
from assistant.perception.orientation import (
    LinearOrientationEstimator,
    PlaneOrientationEstimator,
    angle_error,
)


def chair(facing: float, at=(2.5, 0.3), back_only=False):
    """Seat and backrest points of a chair facing ``facing`` (floor frame)."""
    g = np.arange(-0.25, 0.25, 0.03)
    seat = np.array([(x, y, 0.45) for x in g for y in g])
    back = np.array([(-0.25, y, z) for y in g for z in np.arange(0.45, 0.9, 0.03)])
    legs = np.array([(sx * 0.22, sy * 0.22, z) for sx in (-1, 1) for sy in (-1, 1) for z in np.arange(0.0, 0.45, 0.05)])
    local = back if back_only else np.vstack([seat, back, legs])
    pose = Pose2D(at[0], at[1], facing)  # local +x is the front
    xy = pose.transform_points(local[:, :2])
    return np.column_stack([xy, local[:, 2]])


@pytest.mark.parametrize("facing", [0.0, 1.0, 2.5, -2.0, math.pi])
def test_plane_estimator_finds_the_front(facing):
    pts = chair(facing)
    normals = estimate_normals(pts, np.array([0.0, 0.0, 1.05]))
    est = PlaneOrientationEstimator().fit()
    assert angle_error(est.estimate(pts, normals, "chair+front"), facing) < math.radians(5)
    assert math.isnan(est.estimate(pts, normals, "small table"))


def test_a_view_of_the_back_alone_faces_away_from_the_camera():
    pts = chair(0.0, at=(2.5, 0.0), back_only=True)  # the camera at the origin sees the back
    normals = estimate_normals(pts, np.array([0.0, 0.0, 1.05]))
    est = PlaneOrientationEstimator().fit()
    assert angle_error(est.estimate(pts, normals, "chair+back"), 0.0) < math.radians(10)


def test_linear_estimator_learns_per_subclass():
    rng = np.random.default_rng(0)
    Q, facing = [], []
    for _ in range(12):
        f = math.pi + rng.uniform(-0.8, 0.8)  # front views: the camera is at the origin
        pts = chair(f)
        Q.append(orientation_features(pts, estimate_normals(pts, np.array([0.0, 0.0, 1.05]))))
        facing.append(f)
    Q, facing = np.array(Q), np.array(facing)
    est = LinearOrientationEstimator()
    with pytest.raises(NotFittedError):
        est.predict(Q, ["chair+front"] * len(Q))
    est.fit(Q, ["chair+front"] * len(Q), facing)
    pred = est.predict(Q, ["chair+front"] * len(Q))
    assert np.median(angle_error(pred, facing)) < math.radians(30)
    assert np.isnan(est.predict(Q[:1], ["small table"])[0])

import json

import numpy as np
import pytest

from assistant.executor import ExecutionResult, ExecutionStatus
from assistant.geometry import Pose2D


def test_statuses_cover_the_fetch_failures():
    assert {s.value for s in ExecutionStatus} >= {
        "success", "parse", "no_room", "reference_not_found", "no_path", "collision", "not_visible",
        "ambiguous"}


def test_results_read_as_their_success_and_serialise_to_json():
    ok = ExecutionResult.ok("arrived", final_pose=Pose2D(1.0, 2.0, 0.5), sim_seconds=3.0)
    assert ok and ok.success and ok.to_dict()["failure"] is None
    bad = ExecutionResult.failed(ExecutionStatus.NO_PATH, "the door is blocked",
                                 details={"blocked_at": np.array([1.0, 2.0]), "pose": Pose2D(0, 0, 0),
                                          "status": ExecutionStatus.COLLISION})
    assert not bad
    data = json.loads(json.dumps(bad.to_dict()))
    assert data["failure"] == "no_path" and data["status"] == "no_path"
    assert data["details"] == {"blocked_at": [1.0, 2.0], "pose": [0.0, 0.0, 0.0], "status": "collision"}
    assert ok.with_details(room="bedroom").details == {"room": "bedroom"}
    with pytest.raises(ValueError):
        ExecutionResult.failed(ExecutionStatus.SUCCESS, "not a failure")

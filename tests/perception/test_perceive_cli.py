"""``assistant perceive`` through the console entry point (models: the tiny test set)."""

import json
import math

import numpy as np
import pytest
from PIL import Image

from assistant.cli import main


@pytest.fixture()
def tiny_cli(monkeypatch, tiny_models):
    import assistant.perception.models as models

    monkeypatch.setattr(models, "trained_models", lambda **kw: tiny_models)


def depth_png(path, with_box=True):
    """A 640×480 mm depth PNG: an endless floor 1.05 m below a camera pitched 15° down."""
    from assistant.robot.frames import CameraIntrinsics, pixel_rays

    rays = pixel_rays(CameraIntrinsics.kinect_v1()).astype(float)
    t = math.radians(15)
    up = np.array([0.0, -math.cos(t), -math.sin(t)])
    denom = rays @ up
    with np.errstate(divide="ignore"):
        depth = np.where(denom < -1e-6, 1.05 / -denom, 0.0)
    depth[depth > 6] = 0
    Image.fromarray(np.round(depth * 1000).astype(np.uint16)).save(path)
    return path


def test_perceive_a_depth_png(tmp_path, capsys, tiny_cli):
    png = depth_png(tmp_path / "floor.png")
    code = main(["perceive", "--depth", str(png), "--intrinsics", "525,525,319.5,239.5",
                 "--depth-scale", "0.001", "--json"])
    assert code == 0
    data = json.loads(capsys.readouterr().out)
    assert data["floor"]["height"] == pytest.approx(1.05, abs=0.02)
    assert data["floor"]["tilt_deg"] == pytest.approx(15.0, abs=0.5)
    assert data["detections"] == [] and "reason" in data


def test_perceive_a_simulated_view(capsys, tiny_cli):
    assert main(["perceive", "--world", "apartment", "--pose", "4.5,6.0,-1.5708", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["floor"]["height"] == pytest.approx(1.05, abs=0.01)
    assert data["detections"], data
    for d in data["detections"]:
        assert set(d) >= {"category", "subclass", "x", "y", "facing", "confidence"}
    couch = [d for d in data["detections"] if d["category"] == "couch"]
    assert couch and math.hypot(couch[0]["x"] - 4.5, couch[0]["y"] - 3.0) < 0.3


def test_bad_requests_say_what_to_do(tmp_path, capsys, tiny_cli):
    assert main(["perceive", "--depth", str(tmp_path / "missing.png"), "--intrinsics", "1,1,1,1",
                 "--depth-scale", "0.001"]) == 2
    assert "no such depth image" in capsys.readouterr().err
    assert main(["perceive", "--json"]) == 2
    assert "either --world" in capsys.readouterr().err
    zeros = tmp_path / "zeros.png"
    Image.fromarray(np.zeros((480, 640), dtype=np.uint16)).save(zeros)
    assert main(["perceive", "--depth", str(zeros), "--intrinsics", "525,525,319.5,239.5",
                 "--depth-scale", "0.001", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["detections"] == [] and "empty frame" in data["reason"]

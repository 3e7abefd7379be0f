"""``assistant sim render``: 16-bit PNG in millimetres, JSON sidecar, clear errors."""

from __future__ import annotations

import json

import numpy as np
import pytest
from PIL import Image

from assistant.cli import main


def test_render_writes_png_and_sidecar(tmp_path, capsys):
    out = tmp_path / "frames" / "couch.png"
    status = main(["sim", "render", "apartment", "--pose", "4.5,5.5,-1.571", "--tilt", "20",
                   "--seed", "3", "--out", str(out), "--json"])
    assert status == 0
    printed = json.loads(capsys.readouterr().out.strip())
    image = Image.open(out)
    assert image.mode == "I;16" and image.size == (640, 480)
    mm = np.array(image)
    assert mm.dtype == np.uint16
    valid = mm > 0
    assert valid.mean() > 0.5
    assert 500 <= mm[valid].min() and mm[valid].max() <= 4500  # Kinect range in millimetres
    sidecar = json.loads((tmp_path / "frames" / "couch.png.json").read_text())
    assert sidecar["intrinsics"] == {"width": 640, "height": 480, "fx": 525.0, "fy": 525.0,
                                     "cx": 319.5, "cy": 239.5}
    assert sidecar["depth_scale"] == 0.001 and sidecar["camera_height"] == 1.05
    assert sidecar["tilt_deg"] == 20.0
    assert sidecar["robot_pose"] == {"x": 4.5, "y": 5.5, "heading": pytest.approx(-1.571)}
    assert "couch_1" in sidecar["seen"]
    assert printed["intrinsics"] == sidecar["intrinsics"] and printed["sidecar"].endswith(".png.json")


def test_same_seed_same_png(tmp_path):
    args = ["sim", "render", "apartment", "--pose", "1,-4,3.1", "--scene", "modified"]
    main(args + ["--out", str(tmp_path / "a.png")])
    main(args + ["--out", str(tmp_path / "b.png")])
    assert (tmp_path / "a.png").read_bytes() == (tmp_path / "b.png").read_bytes()


def test_misspelt_world_lists_known_ones(tmp_path, capsys):
    status = main(["sim", "render", "apartmnt", "--pose", "1,1,0", "--out", str(tmp_path / "x.png")])
    assert status == 2
    err = capsys.readouterr().err
    assert "unknown world 'apartmnt'" in err and "apartment" in err and "hk-studio" in err
    assert not (tmp_path / "x.png").exists()


def test_pose_outside_the_map(tmp_path, capsys):
    status = main(["sim", "render", "apartment", "--pose", "40,0,0", "--out", str(tmp_path / "x.png")])
    assert status == 2
    assert "outside the map of apartment" in capsys.readouterr().err


def test_bad_pose_text_is_a_usage_error(tmp_path):
    with pytest.raises(SystemExit) as exit_info:
        main(["sim", "render", "apartment", "--pose", "4.5,north,0", "--out", str(tmp_path / "x.png")])
    assert exit_info.value.code == 2

"""The exported page renders in a real browser with the network cut off (skipped without
Chromium: `apt-get install chromium`)."""

from __future__ import annotations

import shutil
import subprocess

import numpy as np
import pytest

BROWSER = next((shutil.which(b) for b in ("chromium", "chromium-browser", "google-chrome")
                if shutil.which(b)), None)


@pytest.mark.skipif(BROWSER is None, reason="no headless Chromium on this machine")
def test_apartment_page_renders_offline(drawn_apartment, tmp_path):
    from PIL import Image

    page = drawn_apartment.save_html(tmp_path / "apartment.html")
    shot = tmp_path / "shot.png"
    subprocess.run(
        [BROWSER, "--headless=new", "--no-sandbox", "--disable-gpu", "--use-gl=swiftshader",
         "--enable-unsafe-swiftshader", "--host-resolver-rules=MAP * ~NOTFOUND",
         f"--user-data-dir={tmp_path / 'profile'}", "--window-size=800,600",
         "--virtual-time-budget=5000", f"--screenshot={shot}", page.as_uri()],
        capture_output=True, timeout=90, check=False)
    assert shot.exists(), "Chromium wrote no screenshot"
    image = np.asarray(Image.open(shot).convert("RGB")).astype(int)
    # The background is a vertical gradient: the same colour across each row. The drawn
    # home (centred by frame_camera) is everything that differs from its row's left end.
    drawn = np.abs(image - image[:, :1, :]).sum(axis=2) > 30
    assert drawn[40:].mean() > 0.15, "the scene covers a good part of the view"
    wall_like = (image.min(axis=2) > 190) & (np.ptp(image, axis=2) < 20)
    assert wall_like.mean() > 0.01, "light grey walls are visible"

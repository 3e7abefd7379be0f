"""Headless Chromium screenshots of exported scene pages and the checks made on them."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import numpy as np

BROWSER = next((shutil.which(b) for b in ("chromium", "chromium-browser", "google-chrome")
                if shutil.which(b)), None)
#: the robot's body colour (SceneView.draw_robot's default, #d9482b) and its heading cone (yellow)
ROBOT_HUE_DEG = (0.0, 20.0)
CONE_HUE_DEG = (45.0, 62.0)


def screenshot(page: Path, shot: Path, profile: Path) -> np.ndarray:
    """Render ``page`` in headless Chromium (network cut off) and return the RGB image (0–1)."""
    from PIL import Image

    subprocess.run(
        [BROWSER, "--headless=new", "--no-sandbox", "--disable-gpu", "--use-gl=swiftshader",
         "--enable-unsafe-swiftshader", "--disable-background-networking",
         "--host-resolver-rules=MAP * ~NOTFOUND", f"--user-data-dir={profile}",
         "--window-size=800,600", "--virtual-time-budget=5000", f"--screenshot={shot}", page.as_uri()],
        capture_output=True, timeout=90, check=False)
    assert shot.exists(), "Chromium wrote no screenshot"
    return np.asarray(Image.open(shot).convert("RGB")).astype(float) / 255.0


def drawn_mask(image: np.ndarray) -> np.ndarray:
    """The pixels that are not the background (a vertical gradient, the same colour across each
    row) nor the controls bar at the top."""
    drawn = np.abs(image - image[:, :1, :]).sum(axis=2) > 30 / 255
    drawn[:40] = False
    return drawn


def drawn_share(image: np.ndarray) -> float:
    """Share of the view below the controls bar that is drawn."""
    return float(drawn_mask(image)[40:].mean())


def hue_pixels(image: np.ndarray, hue_deg: tuple[float, float], min_saturation: float = 0.35) -> int:
    """How many drawn pixels have a hue in ``hue_deg`` (degrees), saturated and not dark."""
    from matplotlib.colors import rgb_to_hsv

    hsv = rgb_to_hsv(image)
    hue = hsv[..., 0] * 360.0
    return int(((hue >= hue_deg[0]) & (hue <= hue_deg[1]) & (hsv[..., 1] > min_saturation)
                & (hsv[..., 2] > 0.25) & drawn_mask(image)).sum())


def furniture_hues(world, scene: str = "original") -> dict[str, tuple[float, float]]:
    """Furniture id → (hue in degrees, saturation) of its mesh's mean colour, for the saturated
    ones."""
    from matplotlib.colors import rgb_to_hsv

    from assistant.sim.meshes import scene_meshes
    from assistant.viz import shapes

    out = {}
    for item in scene_meshes(world, scene):
        if item.kind != "furniture":
            continue
        _, _, colours = shapes.mesh_arrays(item.mesh)
        if colours is None or len(colours) == 0:
            continue
        hsv = rgb_to_hsv(np.clip(np.asarray(colours, dtype=float).mean(axis=0), 0, 1))
        if hsv[1] > 0.35:
            out[item.id] = (float(hsv[0] * 360.0), float(hsv[1]))
    return out


def furniture_colours_seen(image: np.ndarray, world, min_pixels: int = 40) -> list[str]:
    """The furniture whose colour (hue ± 6°, at least 80 % of its saturation: shading changes
    brightness, not saturation, and the pastel floors are far less saturated) covers at least
    ``min_pixels`` of the image."""
    return [fid for fid, (hue, saturation) in furniture_hues(world).items()
            if hue_pixels(image, (hue - 6.0, hue + 6.0), 0.8 * saturation) >= min_pixels]


def robot_drawn(image: np.ndarray) -> bool:
    """The robot's red body and its yellow heading cone are both visible."""
    return hue_pixels(image, ROBOT_HUE_DEG, 0.6) >= 60 and hue_pixels(image, CONE_HUE_DEG, 0.6) >= 5


def colour_pixels(image: np.ndarray, colour, hue_tol_deg: float = 8.0) -> int:
    """Drawn pixels of ``colour``'s hue (± ``hue_tol_deg``), at least 60 % of its saturation
    and bright (translucent boxes over the background keep their hue, lose some saturation)."""
    from matplotlib.colors import rgb_to_hsv

    h, s, _ = rgb_to_hsv(np.asarray(colour, dtype=float))
    hsv = rgb_to_hsv(image)
    diff = np.abs((hsv[..., 0] - h + 0.5) % 1.0 - 0.5) * 360.0
    return int(((diff <= hue_tol_deg) & (hsv[..., 1] >= 0.6 * s) & (hsv[..., 2] > 0.5) & drawn_mask(image)).sum())

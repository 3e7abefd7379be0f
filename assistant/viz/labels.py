"""Text for the scene view: words rendered to a transparent PNG, laid flat on the floor.

meshcat 0.3.2 has no text geometry, so a label is a thin box whose top face carries an image
of the text (Pillow's built-in font; the image travels as a ``data:`` URL, so labels work
offline and in the static page).
"""

from __future__ import annotations

import io

import meshcat.geometry as mg
from PIL import Image, ImageDraw, ImageFont

from assistant.viz.colours import to_rgb

__all__ = ["label_object", "text_png"]

_FONT_PX = 64
_PAD_PX = 8


def text_png(text: str, color="#1e1e1e") -> tuple[bytes, float]:
    """PNG bytes of ``text`` in ``color`` on a transparent background, and its width/height."""
    try:
        font = ImageFont.load_default(size=_FONT_PX)
    except (TypeError, OSError):  # Pillow without FreeType: its small bitmap font
        font = ImageFont.load_default()
    left, top, right, bottom = font.getbbox(text)
    size = (max(1, right - left) + 2 * _PAD_PX, max(1, bottom - top) + 2 * _PAD_PX)
    image = Image.new("RGBA", size, (0, 0, 0, 0))
    r, g, b = (round(255 * c) for c in to_rgb(color))
    ImageDraw.Draw(image).text((_PAD_PX - left, _PAD_PX - top), text, font=font,
                               fill=(r, g, b, 255))
    buffer = io.BytesIO()
    image.save(buffer, format="PNG")
    return buffer.getvalue(), size[0] / size[1]


def label_object(text: str, height_m: float, max_width_m: float | None = None,
                 color="#1e1e1e") -> mg.Mesh:
    """A meshcat object showing ``text`` on the top face of a 2 mm box centred on its origin,
    letters ``height_m`` tall (smaller when the text would be wider than ``max_width_m``).
    Seen from above it reads left to right along +x with its top towards +y."""
    png, aspect = text_png(text, color)
    height = height_m
    if max_width_m is not None and height * aspect > max_width_m:
        height = max_width_m / aspect
    # side=0 (three.js FrontSide): only outward faces are drawn, so from above the box shows
    # its top face and not the mirrored text of its bottom face through the transparency.
    material = mg.MeshBasicMaterial(map=mg.ImageTexture(mg.PngImage(png)), transparent=True,
                                    side=0)
    return mg.Mesh(mg.Box([height * aspect, height, 0.002]), material)

"""Colours for the scene view: parsing, per-room palette, and the red → green score ramp.

Colours are accepted as ``"#rrggbb"`` strings, a few names (``"red"``, ``"green"``…),
``0xRRGGBB`` integers or ``(r, g, b)`` with components in 0–1. meshcat materials want an
``0xRRGGBB`` integer (:func:`to_hex_int`); vertex colours want floats in 0–1 (:func:`to_rgb`).
"""

from __future__ import annotations

import colorsys

import numpy as np

from assistant.errors import AssistantError

__all__ = ["CATEGORY_COLOURS", "NAMED_COLOURS", "Colour", "room_colour", "score_colours", "to_hex_int", "to_rgb"]

#: Anything :func:`to_rgb` accepts.
Colour = str | int | tuple[float, float, float]

NAMED_COLOURS: dict[str, tuple[float, float, float]] = {
    "red": (0.90, 0.15, 0.15),
    "green": (0.15, 0.75, 0.25),
    "blue": (0.15, 0.40, 0.90),
    "yellow": (0.95, 0.85, 0.10),
    "orange": (0.98, 0.55, 0.10),
    "magenta": (0.85, 0.20, 0.80),
    "cyan": (0.10, 0.80, 0.85),
    "white": (1.0, 1.0, 1.0),
    "black": (0.0, 0.0, 0.0),
    "grey": (0.5, 0.5, 0.5),
    "gray": (0.5, 0.5, 0.5),
}

#: Furniture categories as a detector reports them (``assistant.world.CATEGORIES``), each its
#: own saturated colour, apart from the floor plane's light blue and the robot's red and yellow.
CATEGORY_COLOURS: dict[str, tuple[float, float, float]] = {
    "bed": (0.58, 0.30, 0.85),
    "couch": (0.15, 0.65, 0.30),
    "chair": (0.10, 0.35, 0.85),
    "large table": (0.95, 0.50, 0.05),
    "small table": (0.85, 0.20, 0.55),
}

# Hues (degrees) far apart from each other, in the order rooms are listed in a world file;
# pastel (low saturation) so that red→green score arrows and highlights stand out on them.
_ROOM_HUES = (30.0, 210.0, 275.0, 175.0, 330.0, 55.0, 240.0, 120.0, 0.0, 150.0)


def to_rgb(colour) -> tuple[float, float, float]:
    """``(r, g, b)`` floats in 0–1 for any accepted colour; AssistantError for anything else."""
    if isinstance(colour, str):
        text = colour.strip().lower()
        if text in NAMED_COLOURS:
            return NAMED_COLOURS[text]
        if text.startswith("#") and len(text) == 7:
            try:
                value = int(text[1:], 16)
            except ValueError:
                value = None
            if value is not None:
                return to_rgb(value)
        raise AssistantError(f"colour {colour!r} is not understood; use '#rrggbb', an 0xRRGGBB "
                             f"number, (r, g, b) in 0–1 or one of: {', '.join(sorted(NAMED_COLOURS))}")
    if isinstance(colour, (int, np.integer)) and not isinstance(colour, bool):
        value = int(colour)
        if not 0 <= value <= 0xFFFFFF:
            raise AssistantError(f"colour {value:#x} is outside 0x000000–0xffffff")
        return ((value >> 16 & 255) / 255.0, (value >> 8 & 255) / 255.0, (value & 255) / 255.0)
    try:
        rgb = tuple(float(c) for c in colour)
    except TypeError:
        rgb = ()
    if len(rgb) != 3 or not all(0.0 <= c <= 1.0 for c in rgb):
        raise AssistantError(f"colour {colour!r} is not understood; give (r, g, b) with each "
                             "component between 0 and 1, '#rrggbb' or a name such as 'red'")
    return rgb  # type: ignore[return-value]


def to_hex_int(colour) -> int:
    """The ``0xRRGGBB`` integer meshcat materials take."""
    r, g, b = to_rgb(colour)
    return (round(r * 255) << 16) | (round(g * 255) << 8) | round(b * 255)


def room_colour(index: int, open_area: bool = False) -> tuple[float, float, float]:
    """A distinct floor colour for the ``index``-th room; open areas (no walls) are lighter."""
    hue = _ROOM_HUES[index % len(_ROOM_HUES)] / 360.0
    lightness, saturation = (0.80, 0.35) if open_area else (0.64, 0.40)
    return colorsys.hls_to_rgb(hue, lightness, saturation)


def score_colours(scores: np.ndarray) -> np.ndarray:
    """(N, 3) colours running from red (score 0) through yellow to green (score 1).

    ``scores`` must already lie in 0–1 (values outside are clipped).
    """
    s = np.clip(np.asarray(scores, dtype=float), 0.0, 1.0)
    red = np.clip(2.0 * (1.0 - s), 0.0, 1.0)
    green = np.clip(2.0 * s, 0.0, 1.0)
    return np.stack([0.9 * red, 0.8 * green, np.full_like(s, 0.1)], axis=1)

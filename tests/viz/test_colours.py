"""Colour parsing, room palette and the score ramp."""

from __future__ import annotations

import numpy as np
import pytest

from assistant.errors import AssistantError
from assistant.viz import room_colour, score_colours, to_hex_int, to_rgb


@pytest.mark.parametrize("colour, expected", [
    ("#ff8000", 0xFF8000), (0x123456, 0x123456), ((1.0, 0.0, 0.0), 0xFF0000), ("Red", 0xE62626),
])
def test_colours_in_every_accepted_form(colour, expected):
    assert to_hex_int(colour) == expected


@pytest.mark.parametrize("bad", ["#ff80", "not-a-colour", (2.0, 0.0, 0.0), (0.1, 0.2), -1, None])
def test_bad_colours_say_what_is_accepted(bad):
    with pytest.raises(AssistantError, match="colour"):
        to_rgb(bad)


def test_room_colours_are_distinct_and_open_areas_lighter():
    walled = [room_colour(i) for i in range(8)]
    assert len({tuple(np.round(c, 3)) for c in walled}) == 8
    for i in range(4):
        assert sum(room_colour(i, open_area=True)) > sum(room_colour(i))


def test_score_ramp_runs_from_red_to_green():
    cols = score_colours(np.array([0.0, 0.5, 1.0, 7.0]))
    assert cols[0, 0] > 0.8 and cols[0, 1] == 0.0  # red
    assert cols[2, 1] > 0.7 and cols[2, 0] == 0.0  # green
    assert cols[1, 0] > 0.8 and cols[1, 1] > 0.7  # yellow half way
    assert np.allclose(cols[3], cols[2])  # clipped

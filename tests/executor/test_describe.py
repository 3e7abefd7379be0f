"""Choosing among tables by the words said about them (catalogue size and shape)."""

from __future__ import annotations

import pytest

from assistant.executor.describe import description_fit, models_for_word


@pytest.fixture(scope="module")
def office(all_worlds):
    from assistant.world import furniture_entities, world_grid

    world = all_worlds["two-bedrooms-house"]
    return {e.id: e for e in furniture_entities(world, "original", world_grid(world, 0.05))}


def test_words_name_catalogue_models():
    assert {c for c, _ in models_for_word("round")} == {"small table"}
    assert {c for c, _ in models_for_word("square")} == {"small table", "large table"}  # by shape
    assert models_for_word("purple") == ()


def test_round_small_and_desk_pick_the_right_table(office):
    desk, round_table, hexagon = office["desk_1"], office["roundtable_4"], office["hexagontable_1"]
    assert description_fit(None, ("round",), round_table) > description_fit(None, ("round",), desk)
    assert description_fit(None, ("small",), round_table) > description_fit(None, ("small",), desk)
    assert description_fit("desk", (), desk) > description_fit("desk", (), round_table)
    assert description_fit(None, ("hexagon",), hexagon) > description_fit(None, ("hexagon",), round_table)
    # nothing said, or not a table: no preference
    assert description_fit(None, (), desk) == description_fit("table", (), round_table) == 1.0
    assert description_fit(None, ("round",), office["bed_1"]) == 1.0
    assert 0 < description_fit(None, ("large", "round"), round_table) < 1

"""Worlds that pass the schema but are not a house are refused at load, with the key to fix."""

from __future__ import annotations

import copy

import pytest
import yaml

from assistant.world import load_world, world_names
from assistant.world.worldfile import WorldFileError, parse_world, resolve_world_path


@pytest.fixture(scope="module")
def home() -> dict:
    return yaml.safe_load(resolve_world_path("training-home").read_text())


def _furniture(data, index=0, scene="original"):
    return data["scenes"][scene]["furniture"][index]


def _edit(home, change):
    data = copy.deepcopy(home)
    change(data)
    return yaml.safe_dump(data)


@pytest.mark.parametrize("change, where, words", [
    (lambda d: _furniture(d).update(x=45.0), "scenes.original.furniture[0]", "is not in the living room"),
    (lambda d: _furniture(d).update(x=1e300), "scenes.original.furniture[0]", "is not in the living room"),
    (lambda d: d["rooms"][0].update(polygon=[[0, 0], [100000, 0], [100000, 5], [0, 5]]), "rooms[0].polygon",
     "beyond"),
    (lambda d: d["rooms"][0].update(polygon=[[0, 0], [150, 0], [150, 5], [0, 5]]), "rooms", "at most 100 m"),
    (lambda d: d["rooms"][0].update(polygon=[[0, 0], [5, 0], [5, 0], [0, 0]]), "rooms[0].polygon", "m² of floor"),
    (lambda d: d["rooms"][0].update(polygon=[[0, 0], [5, 5], [5, 0], [0, 5]]), "rooms[0].polygon", "crosses itself"),
    (lambda d: _furniture(d, 1).update(x=_furniture(d)["x"], y=_furniture(d)["y"]),
     "scenes.original.furniture[1]", "overlaps couch_1"),
    (lambda d: d["start"].update(x=-40.0), "start", "in no room"),
])
def test_geometry_that_is_not_a_house_is_refused_with_its_place(home, change, where, words):
    with pytest.raises(WorldFileError) as caught:
        parse_world(_edit(home, change), "home.yaml")
    message = str(caught.value)
    assert message.startswith(f"home.yaml: {where}: ") and words in message
    assert "\n" not in message


@pytest.mark.parametrize("name", world_names())
def test_every_packaged_world_is_a_house(name):
    load_world(name)

"""Small hand-made worlds for simulator tests (a walled box room with a few items)."""

from __future__ import annotations

import json

import pytest

from assistant.world import parse_world


def box_world(furniture=(), objects=(), size=(6.0, 4.0), wall=0.05, start=(1.0, 2.0, 0.0)):
    """A single room ``size`` metres with walls of thickness ``wall`` just outside it."""
    w, h = size
    t = wall
    data = {
        "name": "box",
        "start": {"x": start[0], "y": start[1], "heading": start[2]},
        "rooms": [{"name": "room", "polygon": [[0, 0], [w, 0], [w, h], [0, h]]}],
        "walls": [[-t, -t, w + t, 0], [-t, h, w + t, h + t], [-t, 0, 0, h], [w, 0, w + t, h]],
        "doors": [],
        "scenes": {"original": {"furniture": list(furniture), "objects": list(objects)}},
    }
    return parse_world(json.dumps(data), "<box world>")


@pytest.fixture
def empty_room():
    return box_world()


@pytest.fixture
def room_with_table():
    """A coffee table (0.711 × 0.712 m, 0.517 m high) at (3, 2); the robot starts 2 m from it."""
    table = {"id": "table_1", "model": "coffee table", "x": 3.0, "y": 2.0, "yaw": 0.0,
             "facing": None, "room": "room"}
    return box_world([table])


@pytest.fixture
def make_box_world():
    """The :func:`box_world` builder, for tests that need their own layout."""
    return box_world

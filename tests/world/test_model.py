"""Floor-plan queries of the world model: open-plan openings between rooms."""

from __future__ import annotations

import dataclasses

import pytest

from assistant.world.model import Door, Floorplan, Room, Wall


def _plan(walls=(), open_=True, doors=()):
    a = Room("living room", ((0.0, 0.0), (4.0, 0.0), (4.0, 3.0), (0.0, 3.0)), open=open_)
    b = Room("meeting room", ((0.0, 3.0), (4.0, 3.0), (4.0, 6.0), (0.0, 6.0)), open=open_)
    return Floorplan((a, b), tuple(walls), tuple(doors))


def test_an_open_room_meets_its_neighbour_through_an_opening():
    (opening,) = _plan().openings
    assert opening.connects == ("living room", "meeting room")
    assert opening.centre == pytest.approx((2.0, 3.0)) and opening.width_m == pytest.approx(4.0)
    assert [d.name for d in _plan().passages_of("living room")] == [opening.name]


def test_walls_on_the_shared_side_leave_the_longest_free_stretch():
    # a wall over x 0–2.5 of the shared side y = 3: the stretch 2.5–4 is the way through
    (opening,) = _plan(walls=[Wall(0.0, 2.95, 2.5, 3.05)]).openings
    assert opening.centre == pytest.approx((3.25, 3.0)) and opening.width_m == pytest.approx(1.5)
    # a wall all along it: no opening
    assert _plan(walls=[Wall(-0.1, 2.95, 4.1, 3.05)]).openings == ()


def test_closed_rooms_and_rooms_a_door_joins_have_no_opening():
    assert _plan(open_=False).openings == ()
    door = Door("door", (2.0, 3.0), 0.9, ("living room", "meeting room"))
    plan = _plan(doors=[door])
    assert plan.openings == () and plan.passages_of("meeting room") == [door]


def test_the_study_homes_open_plans(all_worlds):
    two = all_worlds["two-bedrooms-house"].floorplan
    names = {frozenset(o.connects) for o in two.openings}
    # the living room runs into the meeting room, which the hallway and the alcove open onto
    assert names == {frozenset(p) for p in (("living room", "meeting room"), ("hallway", "meeting room"),
                                            ("meeting room", "alcove"))}
    living = next(o for o in two.openings if "living room" in o.connects)
    assert living.centre == pytest.approx((0.0, 4.0), abs=0.05)
    # the apartment's rooms are all joined by doors
    assert all_worlds["apartment"].floorplan.openings == ()
    assert dataclasses.is_dataclass(living)


def test_room_graph_joins_rooms_by_doors_and_openings(all_worlds):
    """One room graph: doors always, open-plan openings unless asked not to."""
    for world in all_worlds.values() if isinstance(all_worlds, dict) else all_worlds:
        plan = world.floorplan
        graph = plan.room_graph()
        assert set(graph.nodes) == set(plan.room_names)
        kinds = {data["kind"] for _, _, data in graph.edges(data=True)}
        assert kinds <= {"door", "opening"}
        doors_only = plan.room_graph(openings=False)
        assert all(d["kind"] == "door" for _, _, d in doors_only.edges(data=True))
        assert doors_only.number_of_edges() + len(plan.openings) >= graph.number_of_edges()
        if plan.openings:
            assert any(d["kind"] == "opening" for _, _, d in graph.edges(data=True))
        for _, _, data in graph.edges(data=True):
            assert data["weight"] > 0 and "outside" not in data["door"].connects

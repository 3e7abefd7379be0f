"""``resolve``: the spatial layer's reading of an RDT among perceived furniture.

The furniture here is the world file's (oracle perception): the choice reads only what is
perceived and the pose the command was said from, so no robot is needed.
"""

from __future__ import annotations

import math

import pytest

from assistant.geometry import Pose2D
from assistant.rdt import RDT
from assistant.spatial.resolve import relation_fit, resolve, room_side_fit, wall_fit
from assistant.world import furniture_entities, world_grid

#: at the studio door, looking in (north)
DOOR = Pose2D(-2.1, 0.8, math.pi / 2)


def _room(world, room, scene="original"):
    """The furniture of ``room`` as perception would report it (oracle: the world file's)."""
    items = furniture_entities(world, scene, world_grid(world, 0.05))
    return [e for e in items if (r := world.floorplan.room_at(*e.centre_m)) is not None and r.name == room]


@pytest.fixture(scope="module")
def studio(all_worlds):
    world = all_worlds["hk-studio"]
    return world, _room(world, "studio")


def test_against_the_left_wall_is_the_desk_at_the_west_wall(studio):
    # desk_1 is nearer and on the left too, but it stands off the west wall; desk_2 is against it
    world, furniture = studio
    best = resolve(RDT("wall", "left", "table"), furniture, DOOR, floorplan=world.floorplan)[0]
    assert best.reference is None and best.target.id == "desk_2"
    desks = {e.id: e for e in furniture if e.id.startswith("desk")}
    assert wall_fit(desks["desk_2"], DOOR, "left", world.floorplan) > wall_fit(desks["desk_1"], DOOR, "left", world.floorplan)


def test_room_sides_are_seen_from_the_viewer(studio):
    world, furniture = studio
    tables = {e.id: e for e in furniture if e.name == "table"}
    back = {k: room_side_fit(e, DOOR, "back", world.floorplan) for k, e in tables.items()}
    left = {k: room_side_fit(e, DOOR, "left", world.floorplan) for k, e in tables.items()}
    assert back["desk_2"] > back["desk_1"]  # the far end
    assert left["desk_1"] > left["hexagontable_1"] and left["desk_2"] > left["hexagontable_1"]
    # turned round, the back is the front
    behind = Pose2D(DOOR.x, DOOR.y, -math.pi / 2)
    assert room_side_fit(tables["desk_2"], behind, "front", world.floorplan) == pytest.approx(back["desk_2"], abs=0.05)


def test_every_relation_of_the_node_counts(studio):
    # "the desk next to the wooden chair at the back on the left": both desks have a chair
    world, furniture = studio
    beside = RDT("chair", "beside", "table")
    others = [RDT("room", "left", "table"), RDT("room", "back", "table")]
    alone = {r.target.id for r in resolve(beside, furniture, DOOR, floorplan=world.floorplan)[:1]}
    both = resolve(beside, furniture, DOOR, floorplan=world.floorplan, also=others)
    assert both[0].target.id == "desk_2"
    assert alone  # without the other relations some desk wins too; with them, the far-left one


def test_a_prior_from_the_words_reorders_the_targets(studio):
    world, furniture = studio
    rdt = RDT("room", "center", "table")
    plain = resolve(rdt, furniture, DOOR, floorplan=world.floorplan)
    top = plain[0].target.id
    demoted = resolve(rdt, furniture, DOOR, floorplan=world.floorplan,
                      prior=lambda e: 0.01 if e.id == top else 1.0)
    assert demoted[0].target.id != top


def test_left_of_the_bed_is_the_beds_own_left(apartment):
    furniture = _room(apartment, "bedroom")
    viewer = Pose2D(5.0, -1.8, -math.pi / 2)
    left = resolve(RDT("bed", "left", "table"), furniture, viewer, floorplan=apartment.floorplan)[0]
    right = resolve(RDT("bed", "right", "table"), furniture, viewer, floorplan=apartment.floorplan)[0]
    # the bed faces south (-90°): its left is east (coffeetable_2), its right west (roundtable_2)
    assert left.target.id == "coffeetable_2" and right.target.id == "roundtable_2"
    assert left.reference.name == "bed"


def test_the_back_wall_is_the_far_wall_as_one_enters(apartment):
    # the living room seen from its door (south side, looking north): the dinner table stands
    # near the far (north) wall, the round table near the door's own wall
    door = Pose2D(4.5, 1.8, math.pi / 2)
    best = resolve(RDT("wall", "back", "table"), _room(apartment, "living room"), door,
                   floorplan=apartment.floorplan)[0]
    assert best.target.id == "dinnertable_1"


def test_in_front_of_the_couch_is_read_from_the_couchs_front(apartment):
    furniture = _room(apartment, "living room")
    door = Pose2D(4.5, 1.8, math.pi / 2)
    readings = resolve(RDT("couch", "front", "table"), furniture, door, floorplan=apartment.floorplan)
    couch = readings[0].reference
    assert couch.name == "couch"
    tx, ty = readings[0].target.centre_m
    cx, cy = couch.centre_m
    ahead = math.cos(math.atan2(ty - cy, tx - cx) - couch.orientation_rad)
    assert ahead > 0.5  # the chosen table is on the couch's front side
    # and the same table is not what "behind the couch" means
    behind = resolve(RDT("couch", "back", "table"), furniture, door, floorplan=apartment.floorplan)
    assert behind[0].target.id != readings[0].target.id or behind[0].fit < readings[0].fit


def test_fits_are_in_zero_one_and_nothing_perceived_is_no_reading(apartment):
    furniture = _room(apartment, "living room")
    viewer = Pose2D(4.5, 1.8, math.pi / 2)
    for rdt in [RDT("couch", "front", "table"), RDT("robot", "left", "table"), RDT("couch", "beside", "table"),
                RDT("chair", "between", "table"), RDT("room", "back", "table"), RDT("wall", "left", "table")]:
        for reading in resolve(rdt, furniture, viewer, floorplan=apartment.floorplan):
            assert 0.0 < reading.fit <= 1.0, (rdt, reading)
    assert resolve(RDT("bed", "left", "table"), furniture, viewer) == []  # no bed in view
    assert resolve(RDT("couch", "front", "desk"), furniture, viewer) == []  # no such target
    table = next(e for e in furniture if e.name == "table")
    assert relation_fit(RDT("robot", "front", "table"), None, table, viewer) > 0


def test_a_reference_fused_with_its_neighbour_is_read_as_the_item_it_is(all_worlds):
    """Perception may report an L of two couches as one couch track whose cells reach over the
    other couch; "in front of the couch" is still the table before the couch the track is
    centred on, not a table by the far end of the other couch."""
    import dataclasses

    import numpy as np

    from assistant.world.entity import as_item

    world = all_worlds["two-bedrooms-house"]
    items = {e.id: e for e in _room(world, "living room")}
    couch, other = items["couch_1"], items["couch_2"]
    cells = np.unique(np.vstack([couch.cells, other.cells]), axis=0)
    cx, cy = couch.centre_m
    fused = dataclasses.replace(couch, id="track:0", cells=cells, category="couch",
                                attributes={"x": cx, "y": cy})
    assert len(as_item(fused).cells) < len(cells)  # the other couch's far end is not this couch
    assert len(as_item(dataclasses.replace(fused, cells=couch.cells)).cells) == len(couch.cells)
    tables = [e for e in items.values() if e.name == "table"]
    viewer = Pose2D(-1.0, 3.34, -1.0)
    best = resolve(RDT("couch", "front", "table"), [fused, *tables], viewer, floorplan=world.floorplan)[0]
    assert best.target.id == "roundtable_1"

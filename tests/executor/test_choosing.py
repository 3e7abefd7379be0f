"""How a static node picks its target among perceived furniture, and whether the robot sees it
(no robot needed: the choice reads only perception and the pose the command was said from)."""

from __future__ import annotations

import math

import pytest

from assistant.executor.choosing import PlaceChooser, Said
from assistant.executor.sensing import OracleFurniture
from assistant.executor.viewing import clear_sight, in_view
from assistant.geometry import Pose2D
from assistant.grounding import RDT


def _chooser(world) -> PlaceChooser:
    return PlaceChooser(world, OracleFurniture(world, "original"))


@pytest.fixture
def studio(all_worlds):
    return _chooser(all_worlds["hk-studio"])


#: at the studio door, looking in (north)
DOOR = Pose2D(-2.1, 0.8, math.pi / 2)
DESK = Said("desk")


def test_against_the_left_wall_is_the_desk_at_the_west_wall(studio):
    # desk_1 is nearer and on the left too, but it stands off the west wall; desk_2 is against it
    ref, target, _ = studio.choose_pair(RDT("wall", "left", "table"), "studio", DOOR, said=DESK)
    assert ref is None and target.id == "desk_2"
    # and the right wall is another table: the side said decides
    assert studio.choose_pair(RDT("wall", "right", "table"), "studio", DOOR, said=DESK)[1].id != "desk_2"


def test_every_pair_of_the_node_counts(studio):
    # "the desk next to the wooden chair at the back on the left": both desks have a chair
    beside = RDT("chair", "beside", "table")
    others = [RDT("room", "left", "table"), RDT("room", "back", "table")]
    assert studio.choose_pair(beside, "studio", DOOR, others, DESK)[1].id == "desk_2"


def test_the_back_wall_is_the_far_wall_as_one_enters(all_worlds):
    # the apartment's living room seen from its door (south side, looking north): the dinner
    # table stands near the far (north) wall, the round table near the door's own wall
    chooser = _chooser(all_worlds["apartment"])
    door = Pose2D(4.5, 1.8, math.pi / 2)
    _, target, _ = chooser.choose_pair(RDT("wall", "back", "table"), "living room", door)
    assert target.id == "dinnertable_1"


def test_left_of_the_bed_is_the_beds_own_left(apartment):
    chooser = _chooser(apartment)
    pose = Pose2D(5.0, -1.8, -math.pi / 2)
    left = chooser.choose_pair(RDT("bed", "left", "table"), "bedroom", pose)
    right = chooser.choose_pair(RDT("bed", "right", "table"), "bedroom", pose)
    # the bed faces south (-90°): its left is east (coffeetable_2), its right west (roundtable_2)
    assert left[0].id == "bed_1" and left[1].id == "coffeetable_2" and right[1].id == "roundtable_2"


def test_nothing_to_choose_when_the_reference_is_not_seen(apartment):
    chooser = _chooser(apartment)
    assert chooser.choose_pair(RDT("couch", "front", "table"), "bedroom", Pose2D(5.0, -1.8, 0.0)) is None


def test_the_words_said_pick_among_look_alikes(all_worlds):
    # "the desk" vs any table, in the studio from its door: the desk word favours a desk
    chooser = _chooser(all_worlds["hk-studio"])
    tables = chooser.in_room("studio", "table")
    desks = [e for e in tables if e.id.startswith("desk")]
    others = [e for e in tables if not e.id.startswith("desk")]
    assert desks and others
    assert min(DESK.fit(e) for e in desks) > max(DESK.fit(e) for e in others)
    assert all(Said().fit(e) == 1.0 for e in tables)
    surfaces = chooser.likely_surfaces("studio", "table", DOOR, DESK)
    assert surfaces[0].id.startswith("desk")


def test_other_furniture_on_the_line_of_sight_hides_the_target(all_worlds):
    world = all_worlds["apartment"]
    chooser = _chooser(world)
    furniture = chooser.perception.furniture()
    table = next(e for e in chooser.in_room("living room", "table") if e.id == "roundtable_1")  # (4.0, 2.0)
    # from the couch's far side (couch_1 spans x 3.47–5.53 at y ≈ 3), the couch is in the way
    assert not clear_sight(table, 4.0, 3.9, furniture)
    # from the south-west, over open floor, nothing is
    assert clear_sight(table, 2.8, 1.6, furniture)
    assert not in_view(table, Pose2D(4.0, 3.9, -math.pi / 2), furniture, 1.8)
    assert in_view(table, Pose2D(2.8, 1.6, math.atan2(0.4, 1.2)), furniture, 1.8)
    # facing away from it, it is not in view either
    assert not in_view(table, Pose2D(2.8, 1.6, math.atan2(0.4, 1.2) + math.pi), furniture, 1.8)


def _seen(world, perception, *sightings):
    from assistant.executor.sightings import place_sightings

    return {s.name: s for s in place_sightings(world, perception.furniture(), list(sightings))}


def test_an_object_seen_is_a_landmark(apartment):
    """"the table next to the keys": the keys the object detector saw single out their table among
    the living room's three; an object not seen is no reference (the node's other pairs decide)."""
    from assistant.perception.objects import Sighting

    perception = OracleFurniture(apartment, "lived-in")
    door = Pose2D(4.5, 1.8, math.pi / 2)
    for name, x, y, table in (("keys", 4.13, 2.05, "roundtable_1"), ("wallet", 4.7, 4.08, "coffeetable_1"),
                              ("cell phone", 4.72, 7.09, "dinnertable_1")):
        chooser = PlaceChooser(apartment, perception, _seen(apartment, perception, Sighting(name, x, y, 0.75)))
        ref, target, fit = chooser.choose_pair(RDT(name, "beside", "table"), "living room", door)
        assert ref.id == f"object:{name}" and ref.name == name and target.id == table and fit > 0.3
        assert chooser.in_room("living room", name) and not chooser.in_room("bedroom", name)
        # a landmark is never a surface to search
        assert all(not e.id.startswith("object:") for e in chooser.likely_surfaces("living room", "table", door))
    blind = PlaceChooser(apartment, perception)
    assert blind.choose_pair(RDT("keys", "beside", "table"), "living room", door) is None


def test_an_object_landmark_and_a_furniture_pair_agree(apartment):
    # "the table by the wallet in front of the couch": both relations read the coffee table
    from assistant.perception.objects import Sighting

    perception = OracleFurniture(apartment, "lived-in")
    chooser = PlaceChooser(apartment, perception, _seen(apartment, perception, Sighting("wallet", 4.7, 4.08, 0.75)))
    door = Pose2D(4.5, 1.8, math.pi / 2)
    _, target, _ = chooser.choose_pair(RDT("wallet", "beside", "table"), "living room", door,
                                       [RDT("couch", "front", "table")])
    assert target.id == "coffeetable_1"

import math

import pytest

from assistant.errors import UnknownNameError
from assistant.world import (
    WorldFileError,
    check_world,
    dump_world,
    load_world,
    parse_world,
    world_names,
    write_world,
)

STUDY_HOMES = ["apartment", "hk-studio", "one-bedroom-house", "two-bedrooms-house"]


def test_the_four_study_homes_are_packaged():
    assert set(STUDY_HOMES) <= set(world_names())


@pytest.mark.parametrize("name", STUDY_HOMES)
def test_study_home_has_both_scenes_and_passes_checks(name):
    world = load_world(name)
    assert {"original", "modified"} <= set(world.scenes)
    assert check_world(world) == []
    study = {"fork", "glasses case", "laptop", "monitor", "mug", "statue"}
    for scene in (world.scene("original"), world.scene("modified")):  # as the dissertation has them
        assert len(scene.objects) == 6
        assert {o.name for o in scene.objects} == study
    # the lived-in scene: the original furniture, the study's objects and everyday things
    lived = world.scene("lived-in")
    assert lived.furniture == world.scene("original").furniture
    assert study < {o.name for o in lived.objects}
    assert {"keys", "wallet", "cell phone", "book", "remote"} <= {o.name for o in lived.objects}


@pytest.mark.parametrize("name", STUDY_HOMES)
def test_world_round_trips(name, tmp_path):
    world = load_world(name)
    path = write_world(world, tmp_path / f"{name}.yaml")
    again = load_world(path)
    assert again == world
    assert dump_world(again) == dump_world(world)


def test_facts_of_the_apartment(apartment):
    assert apartment.start.as_tuple() == pytest.approx((5.0, 0.0, 3.142 - 2 * math.pi))
    scene = apartment.scene("original")
    couch = scene.item("couch_1")
    assert (couch.x, couch.y, couch.facing_rad) == (4.5, 3.0, 1.571)
    assert couch.category == "couch" and couch.word == "couch"
    assert scene.item("dinnertable_1").category == "large table"
    assert scene.object("glasses case").on == "coffeetable_1"
    assert apartment.floorplan.room_at(4.5, 4.0).name == "living room"
    assert apartment.floorplan.room_at(0.0, -5.0).name == "bedroom"
    moved = apartment.scene("modified").item("roundtable_2")
    assert (moved.x, moved.y) == (3.9, -3.0)


def test_unknown_world_lists_the_known_ones():
    with pytest.raises(UnknownNameError) as info:
        load_world("apartmnet")
    assert "apartment" in str(info.value) and "hk-studio" in str(info.value)


def _broken(apartment, old: str, new: str) -> str:
    text = dump_world(apartment)
    assert old in text
    return text.replace(old, new, 1)


@pytest.mark.parametrize("old,new,message", [
    ("yaw: 1.571, facing: 1.571", "yaw: north, facing: 1.571",
     "scenes.original.furniture[1].yaw: expected a number, got 'north'"),
    ("model: couch", "model: coutch", "scenes.original.furniture[1].model: unknown model 'coutch' (did you mean 'couch'?)"),
    ("room: living room}", "rom: living room}", "scenes.original.furniture[0].rom: unknown key (did you mean 'room'?)"),
    ("'on': dinnertable_1", "'on': dinertable_1", "scenes.original.objects[0].on: no furniture 'dinertable_1'"),
    ("connects: [hallway, living room]", "connects: [hallway, livingroom]", "doors[0].connects[1]: unknown room 'livingroom'"),
    ("start: {x: 5.0, y: 0.0, heading: 3.142}", "start: {x: 5.0, y: 0.0}", "start.heading: missing"),
    ("- [-5.0, 1.258, 2.023, 1.308]", "- [-5.0, 1.258, -6.0, 1.308]", "walls[0]: expected a wall block"),
    ("facing: 1.571, room: living room", "facing: 0.0, room: living room", "scenes.original.furniture[1].facing: a couch placed at yaw 1.571 faces"),
])
def test_broken_world_file_names_file_section_index_and_key(apartment, tmp_path, old, new, message):
    path = tmp_path / "broken.yaml"
    path.write_text(_broken(apartment, old, new))
    with pytest.raises(WorldFileError) as info:
        load_world(path)
    assert str(info.value).startswith("broken.yaml: ")
    assert message in str(info.value)


def test_not_yaml_and_missing_file(tmp_path):
    bad = tmp_path / "bad.yaml"
    bad.write_text("name: [unclosed\n")
    with pytest.raises(WorldFileError, match="bad.yaml: line .*not valid YAML"):
        load_world(bad)
    with pytest.raises(WorldFileError, match="no such file"):
        load_world(tmp_path / "missing.yaml")
    (tmp_path / "list.yaml").write_text("- 1\n- 2\n")
    with pytest.raises(WorldFileError, match="expected a mapping"):
        load_world(tmp_path / "list.yaml")


def test_checks_find_a_floating_object_and_an_unreachable_room(apartment):
    text = _broken(apartment, "{name: laptop, 'on': dinnertable_1, x: 4.5, y: 7.0}",
                   "{name: laptop, 'on': dinnertable_1, x: 2.0, y: 2.0}")
    # close the living-room door with a wall block
    text = text.replace("walls:\n", "walls:\n- [2.0, 1.2, 3.3, 1.35]\n", 1)
    problems = [str(p) for p in check_world(parse_world(text))]
    assert any("laptop at (2.0, 2.0) is not on dinnertable_1" in p for p in problems)
    assert any("cannot reach the living room" in p for p in problems)


def test_the_key_on_and_yes_no_values_are_read_as_written(tmp_path):
    """YAML 1.1 reads on/off/yes/no as booleans: an object's ``on: couch_1`` written without
    quotes was refused as the unknown key ``True`` (the file's own keys list 'on')."""
    from assistant.fileio import read_yaml

    text = dump_world(load_world("apartment")).replace("'on':", "on:")
    assert "'on'" not in text
    path = tmp_path / "mine.yaml"
    path.write_text(text)
    assert load_world(path) == load_world("apartment")
    assert read_yaml("say: no\nopen: true\nloud: off") == {"say": "no", "open": True, "loud": "off"}

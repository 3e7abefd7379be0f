"""Placing object sightings: room from the floor plan, support from perceived furniture."""

from assistant.executor.sightings import place_sightings
from assistant.perception.objects import Sighting
from assistant.world import furniture_entities, world_grid


def _seen(name, x, y):
    return Sighting(name, x, y, 0.8, 1.5, 300, 12.0)


def test_objects_on_furniture_get_room_and_support(apartment):
    grid = world_grid(apartment)
    furniture = furniture_entities(apartment, "original", grid)
    placed = place_sightings(apartment, furniture, [_seen("laptop", 4.5, 7.0), _seen("mug", -1.2, -5.0)])
    assert [(p.name, p.room, p.furniture_id) for p in placed] == [
        ("laptop", "living room", "dinnertable_1"), ("mug", "bedroom", "hexagontable_1")]
    assert placed[0].to_dict()["furniture"] == placed[0].furniture_category


def test_without_perceived_furniture_only_the_room_is_known(apartment):
    (placed,) = place_sightings(apartment, [], [_seen("mug", -1.2, -5.0)])
    assert placed.room == "bedroom" and placed.furniture_id is None and placed.furniture_category is None


def test_a_thing_between_a_chair_and_its_table_is_on_the_table(apartment):
    # the bedroom's wood chair stands pushed to the hexagon table: a mug seen 0.1 m from the
    # chair's footprint and 0.2 m from the table's is on the table
    grid = world_grid(apartment)
    furniture = furniture_entities(apartment, "original", grid)
    (placed,) = place_sightings(apartment, furniture, [_seen("mug", -1.2, -4.4)])
    assert placed.furniture_id == "hexagontable_1"
    (alone,) = place_sightings(apartment, [f for f in furniture if f.id != "hexagontable_1"],
                               [_seen("mug", -1.2, -4.4)])
    assert alone.furniture_id == "woodchair_1"  # with no table perceived, the chair it is

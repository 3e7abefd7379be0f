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

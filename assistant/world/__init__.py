"""Floor plans, world files, the furniture catalogue and entities."""

from assistant.world.catalogue import CATEGORIES, Catalogue, FurnitureModel, ObjectModel, load_catalogue
from assistant.world.checks import Problem, check_world, occupancy
from assistant.world.entities import floorplan_entities, furniture_entities, world_grid
from assistant.world.entity import ROBOT_RADIUS_M, Entity, EntityKind
from assistant.world.environment import EnvironmentModel
from assistant.world.model import (
    Door,
    Floorplan,
    FurnitureItem,
    PlacedObject,
    Room,
    Scene,
    Wall,
    World,
)
from assistant.world.worldfile import (
    WorldFileError,
    dump_world,
    load_world,
    parse_world,
    world_names,
    write_world,
)

__all__ = [
    "CATEGORIES", "Catalogue", "Door", "Entity", "EntityKind", "EnvironmentModel", "Floorplan", "FurnitureItem",
    "FurnitureModel", "ObjectModel", "PlacedObject", "Problem", "ROBOT_RADIUS_M", "Room",
    "Scene", "Wall", "World", "WorldFileError", "check_world", "dump_world", "floorplan_entities",
    "furniture_entities", "load_catalogue", "load_world", "occupancy", "parse_world",
    "world_grid", "world_names", "write_world",
]

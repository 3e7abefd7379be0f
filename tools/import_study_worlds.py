"""Write the product's world files from the study-world facts (run once by a developer).

    python tools/import_study_worlds.py ../shared/worlds/study_worlds.json

Reads the facts (rooms, walls, doors, furniture poses, objects, start poses) and writes
``assistant/world/data/worlds/<name>.yaml`` in the product's own world-file format.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from assistant.geometry import Pose2D
from assistant.world.model import Door, Floorplan, FurnitureItem, PlacedObject, Room, Scene, Wall, World
from assistant.world.worldfile import world_directory, write_world

TITLES = {
    "apartment": "Apartment: a hallway between a living room and a bedroom",
    "hk-studio": "Studio flat with a meeting room, a hallway and an office",
    "one-bedroom-house": "One-bedroom house: hallway, living room, office, meeting room, bedroom",
    "two-bedrooms-house": "Two-bedroom house: living and meeting rooms, an inner hall and three rooms",
}


# The facts name one door's side "hallway (entry)/living room"; the door at x = 3.1 opens
# from the living room (x 2.6–5.125), so the world file says so.
DOOR_SIDE_FIXES = {("one-bedroom-house", "hallway (entry)/living room"): "living room"}


def rect_polygon(r):
    xmin, ymin, xmax, ymax = r
    return ((xmin, ymin), (xmax, ymin), (xmax, ymax), (xmin, ymax))


def convert(name: str, facts: dict) -> World:
    base = facts["original"]
    plan = Floorplan(
        tuple(Room(r["name"], rect_polygon(r["rect"]), bool(r.get("open"))) for r in base["rooms"]),
        tuple(dict.fromkeys(Wall(*w) for w in base["walls"])),  # drop exact duplicates
        tuple(Door(d["name"], tuple(d["centre"]), d["width"],
                   tuple(DOOR_SIDE_FIXES.get((name, c), c) for c in d["connects"]))
              for d in base["doors"]),
    )
    scenes = {}
    for scene_name, scene in facts.items():
        furniture = tuple(
            FurnitureItem(f["id"], f["model"], f["x"], f["y"], f["yaw"], f["facing"], f["room"])
            for f in scene["furniture"]
        )
        objects = tuple(PlacedObject(o["name"], o["on"], o["x"], o["y"]) for o in scene["objects"])
        scenes[scene_name] = Scene(scene_name, furniture, objects)
    start = base["start"]
    return World(name, plan, Pose2D(start["x"], start["y"], start["yaw"]), start["yaw"], scenes, TITLES[name])


def main(path: str) -> None:
    data = json.loads(Path(path).read_text())
    for name, facts in data["worlds"].items():
        out = write_world(convert(name, facts), world_directory() / f"{name}.yaml")
        print("wrote", out)


if __name__ == "__main__":
    main(sys.argv[1])

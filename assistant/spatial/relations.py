"""Relations between the furniture of a world file (``assistant relations``).

For every room, every ordered pair of distinct furniture items in it gets a DIR-SRV and a
DIST-SRV: ``described`` with respect to ``reference``. Front-less references (tables) are
read from the viewer's side, the viewer being the robot at its start pose in the world file
(see :mod:`assistant.spatial.srv`). Uses the ground-truth furniture of the world file, so it
shows what the spatial layer makes of a known layout — not what the robot perceives.
"""

from __future__ import annotations

from assistant.spatial.forces import DEFAULT_DIRECTIONS
from assistant.spatial.srv import dir_srv, dist_srv

DEFAULT_RESOLUTION_M = 0.05


def relations(world, scene: str = "original", resolution_m: float = DEFAULT_RESOLUTION_M,
              viewer_heading_rad: float | None = None, directions: int = DEFAULT_DIRECTIONS,
              reference: str | None = None) -> list[dict]:
    """One dict per (reference, described) furniture pair of each room: ``room``,
    ``reference``/``described`` (furniture ids), their words, ``frame`` (``intrinsic`` or
    ``viewer``), ``dir`` {front … inner-right}, ``dist`` {superposition … far}, and the
    strongest ``direction`` and ``distance`` words. ``viewer_heading_rad`` defaults to the
    world's start heading. ``reference`` keeps only pairs whose reference id or word matches.
    """
    from assistant.world import furniture_entities, world_grid

    if viewer_heading_rad is None:
        viewer_heading_rad = world.start.theta
    grid = world_grid(world, resolution_m)
    entities = furniture_entities(world, scene, grid)
    rooms: dict[str, list] = {}
    for ent in entities:
        rooms.setdefault(ent.room, []).append(ent)
    out = []
    room_order = [r for r in world.floorplan.room_names if r in rooms] + \
        [r for r in rooms if r not in world.floorplan.room_names]
    for room in room_order:
        items = rooms[room]
        for ref in items:
            if reference is not None and reference not in (ref.id, ref.name):
                continue
            for desc in items:
                if desc is ref:
                    continue
                d = dir_srv(ref, desc, viewer_heading_rad, directions)
                dist = dist_srv(ref, desc)
                out.append({
                    "room": room,
                    "reference": ref.id,
                    "reference_word": ref.name,
                    "described": desc.id,
                    "described_word": desc.name,
                    "frame": d.frame,
                    "dir": d.as_dict(),
                    "dist": dist.as_dict(),
                    "direction": d.strongest()[0],
                    "distance": dist.strongest()[0],
                })
    return out

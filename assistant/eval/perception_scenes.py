"""Environment modelling of in-room scenes (dissertation 3.7.3, Table 3-9).

Sixteen furniture clusters of the four study homes (two or three items each, the scenes of
Table 3-9). For each, the simulated robot looks at the cluster from free spots around it in
its room, the detector's entities are fused by the :class:`EnvironmentModel`, and the result is
compared with the world file: position error, orientation error, and whether the spatial
relations between the detected items match the true ones (the strongest DIR-SRV label of
every pair whose reference has a front, from :mod:`assistant.spatial`).
"""

from __future__ import annotations

import math

import numpy as np

from assistant.geometry import Pose2D

#: (world, furniture ids) of the 16 scenes, in Table 3-9's order
SCENES = (
    ("apartment", ("couch_1", "roundtable_1", "coffeetable_1")),
    ("apartment", ("dinnertable_1", "bluechair_2")),
    ("apartment", ("hexagontable_1", "woodchair_2", "woodchair_1")),
    ("apartment", ("bed_1", "roundtable_2")),
    ("hk-studio", ("bluechair_1", "dinnertable_1")),
    ("hk-studio", ("couch_1", "coffeetable_1")),
    ("hk-studio", ("bluechair_3", "desk_3")),
    ("hk-studio", ("woodchair_3", "hexagontable_1")),
    ("one-bedroom-house", ("roundtable_1", "couch_1", "bluechair_1")),
    ("one-bedroom-house", ("bluechair_2", "desk_1")),
    ("one-bedroom-house", ("woodchair_1", "roundtable_4")),
    ("one-bedroom-house", ("bluechair_3", "coffeetable_2")),
    ("two-bedrooms-house", ("couch_2", "roundtable_2", "hexagontable_1")),
    ("two-bedrooms-house", ("dinnertable_1", "bluechair_2")),
    ("two-bedrooms-house", ("bluechair_3", "desk_1")),
    ("two-bedrooms-house", ("couch_1", "roundtable_1")),
)


def viewpoints(world, scene: str, items, radii=(1.3, 1.6, 2.0, 2.4, 2.8, 3.2, 3.6), count: int = 6,
               clearance_m: float = 0.3, preferred_m: float = 2.6) -> list[Pose2D]:
    """Up to ``count`` robot poses looking at the cluster's centre from free floor in any room
    (through a door is fine, through a wall is not), spread around it (at least 50° apart; radius nearest ``preferred_m`` first), with no wall
    in between."""
    from assistant.world import occupancy

    centre = np.mean([[i.x, i.y] for i in items], axis=0)
    grid, blocked = occupancy(world, scene, 0.05, clearance_m)
    walls_grid, walls = occupancy_walls(world)
    found: list[tuple[float, float, Pose2D]] = []
    for r in radii:
        for deg in range(0, 360, 15):
            a = math.radians(deg)
            x, y = centre[0] + r * math.cos(a), centre[1] + r * math.sin(a)
            if world.floorplan.room_at(x, y) is None:
                continue
            cell = grid.world_to_cell(np.array([[x, y]]))
            if not grid.contains_cells(cell)[0] or blocked[cell[0, 0], cell[0, 1]]:
                continue
            line = np.linspace([x, y], centre, 40)
            cells = walls_grid.world_to_cell(line)
            ok = walls_grid.contains_cells(cells)
            if walls[cells[ok, 0], cells[ok, 1]].any():
                continue
            found.append((abs(r - preferred_m), a, Pose2D(x, y, math.atan2(centre[1] - y, centre[0] - x))))
    found.sort(key=lambda t: t[0])
    chosen: list[tuple[float, Pose2D]] = []
    for _, a, pose in found:
        if all(abs((a - b + math.pi) % (2 * math.pi) - math.pi) > math.radians(50) for b, _ in chosen):
            chosen.append((a, pose))
        if len(chosen) == count:
            break
    return [p for _, p in chosen]


def occupancy_walls(world):
    from assistant.world import world_grid

    grid = world_grid(world, 0.05)
    mask = np.zeros(grid.shape, dtype=bool)
    for wall in world.floorplan.walls:
        mask |= grid.rasterize_polygon(wall.polygon_array)
    return grid, mask


def _relations(entities) -> dict:
    """Strongest DIR-SRV label of every ordered pair whose reference has a front."""
    from assistant.spatial import dir_srv

    out = {}
    for ref in entities:
        if ref.orientation_rad is None:
            continue
        for other in entities:
            if other is ref:
                continue
            srv = dir_srv(ref, other)
            if srv is not None:
                out[(ref.id, other.id)] = srv.strongest()[0]
    return out


def evaluate_scene(world_name: str, ids, detector, scene: str = "original") -> dict:
    """Explore one cluster, fuse, and score it against the world file."""
    from assistant.sim.renderer import DepthRenderer
    from assistant.world import load_world
    from assistant.world.entities import furniture_entities
    from assistant.world.environment import EnvironmentModel

    world = load_world(world_name)
    items = [world.scene(scene).item(i) for i in ids]
    renderer = DepthRenderer(world, scene, seed=0)
    model = EnvironmentModel(world)
    poses = viewpoints(world, scene, items)
    for pose in poses:
        model.update(detector.detect(renderer.render(pose), model.grid), pose)
    fused = model.furniture()
    truth = {e.id: e for e in furniture_entities(world, scene, model.grid) if e.id in ids}
    rows, matched = [], {}
    for item in items:
        best = min(fused, key=lambda e: np.linalg.norm(_position(e) - [item.x, item.y]), default=None)
        row = {"id": item.id, "category": item.category, "truth": [item.x, item.y, item.facing_rad]}
        if best is None or np.linalg.norm(_position(best) - [item.x, item.y]) > 0.8 or best.id in matched.values():
            row.update({"detected": None})
        else:
            matched[item.id] = best.id
            pos = _position(best)
            row.update({"detected": [round(float(pos[0]), 3), round(float(pos[1]), 3),
                                     None if best.orientation_rad is None else round(best.orientation_rad, 3)],
                        "detected_category": best.category,
                        "word_right": best.name == item.word,
                        "position_error_m": round(float(np.linalg.norm(pos - [item.x, item.y])), 3)})
            if item.facing_rad is not None and best.orientation_rad is not None:
                err = abs((best.orientation_rad - item.facing_rad + math.pi) % (2 * math.pi) - math.pi)
                row["orientation_error_rad"] = round(err, 3)
        rows.append(row)
    sr_match = None
    if len(matched) == len(items):
        truth_rel = _relations([truth[i] for i in ids])
        by_id = {e.id: e for e in fused}
        renamed = []
        for i in ids:  # the detected entity under the true id, so pairs line up
            e = by_id[matched[i]]
            renamed.append(type(e)(i, e.name, e.kind, e.grid, e.cells, e.orientation_rad,
                                   category=e.category, room=e.room, confidence=e.confidence,
                                   attributes=e.attributes))
        det_rel = _relations(renamed)
        sr_match = bool(truth_rel == det_rel and all(r.get("word_right") for r in rows))
    return {"world": world_name, "items": rows, "views": len(poses), "sr_match": sr_match,
            "extra_entities": len(fused) - len(matched)}


def _position(entity) -> np.ndarray:
    """The fused detection centre (or the footprint's centroid)."""
    if "x" in entity.attributes:
        return np.array([entity.attributes["x"], entity.attributes["y"]])
    return entity.centroid_m

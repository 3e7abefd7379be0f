"""Geometry rules every world must meet when it is loaded: a house, not just valid YAML.

The world-file schema checks types; these rules check sizes and places, so a world that would
make a later step take gigabytes or crash is refused at load with the file, section and index:
coordinates within :data:`MAX_COORDINATE_M` of the origin, a plan at most :data:`MAX_EXTENT_M`
across, rooms of at least :data:`MIN_ROOM_AREA_M2` that do not cross themselves, the start pose
and every piece of furniture in (or within :data:`ROOM_TOLERANCE_M` of) a room — its own room
for furniture — and no two pieces of furniture overlapping by more than
:data:`MAX_OVERLAP_M2`. (:func:`assistant.world.checks.check_world` adds the slower checks:
objects on their furniture, every room reachable.)
"""

from __future__ import annotations

import numpy as np

from assistant.geometry.shapes import point_in_polygon, polygon_area, polygon_lattice

#: largest coordinate accepted (metres from the world origin)
MAX_COORDINATE_M = 1000.0
#: largest width or depth of a whole floor plan (metres)
MAX_EXTENT_M = 100.0
#: smallest room floor area (square metres)
MIN_ROOM_AREA_M2 = 0.5
#: how far outside its room a piece of furniture's centre (or the start) may lie (metres)
ROOM_TOLERANCE_M = 0.3
#: largest floor area two pieces of furniture may share (square metres)
MAX_OVERLAP_M2 = 0.05
_LATTICE_M = 0.03


def geometry_problems(world) -> list[tuple[str, str]]:
    """``(where, problem)`` for every rule ``world`` breaks (empty when it is a house)."""
    out: list[tuple[str, str]] = []
    plan = world.floorplan
    for i, room in enumerate(plan.rooms):
        poly = room.polygon_array
        if np.abs(poly).max() > MAX_COORDINATE_M:
            out.append((f"rooms[{i}].polygon", f"coordinates beyond ±{MAX_COORDINATE_M:g} m; "
                        "give metres from a corner of the home"))
            return out  # the other rules would only repeat it
        area = polygon_area(poly)
        if _crosses_itself(poly):
            out.append((f"rooms[{i}].polygon", f"the {room.name}'s outline crosses itself; "
                        "list its corners in order around the room"))
        elif area < MIN_ROOM_AREA_M2:
            out.append((f"rooms[{i}].polygon", f"the {room.name} has {area:.2f} m² of floor; a room "
                        f"needs at least {MIN_ROOM_AREA_M2} m² (are two corners the same?)"))
    for i, wall in enumerate(plan.walls):
        if np.abs(wall.polygon_array).max() > MAX_COORDINATE_M:
            out.append((f"walls[{i}]", f"coordinates beyond ±{MAX_COORDINATE_M:g} m"))
    if out:
        return out
    xmin, ymin, xmax, ymax = plan.bounds()
    if max(xmax - xmin, ymax - ymin) > MAX_EXTENT_M:
        return [("rooms", f"the plan is {xmax - xmin:.0f} m × {ymax - ymin:.0f} m; a home is at most "
                 f"{MAX_EXTENT_M:g} m across (are the coordinates in metres?)")]
    if not any(_near_room(room, world.start.x, world.start.y) for room in plan.rooms):
        out.append(("start", f"({world.start.x}, {world.start.y}) is in no room"))
    for scene_name, scene in world.scenes.items():
        base = f"scenes.{scene_name}.furniture"
        items = list(scene.furniture)
        for i, item in enumerate(items):
            if not _near_room(plan.room(item.room), item.x, item.y):
                out.append((f"{base}[{i}]", f"{item.id} at ({item.x}, {item.y}) is not in the {item.room}; "
                            "fix its x, y or its room"))
        out.extend(_overlaps(items, base))
    return out


def _near_room(room, x: float, y: float) -> bool:
    if room.contains(x, y):
        return True
    poly = room.polygon_array
    a, b = poly, np.roll(poly, -1, axis=0)
    ab = b - a
    t = np.clip(((np.array([x, y]) - a) * ab).sum(axis=1) / np.maximum((ab * ab).sum(axis=1), 1e-12), 0, 1)
    nearest = a + t[:, None] * ab
    return float(np.hypot(*(nearest - [x, y]).T).min()) <= ROOM_TOLERANCE_M


def _crosses_itself(poly: np.ndarray) -> bool:
    """True when two non-adjacent edges of the outline intersect."""
    n = len(poly)
    edges = [(poly[k], poly[(k + 1) % n]) for k in range(n)]

    def orient(p, q, r) -> float:
        return float((q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]))

    for i in range(n):
        for j in range(i + 2, n):
            if i == 0 and j == n - 1:
                continue  # these two share a corner
            (p1, p2), (q1, q2) = edges[i], edges[j]
            d1, d2 = orient(q1, q2, p1), orient(q1, q2, p2)
            d3, d4 = orient(p1, p2, q1), orient(p1, p2, q2)
            if d1 * d2 < 0 and d3 * d4 < 0:
                return True
    return False


def _overlaps(items, base: str) -> list[tuple[str, str]]:
    out = []
    polys = [item.footprint_polygon() for item in items]
    boxes = [(p.min(axis=0), p.max(axis=0)) for p in polys]
    for i in range(len(items)):
        for j in range(i + 1, len(items)):
            lo = np.maximum(boxes[i][0], boxes[j][0])
            hi = np.minimum(boxes[i][1], boxes[j][1])
            if ((hi - lo) <= 0).any() or float(np.prod(hi - lo)) <= MAX_OVERLAP_M2:
                continue
            points = polygon_lattice(polys[i], _LATTICE_M)
            shared = float(point_in_polygon(points, polys[j]).sum()) * _LATTICE_M ** 2 if len(points) else 0.0
            if shared > MAX_OVERLAP_M2:
                out.append((f"{base}[{j}]", f"{items[j].id} overlaps {items[i].id} by {shared:.2f} m²; "
                            "move one of them"))
    return out

"""Seeing the target furniture: whether it is in view, and where to stand to see it.

The fetch ends facing the furniture the object is on. :func:`in_view` says whether the
furniture is near enough, inside the Kinect's field of view and not hidden behind other
perceived furniture (:func:`clear_sight`); :func:`viewing_poses` lists the free poses around
it to drive to when it is not. All of it reads only the floor plan, the perceived furniture
and the occupancy the robot knows.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from scipy.spatial import cKDTree

from assistant.executor.planning import OccupancyMap
from assistant.executor.sensing import entity_centre, entity_polygon, entity_room
from assistant.geometry import Pose2D
from assistant.world import Entity, World
from assistant.world.entity import as_item

__all__ = ["HALF_FOV_RAD", "clear_sight", "in_view", "point_viewing_spot", "viewing_poses"]

#: half the Kinect's horizontal field of view (57°), radians
HALF_FOV_RAD = math.radians(28.5)


def in_view(target: Entity, pose: Pose2D, furniture: Sequence[Entity], view_distance_m: float) -> bool:
    """Whether ``target`` is near enough (``view_distance_m`` from its centre, plus its own
    radius: large tables stand farther off), inside the camera's field of view and not hidden
    behind other perceived ``furniture`` (:func:`clear_sight`) from ``pose``."""
    x, y = entity_centre(target)
    local = pose.to_local(np.array([[x, y]]))[0]
    dist = math.hypot(*local)
    radius = float(np.hypot(*(entity_polygon(target) - [x, y]).T).max())  # large tables stand farther off
    return (dist <= view_distance_m + radius and abs(math.atan2(local[1], local[0])) < HALF_FOV_RAD * 0.8
            and clear_sight(target, pose.x, pose.y, furniture))


def clear_sight(target: Entity, x: float, y: float, furniture: Sequence[Entity], step_m: float = 0.05) -> bool:
    """Whether the straight line from ``(x, y)`` to ``target``'s centre crosses no other
    perceived furniture before it reaches the target's own cells: an arm of the couch
    between the robot and a low table hides what lies on the table. ``furniture``: what
    perception has reported."""
    tx, ty = entity_centre(target)
    length = math.hypot(tx - x, ty - y)
    if length < step_m:
        return True
    t = np.arange(step_m, length, step_m) / length
    line = np.column_stack([x + t * (tx - x), y + t * (ty - y)])
    own = target.points_m()
    if len(own):  # the part of the line over the target itself does not count
        d, _ = cKDTree(own).query(line, k=1)
        line = line[d > target.grid.resolution_m]
    if len(line) == 0:
        return True
    for other in furniture:
        if other.id == target.id:
            continue
        cells = as_item(other).points_m()  # a track that swallowed the target's cells is not in the way
        if len(cells) == 0:
            continue
        lo, hi = cells.min(axis=0) - 0.1, cells.max(axis=0) + 0.1
        near = line[np.all((line >= lo) & (line <= hi), axis=1)]
        if len(near) == 0:
            continue
        d, _ = cKDTree(cells).query(near, k=1)
        if np.any(d <= other.grid.resolution_m * 0.75):  # inside a cell (half its diagonal is 0.71)
            return False
    return True


def viewing_poses(world: World, target: Entity, pose: Pose2D, occupancy: OccupancyMap,
                  furniture: Sequence[Entity], standoff_m: float) -> list[tuple[float, float, float]]:
    """Free poses ``(x, y, heading)`` ``standoff_m`` off the furniture's edge, facing its
    centre, nearest the robot at ``pose`` first; poses out of the target's room, or from which
    other ``furniture`` hides the target, come last."""
    cx, cy = entity_centre(target)
    poly = entity_polygon(target)
    occ = occupancy
    room = entity_room(world, target)
    out = []
    for k in range(16):
        a = 2 * math.pi * k / 16
        u = np.array([math.cos(a), math.sin(a)])
        extent = float(((poly - [cx, cy]) @ u).max())
        for extra in (0.0, 0.25):
            r = extent + standoff_m + extra
            x, y = cx + r * u[0], cy + r * u[1]
            if not occ.is_free(x, y) or float(occ.clearance_at(np.array([[x, y]]))[0]) < 0.35 \
                    or not occ.reachable_from(pose, np.array([[x, y]]))[0]:
                continue
            here = world.floorplan.room_at(x, y)
            penalty = 0.0 if here is not None and here.name == room else 3.0
            if not clear_sight(target, x, y, furniture):  # other furniture in the way: a last resort
                penalty += 2.0
            cost = math.hypot(x - pose.x, y - pose.y) + penalty + extra
            out.append((cost, (x, y, math.atan2(cy - y, cx - x))))
            break
    out.sort(key=lambda c: c[0])
    return [g for _, g in out]


def point_viewing_spot(occupancy: OccupancyMap, pose: Pose2D, xy: tuple[float, float],
                       clearance_m: float, radii_m: Sequence[float] = (1.3, 1.6, 1.9)
                       ) -> tuple[float, float] | None:
    """A free spot (metres) ``radii_m`` from the point ``xy`` (a thing seen from afar), with
    ``clearance_m`` of room and reachable from ``pose``: the cheapest by the way there plus how
    far its distance is from 1.5 m (near enough for the object detector, far enough to see the
    surface it lies on); None when there is none."""
    here = pose
    best = None
    for r in radii_m:
        for a in np.linspace(0, 2 * math.pi, 16, endpoint=False):
            x, y = xy[0] + r * math.cos(a), xy[1] + r * math.sin(a)
            pt = np.array([[x, y]])
            if occupancy.clearance_at(pt)[0] < clearance_m or not occupancy.reachable_from(here, pt)[0]:
                continue
            cost = math.hypot(x - here.x, y - here.y) + abs(r - 1.5)
            if best is None or cost < best[0]:
                best = (cost, x, y)
    return None if best is None else (best[1], best[2])

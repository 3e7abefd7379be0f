"""How a person walks into a room: the rooms on the way, and the heading they enter with.

Both the static description ("against the left wall" is named as one walks in) and the
how-to-find steps ("go into the living room, turn right") read the room from the side a person
enters by: through the door, or open-plan opening, on the way from where the listener stands.
"""

from __future__ import annotations

import math

import networkx as nx

__all__ = ["entry_heading", "inward_heading", "room_path"]


def room_path(floorplan, pose, room: str) -> list[str] | None:
    """Rooms from the one holding ``pose`` to ``room`` (both included), or None."""
    here = floorplan.room_at(pose.x, pose.y)
    if here is None:
        return None
    try:
        return nx.shortest_path(floorplan.room_graph(), here.name, room)  # fewest rooms, as a person counts
    except nx.NetworkXNoPath:
        return None


def entry_heading(floorplan, room: str, listener_pose=None) -> float | None:
    """The heading (radians) of a person entering ``room``: through the door (or open-plan
    opening, :attr:`~assistant.world.Floorplan.openings`) on the way from the listener (if
    given and elsewhere), else the room's first door; the listener's own heading when they
    are already inside; None when it cannot be told."""
    r = floorplan.room(room)
    if listener_pose is not None and r.contains(listener_pose.x, listener_pose.y):
        return float(listener_pose.theta)
    doors = floorplan.passages_of(room)  # doors, and open-plan openings: how a person walks in
    if listener_pose is not None and doors:
        path = room_path(floorplan, listener_pose, room)
        if path and len(path) >= 2:
            prev = path[-2]
            doors = [d for d in doors if prev in d.connects] or doors
    doors = [d for d in doors if all(c in floorplan.room_names for c in d.connects)] or doors
    if not doors:
        return None
    return inward_heading(r, doors[0].centre)


def inward_heading(room, point) -> float:
    """Heading perpendicular to the room's nearest bounding-box side at ``point``, pointing in."""
    poly = room.polygon_array
    xmin, ymin = poly.min(axis=0)
    xmax, ymax = poly.max(axis=0)
    x, y = point
    sides = {0.0: abs(x - xmin), math.pi: abs(x - xmax), math.pi / 2: abs(y - ymin),
             -math.pi / 2: abs(y - ymax)}
    return min(sides, key=sides.get)

"""How-to-find steps from the listener's pose (beyond the dissertation, issue item 4).

A dynamic description tells the listener how to get there: "go into the living room, turn
right, the glasses case is on the table in front of the couch". The steps are content nodes
like the static ones: ``room-enter-non`` (key ``enter``) when the listener is elsewhere, then
``move-<left|right|front>-non`` — the side the support is on as the listener enters the room
(or from where they stand, when already inside).
"""

from __future__ import annotations

import math

import networkx as nx
import numpy as np

from assistant.generation.types import ContentNode

__all__ = ["STRAIGHT_RAD", "entry_heading", "inward_heading", "room_path", "route_nodes"]

#: a support within this angle of the walking direction is "straight ahead" (radians)
STRAIGHT_RAD = math.radians(30)


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


def route_nodes(floorplan, listener_pose, support, room: str) -> list[ContentNode]:
    """The how-to-find steps to ``support`` (an entity) in ``room`` from ``listener_pose``."""
    r = floorplan.room(room)
    inside = r.contains(listener_pose.x, listener_pose.y)
    nodes: list[ContentNode] = []
    if inside:
        origin = np.array([listener_pose.x, listener_pose.y])
        heading = float(listener_pose.theta)
    else:
        nodes.append(ContentNode("route", "enter", "room-enter-non", 1.0, {"room": room}))
        heading = entry_heading(floorplan, room, listener_pose)
        path = room_path(floorplan, listener_pose, room) or [room]
        prev = path[-2] if len(path) >= 2 else None
        doors = [d for d in floorplan.passages_of(room) if prev is None or prev in d.connects] or \
            floorplan.passages_of(room)
        if heading is None or not doors:
            return nodes
        origin = np.array(doors[0].centre)
    delta = support.centroid_m - origin
    bearing = math.atan2(delta[1], delta[0]) - heading
    bearing = math.atan2(math.sin(bearing), math.cos(bearing))
    if abs(bearing) <= STRAIGHT_RAD:
        direction = "front"
    elif abs(bearing) >= math.pi - STRAIGHT_RAD and inside:
        direction = "back"
    else:
        direction = "left" if bearing > 0 else "right"
    if direction != "back":
        p = math.cos(bearing) ** 2 if direction == "front" else math.sin(bearing) ** 2
        nodes.append(ContentNode("route", f"move-{direction}", f"move-{direction}-non", float(p),
                                 {"direction": direction}))
    else:
        nodes.append(ContentNode("route", "move-back", "move-back-non", 1.0, {"direction": "back"}))
    return nodes

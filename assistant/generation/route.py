"""How-to-find steps from the listener's pose (beyond the dissertation, issue item 4).

A dynamic description tells the listener how to get there: "go into the living room, turn
right, the glasses case is on the table in front of the couch". The steps are content nodes
like the static ones: ``room-enter-non`` (key ``enter``) when the listener is elsewhere, then
``move-<left|right|front>-non`` — the side the support is on as the listener enters the room
(or from where they stand, when already inside).
"""

from __future__ import annotations

import math

import numpy as np

from assistant.generation.entry import entry_heading, room_path
from assistant.generation.types import ContentNode

__all__ = ["STRAIGHT_RAD", "route_nodes"]

#: a support within this angle of the walking direction is "straight ahead" (radians)
STRAIGHT_RAD = math.radians(30)


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

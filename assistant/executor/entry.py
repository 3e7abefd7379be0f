"""Entering a room: the first step of every robot task, written once.

Through the doors of the room graph first (:meth:`Navigator.enter_room`). When no door leads
there — rooms of an open plan share a boundary with no wall — the robot drives straight to the
free spot well inside the room nearest to it (:func:`drive_inside`). A task that must get into
every room (the search, with ``insist``) also takes a door that depth noise has closed on the
map as a reason to try again: it forgets the obstacle cells seen around the doors on the way
(the floor plan says they are open), tries the doors once more, and then drives inside.
"""

from __future__ import annotations

import math

import numpy as np

from assistant.executor.context import TaskContext
from assistant.executor.outcome import ExecutionResult, ExecutionStatus
from assistant.executor.rooms import RoomGraph, room_of

__all__ = ["clear_doors", "drive_inside", "enter_room"]

#: (inset from the room's bounding box, least clearance), metres: well inside if there is
#: room, else just inside
SPOT_LEVELS = ((0.6, 0.4), (0.3, 0.32))


def enter_room(ctx: TaskContext, room: str, *, insist: bool = False) -> ExecutionResult:
    """Enter ``room`` (module docstring). Without ``insist`` only a missing door (``no_path``
    before driving) leads to driving inside; with it any failure does, after the doors are
    cleared and tried again, and arriving counts only inside a floor-plan room."""
    if insist and room_of(ctx.world, ctx.pose()) == room:
        return ExecutionResult.ok(f"in the {room}")
    entered = ctx.step(ctx.navigator.enter_room(ctx.robot, room))
    if entered.success and (not insist or _inside(ctx, room)):
        return entered
    if not insist:
        if entered.status is not ExecutionStatus.NO_PATH or "goal" in entered.details:
            return entered
        return drive_inside(ctx, room, entered)
    ctx.event("enter_failed", room=room, result=entered)
    if clear_doors(ctx, room):
        entered = ctx.step(ctx.navigator.enter_room(ctx.robot, room))
        if entered.success and _inside(ctx, room):
            return entered
    return drive_inside(ctx, room, entered)


def _inside(ctx: TaskContext, room: str) -> bool:
    pose = ctx.pose()
    return room_of(ctx.world, pose) == room and ctx.world.floorplan.room_at(pose.x, pose.y) is not None


def drive_inside(ctx: TaskContext, room: str, entered: ExecutionResult, tries: int = 4) -> ExecutionResult:
    """Drive to the free, reachable spot inside ``room`` nearest the robot (:data:`SPOT_LEVELS`),
    at most ``tries`` times, each time from the latest occupancy (depth shows more on the way)
    and never again near a spot that failed. ``entered``: the door route's result, returned
    (as ``no_path`` if it had arrived elsewhere) when no spot is reached."""
    poly = ctx.world.floorplan.room(room).polygon_array
    cx, cy = poly.mean(axis=0)
    result = entered
    tried: list[tuple[float, float]] = []
    for _ in range(tries):
        spot = _nearest_free_spot(ctx, poly, tried)
        if spot is None:
            break
        x, y = spot
        tried.append(spot)
        result = ctx.go_to((x, y), math.atan2(cy - y, cx - x), snap_goal=False)
        if room_of(ctx.world, ctx.pose()) == room and (result.success or result.status is ExecutionStatus.NO_PATH):
            # in the room already (the spot aimed at turned out to be taken): good enough to look
            return ExecutionResult.ok(f"entered the {room}", final_pose=ctx.pose(),
                                      details={"room": room, "open_plan": True})
        if result.status is ExecutionStatus.TIMEOUT or result.details.get("bumped"):
            break
    if result.success:  # arrived somewhere, but not in the room
        result = ExecutionResult.failed(ExecutionStatus.NO_PATH, f"no way into the {room} was found",
                                        final_pose=ctx.pose())
    return result


def _nearest_free_spot(ctx: TaskContext, poly: np.ndarray, tried) -> tuple[float, float] | None:
    pose = ctx.pose()
    occ = ctx.obstacles.occupancy()
    for inset, clearance in SPOT_LEVELS:
        lo, hi = poly.min(axis=0) + inset, poly.max(axis=0) - inset
        if np.any(hi < lo):
            lo = hi = poly.mean(axis=0)
        xs, ys = np.meshgrid(np.arange(lo[0], hi[0] + 1e-9, 0.1), np.arange(lo[1], hi[1] + 1e-9, 0.1))
        pts = np.column_stack([xs.ravel(), ys.ravel()])
        keep = (occ.clearance_at(pts) >= clearance) & occ.reachable_from(pose, pts)
        for t in tried:
            keep &= np.hypot(pts[:, 0] - t[0], pts[:, 1] - t[1]) > 0.5
        pts = pts[keep]
        if len(pts):
            x, y = pts[int(np.argmin(np.hypot(pts[:, 0] - pose.x, pts[:, 1] - pose.y)))]
            return float(x), float(y)
    return None


def clear_doors(ctx: TaskContext, room: str) -> bool:
    """Zero the depth-obstacle counts within 1 m of every door of the floor plan on the way to
    ``room`` (all of its doors when the way is unknown); True when any were cleared."""
    here = room_of(ctx.world, ctx.pose())
    doors = RoomGraph(ctx.world).doors_between(here, room) if here else None
    doors = doors or ctx.world.floorplan.doors_of(room)
    obstacles = ctx.obstacles
    grid = obstacles.grid
    cleared = False
    for door in doors:
        cx, cy = door.centre
        xs, ys = np.meshgrid(np.arange(cx - 1.0, cx + 1.0, grid.resolution_m / 2),
                             np.arange(cy - 1.0, cy + 1.0, grid.resolution_m / 2))
        cells = grid.world_to_cell(np.column_stack([xs.ravel(), ys.ravel()]))
        cells = cells[grid.contains_cells(cells)]
        if len(cells) and (obstacles.hits[cells[:, 0], cells[:, 1]] > 0).any():
            obstacles.hits[cells[:, 0], cells[:, 1]] = 0
            cleared = True
    return cleared

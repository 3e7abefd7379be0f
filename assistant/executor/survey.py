"""Where to look from: the fetch task's look-arounds, and the spots it looks again from.

A fetch looks around when it enters the room; in a room too large to see from its door, or
when a node names furniture not seen yet, it looks again from the free spot that brings the
most of the room within perception's reliable range (:meth:`Surveyor.survey`), or from the
middle of the room or the side the command points to (:meth:`Surveyor.better_view`). An item
perception is unsure of is looked at again from another side before a task acts on it
(:meth:`Surveyor.look_again_at`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

from assistant.executor.context import TaskContext
from assistant.executor.outcome import ExecutionResult
from assistant.executor.sensing import entity_centre
from assistant.executor.viewing import viewing_poses
from assistant.geometry import Pose2D, polygon_lattice

__all__ = ["Surveyor"]


@dataclass
class Surveyor:
    """Look-arounds in ``ctx``; ``on_frame(frame, pose)`` perceives each frame of a turn.
    ``survey_range_m`` / ``max_unseen_share``: see :meth:`survey`. ``looked_from``: the poses
    looked around from so far."""

    ctx: TaskContext
    on_frame: Callable
    survey_range_m: float = 4.5
    max_unseen_share: float = 0.5
    looked_from: list[Pose2D] = field(default_factory=list)

    def look_around(self) -> ExecutionResult:
        """A full turn on the spot, perceiving every stop."""
        self.looked_from.append(self.ctx.pose())
        return self.ctx.look_around(self.on_frame)

    def room_points(self, room: str, step_m: float = 0.25) -> np.ndarray:
        """Floor points (N, 2) of ``room`` on a ``step_m`` lattice."""
        r = next((r for r in self.ctx.world.floorplan.rooms if r.name == room), None)
        return np.zeros((0, 2)) if r is None else polygon_lattice(r.polygon_array, step_m)

    def unseen(self, points: np.ndarray, range_m: float) -> np.ndarray:
        """Which ``points`` lie farther than ``range_m`` from every pose the robot has looked
        around from."""
        unseen = np.ones(len(points), dtype=bool)
        for p in self.looked_from:
            unseen &= np.hypot(points[:, 0] - p.x, points[:, 1] - p.y) > range_m
        return unseen

    def survey(self, room: str, toward: tuple[float, float] | None = None,
                max_unseen_share: float | None = None, range_m: float | None = None) -> bool:
        """When more than ``max_unseen_share`` (default :attr:`max_unseen_share`) of a room
        lies beyond ``range_m`` (default :attr:`survey_range_m`) from everywhere the robot has
        looked (the hk-studio studio seen from its door), look again from the free spot that
        brings most of the rest within that range (or the one nearest ``toward``, the side the
        command points to). True when it moved and looked."""
        share = self.max_unseen_share if max_unseen_share is None else max_unseen_share
        range_m = self.survey_range_m if range_m is None else range_m
        pts = self.room_points(room)
        if len(pts) == 0:
            return False
        unseen = self.unseen(pts, range_m)
        if unseen.mean() <= share:
            return False
        if toward is None:
            occ = self.ctx.obstacles.occupancy()
            spots = self.room_points(room, 0.5)
            spots = spots[(occ.clearance_at(spots) >= 0.4) & occ.reachable_from(self.ctx.pose(), spots)]
            if len(spots) == 0:
                return False
            rest = pts[unseen]
            gain = (np.hypot(rest[:, None, 0] - spots[None, :, 0], rest[:, None, 1] - spots[None, :, 1])
                    <= range_m).sum(axis=0)
            toward = tuple(spots[int(np.argmax(gain))])
        self.better_view(room, toward)
        return True

    def better_view(self, room: str, toward: tuple[float, float] | None = None) -> None:
        """Move to the middle of the room — or, given ``toward``, to the free spot of the room
        nearest that point — and look around."""
        r = next((r for r in self.ctx.world.floorplan.rooms if r.name == room), None)
        if r is None:
            return
        cx, cy = r.polygon_array.mean(axis=0)
        if toward is not None:
            occ = self.ctx.obstacles.occupancy()
            lo, hi = r.polygon_array.min(axis=0) + 0.4, r.polygon_array.max(axis=0) - 0.4
            xs, ys = np.meshgrid(np.arange(lo[0], hi[0] + 1e-9, 0.2), np.arange(lo[1], hi[1] + 1e-9, 0.2))
            pts = np.column_stack([xs.ravel(), ys.ravel()])
            pts = pts[(occ.clearance_at(pts) >= 0.4) & occ.reachable_from(self.ctx.pose(), pts)]
            if len(pts):
                cx, cy = pts[int(np.argmin(np.hypot(pts[:, 0] - toward[0], pts[:, 1] - toward[1])))]
        moved = self.ctx.go_to((float(cx), float(cy)))
        self.ctx.event("better_view", result=moved)
        self.look_around()

    def look_again_at(self, item, standoff_m: float = 0.75, min_move_m: float = 0.75) -> bool:
        """Look at ``item`` (a perceived furniture entity perception is unsure of) from another
        pose: the nearest free viewing pose (``viewing.viewing_poses``, ``standoff_m`` off its
        edge) at least ``min_move_m`` from where the robot stands, facing the item's centre, one
        frame perceived there. True when the robot got there and looked."""
        ctx = self.ctx
        here = ctx.pose()
        goals = [g for g in viewing_poses(ctx.world, item, here, ctx.obstacles.occupancy(),
                                          ctx.perception.furniture(), standoff_m)
                 if np.hypot(g[0] - here.x, g[1] - here.y) >= min_move_m]
        for goal in goals[:3]:
            moved = ctx.go_to(goal[:2], goal[2])
            if moved.success:
                ctx.face_point(*entity_centre(item))
                ctx.event("look_again", item=item.id, category=item.category, result=moved)
                self.on_frame(ctx.robot.depth_frame(), ctx.pose())
                return True
        ctx.event("look_again", item=item.id, category=item.category, result=None)
        return False

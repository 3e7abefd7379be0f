"""Outcomes as values: what happened when the robot tried to do something, and why.

Planning, motion and the fetch task return an :class:`ExecutionResult` instead of raising for
things that happen in a home (a blocked door, a bump, a table that is not there); the dialogue
turns ``status`` into a sentence and ``assistant fetch --json`` reports ``status.value`` as its
``failure`` field (null on success).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from enum import Enum

from assistant.geometry import Pose2D


class ExecutionStatus(str, Enum):
    """Why a step, a task or a use case ended: the product's one status enum (the application
    layer's :class:`~assistant.app.result.Status` is this enum)."""

    SUCCESS = "success"
    PARSE = "parse"  # the words could not be turned into a plan
    NO_ROOM = "no_room"  # the plan names a room this home does not have
    REFERENCE_NOT_FOUND = "reference_not_found"  # the furniture a node refers to was not seen
    NO_PATH = "no_path"  # no collision-free path to the goal
    COLLISION = "collision"  # the robot bumped, or stopped because its path ahead is blocked
    NOT_VISIBLE = "not_visible"  # arrived, but the target is not in the camera's view
    AMBIGUOUS = "ambiguous"  # several things fit the description equally well
    NOT_FOUND = "not_found"  # a search looked everywhere it could and did not see the object
    TIMEOUT = "timeout"  # the time or step budget of a motion ran out
    STOPPED = "stopped"  # the person asked the robot to stop


@dataclass(frozen=True)
class ExecutionResult:
    """The outcome of a planning or motion step.

    ``final_pose`` is the odometry pose at the end (world frame), ``sim_seconds`` the robot
    time the step took (odometry timestamps), ``distance_m`` the distance driven. ``details``
    carries step-specific values (e.g. ``bumped``, ``blocked_at``, ``goal_snapped``).
    """

    status: ExecutionStatus
    message: str = ""
    final_pose: Pose2D | None = None
    sim_seconds: float = 0.0
    distance_m: float = 0.0
    details: dict = field(default_factory=dict)

    @property
    def success(self) -> bool:
        return self.status is ExecutionStatus.SUCCESS

    def __bool__(self) -> bool:  # `if result:` reads as "if it worked"
        return self.success

    def with_details(self, **extra) -> "ExecutionResult":
        return replace(self, details={**self.details, **extra})

    def to_dict(self) -> dict:
        pose = self.final_pose
        return {
            "status": self.status.value,
            "success": self.success,
            "failure": None if self.success else self.status.value,
            "message": self.message,
            "final_pose": None if pose is None else [pose.x, pose.y, pose.theta],
            "sim_seconds": self.sim_seconds,
            "distance_m": self.distance_m,
            "details": {k: _plain(v) for k, v in self.details.items()},
        }

    @classmethod
    def ok(cls, message: str = "", **kwargs) -> "ExecutionResult":
        return cls(ExecutionStatus.SUCCESS, message, **kwargs)

    @classmethod
    def failed(cls, status: ExecutionStatus, message: str, **kwargs) -> "ExecutionResult":
        if status is ExecutionStatus.SUCCESS:
            raise ValueError("a failed result needs a failure status, not success")
        return cls(status, message, **kwargs)


def _plain(value):
    """JSON-friendly form of a detail value."""
    if isinstance(value, Pose2D):
        return [value.x, value.y, value.theta]
    if isinstance(value, Enum):
        return value.value
    if hasattr(value, "tolist"):
        return value.tolist()
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    return value

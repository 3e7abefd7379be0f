"""What a fetch reports: one :class:`NodeReport` per RDT node and the :class:`FetchResult`."""

from __future__ import annotations

from dataclasses import dataclass, field

from assistant.executor.outcome import ExecutionStatus
from assistant.geometry import Pose2D

__all__ = ["FetchResult", "NodeReport"]


@dataclass
class NodeReport:
    """What happened at one RDT node."""

    rdt: str
    kind: str  # "dynamic" or "static"
    status: str
    message: str = ""
    model: str | None = None  # the policy model used (may be a fallback RDT)
    reference: str | None = None  # entity id
    target: str | None = None  # entity id
    move_to: list | None = None  # [x, y, heading]
    score: float | None = None
    tried: list = field(default_factory=list)  # [reference, direction] pairs tried

    def to_dict(self) -> dict:
        return {"rdt": self.rdt, "kind": self.kind, "status": self.status, "message": self.message,
                "model": self.model, "reference": self.reference, "target": self.target,
                "move_to": self.move_to, "score": self.score, "tried": self.tried}


@dataclass
class FetchResult:
    """The outcome of one fetch: ``status`` (success or the failure reason), the plan, each
    node's report, the robot's final pose (its own estimate, world frame), the target
    furniture chosen (id, centre) and simulated seconds."""

    status: ExecutionStatus
    message: str
    plan: dict | None = None
    nodes: list[NodeReport] = field(default_factory=list)
    final_pose: Pose2D | None = None
    target_furniture: dict | None = None
    sim_seconds: float = 0.0
    distance_m: float = 0.0
    recovered: bool = False
    details: dict = field(default_factory=dict)
    score_map: tuple | None = None  # (poses (N, 3), scores (N,)) of the last policy search
    seen: list = field(default_factory=list)  # placed Sightings: the latest of each object seen

    @property
    def success(self) -> bool:
        return self.status is ExecutionStatus.SUCCESS

    def to_dict(self) -> dict:
        p = self.final_pose
        return {"status": self.status.value, "success": self.success,
                "failure": None if self.success else self.status.value, "message": self.message,
                "plan": self.plan, "nodes": [n.to_dict() for n in self.nodes],
                "final_pose": None if p is None else [round(p.x, 3), round(p.y, 3), round(p.theta, 4)],
                "target_furniture": self.target_furniture, "recovered": self.recovered,
                "sim_seconds": round(self.sim_seconds, 2), "distance_m": round(self.distance_m, 2),
                "seen": [s.to_dict() for s in self.seen], "details": self.details}

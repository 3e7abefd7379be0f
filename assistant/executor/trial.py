"""One fetch trial in the simulator, from text to final pose, with its evaluation.

:class:`FetchRunner` holds what is slow to build and shared between trials (the command parser,
the policy library, the furniture detector) and runs :meth:`FetchRunner.run`: parse the text,
start a :class:`~assistant.sim.SimRobot` in the world's scene at its start pose, carry out the
plan with a :class:`~assistant.executor.fetch.FetchTask`, then *evaluate*: render the final
depth frame and count the pixels whose simulator hit id is the target object
(:func:`object_visibility`). The hit ids are ground truth and are read here, after the task has
ended — the task itself never sees them.

Success (Table 5-4, our threshold): the target object covers at least
:data:`MIN_PIXELS` pixels of the final 640×480 depth frame at a median distance of at most
:data:`MAX_DISTANCE_M`.
"""

from __future__ import annotations

import time
from dataclasses import dataclass

import numpy as np

#: evaluation threshold: pixels of the target object in the final frame
MIN_PIXELS = 50
#: evaluation threshold: median distance (metres) of those pixels
MAX_DISTANCE_M = 4.5


def object_visibility(frame, object_name: str | None) -> dict:
    """``{pixels, distance}`` of ``object_name`` in a simulated frame (hit ids; evaluation
    only). ``distance`` is the median depth (metres) of its pixels, None when none."""
    if frame is None or object_name is None or frame.hit_ids is None:
        return {"pixels": 0, "distance": None}
    names = list(frame.hit_names)
    if object_name not in names:
        return {"pixels": 0, "distance": None}
    mask = frame.hit_ids == names.index(object_name)
    pixels = int(mask.sum())
    if pixels == 0:
        return {"pixels": 0, "distance": None}
    depth = frame.depth_m[mask]
    depth = depth[depth > 0]
    distance = float(np.median(depth)) if len(depth) else None
    return {"pixels": pixels, "distance": None if distance is None else round(distance, 3)}


def is_visible(visibility: dict) -> bool:
    d = visibility.get("distance")
    return visibility.get("pixels", 0) >= MIN_PIXELS and d is not None and d <= MAX_DISTANCE_M


@dataclass
class TrialOutcome:
    """A trial's JSON fields (DESIGN.md ``assistant fetch --json``) plus the task result."""

    data: dict
    result: object  # FetchResult or None (parse errors)
    robot_path: list | None = None

    @property
    def success(self) -> bool:
        return bool(self.data["success"])


class FetchRunner:
    """Shared, slow-to-build parts of fetch trials (parser, policies, detector), built on first
    use. ``grounder``: the grounding model name (None = the default); ``noise``: drive with the
    simulator's odometry noise (the localizer corrects it); ``taught``: train the policies on
    the user's taught demonstrations too (the product does, the evaluations do not)."""

    def __init__(self, grounder: str | None = None, noise: bool = True, policies=None, detector=None,
                 parser=None, max_sim_seconds: float = 900.0, taught: bool = False):
        self.grounder = grounder
        self.taught = taught
        self.noise = noise
        self._policies = policies
        self._detector = detector
        self._parsers = {} if parser is None else {None: parser}
        self.max_sim_seconds = max_sim_seconds

    def parser(self, world):
        key = world.name
        if key not in self._parsers:
            if None in self._parsers:
                return self._parsers[None]
            from assistant.grounding import CommandParser

            shared = next(iter(self._parsers.values()), None)
            if shared is None:
                self._parsers[key] = CommandParser.load(self.grounder, world=world)
            else:  # same trained layers, this world
                self._parsers[key] = CommandParser(shared.language, shared.grounder, world)
        return self._parsers[key]

    @property
    def policies(self):
        if self._policies is None:
            from assistant.policy.library import PolicyLibrary

            self._policies = PolicyLibrary(taught=self.taught)
        return self._policies

    @property
    def detector(self):
        if self._detector is None:
            from assistant.perception import FurnitureDetector

            self._detector = FurnitureDetector()
        return self._detector

    def run(self, text: str, world: str, scene: str = "original", perception: str = "sensed",
            seed: int = 0, object_name: str | None = None, on_event=None, robot=None) -> TrialOutcome:
        """One fetch; ``object_name`` overrides the plan's object for evaluation (the dev set
        says which object the command is about). ``robot``: an unconnected robot to use instead
        of a new simulator (a recording or a replay); without the simulator's hit ids the
        object is judged by the task's own result."""
        from assistant.executor.context import TaskContext
        from assistant.executor.fetch import FetchTask
        from assistant.executor.outcome import ExecutionStatus
        from assistant.executor.sensing import make_furniture_source
        from assistant.perception.objects import SimObjectDetector
        from assistant.robot import make_robot
        from assistant.world import load_world

        start = time.perf_counter()
        w = load_world(world)
        scene = w.scene(scene).name
        parsed = self.parser(w).parse(text)
        plan = parsed.plan
        source = make_furniture_source(perception, w, scene,
                                       detector=self.detector if perception == "sensed" else None)
        task = FetchTask(self.policies, object_detector=SimObjectDetector.for_scene(w.scene(scene)))
        path: list = []
        if robot is None:
            robot = make_robot("sim", world=w, scene=scene, seed=seed, noise=self.noise)
        with robot:
            ctx = TaskContext.start(w, robot, source, max_sim_seconds=self.max_sim_seconds, on_event=on_event)
            result = task.run(ctx, plan)
            final_frame = robot.depth_frame()
            true_pose = getattr(robot, "ground_truth_pose", None)
        # ---- evaluation (ground truth from here on)
        obj = object_name or plan.object
        known = {o.name for o in w.scene(scene).objects}
        visibility = object_visibility(final_frame, obj if obj in known else None)
        seen = is_visible(visibility) if final_frame.hit_ids is not None else result.success
        if not result.success:
            failure = result.status.value
        elif not seen:
            failure = ExecutionStatus.NOT_VISIBLE.value
        else:
            failure = None
        placed = next((o for o in w.scene(scene).objects if o.name == obj), None)
        data = {
            "text": text, "world": w.name, "scene": scene, "perception": perception, "seed": seed,
            "plan": plan.to_dict(),
            "object": obj,
            "nodes": [n.to_dict() for n in result.nodes],
            "success": failure is None,
            "failure": failure,
            "executor": {"status": result.status.value, "message": result.message,
                         "target_furniture": result.target_furniture, "recovered": result.recovered},
            "final_pose": None if result.final_pose is None else
            [round(result.final_pose.x, 3), round(result.final_pose.y, 3), round(result.final_pose.theta, 4)],
            "true_final_pose": None if true_pose is None else
            [round(true_pose.x, 3), round(true_pose.y, 3), round(true_pose.theta, 4)],
            "target_position": None if placed is None else [round(placed.x, 3), round(placed.y, 3)],
            "target_visible": visibility,
            "seen": [s.to_dict() for s in result.seen],
            "sim_seconds": round(result.sim_seconds, 2),
            "wall_seconds": round(time.perf_counter() - start, 3),
        }
        return TrialOutcome(data, result, path)

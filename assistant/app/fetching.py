"""The fetch use case: from a command's words to the robot facing the object's furniture.

:class:`Fetcher` holds what is slow to build and shared between fetches (the command parser,
per home; the policy library; the furniture detector) and runs :meth:`Fetcher.fetch`: parse
the text, make the robot (:func:`~assistant.app.robots.open_robot`, any robot spec), give the
:class:`~assistant.executor.fetch.FetchTask` a task context, then judge the end: what the
robot's own object detector sees in the final frame and — on the simulator, after the task has
ended — how many pixels of the object the frame holds (the hit ids, evaluation only: the task
never reads them). Success (Table 5-4, our threshold,
:func:`~assistant.executor.trial.is_visible`): the task succeeded and the object covers at
least 50 pixels at most 4.5 m away; on a robot without hit ids (a replay, hardware) the task's
own result stands.
"""

from __future__ import annotations

import time

from assistant.app.result import Result, Status
from assistant.app.robots import DEFAULT_ROBOT, open_robot
from assistant.app.stopping import StoppableRobot, Stopped
from assistant.executor.context import TaskContext
from assistant.executor.fetch import FETCH_BUDGET_S, FetchTask
from assistant.executor.sensing import make_furniture_source
from assistant.executor.sightings import place_sightings
from assistant.executor.trial import is_visible, object_visibility
from assistant.perception.objects import SimObjectDetector

__all__ = ["Fetcher"]


class Fetcher:
    """Shared, slow-to-build parts of fetches (parser, policies, detector), built on first use.

    ``grounder``: the grounding model name (None = the default); ``noise``: the simulator's
    odometry noise (the localizer corrects it); ``parser`` / ``policies`` / ``detector``: given
    parts instead of the default ones; ``max_sim_seconds``: the robot-time budget of a fetch;
    ``taught``: train the policies on the user's taught demonstrations too (the product does,
    the evaluations do not).
    """

    def __init__(self, grounder: str | None = None, noise: bool = True, policies=None, detector=None,
                 parser=None, max_sim_seconds: float = FETCH_BUDGET_S, taught: bool = False):
        self.grounder = grounder
        self.taught = taught
        self.noise = noise
        self._policies = policies
        self._detector = detector
        self._parsers = {} if parser is None else {None: parser}
        self.max_sim_seconds = max_sim_seconds

    def parser(self, world):
        """The :class:`~assistant.grounding.CommandParser` for ``world`` (trained layers shared)."""
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

    def fetch(self, text: str, world, scene: str = "original", perception: str = "sensed", *,
              robot: str = DEFAULT_ROBOT, seed: int = 0, object_name: str | None = None, on_event=None,
              stop=None, on_pose=None, start=None) -> Result:
        """Carry out the fetch command ``text`` in ``world`` (a name or
        :class:`~assistant.world.World`) with the robot ``robot`` (a robot spec, or an
        unconnected robot such as a replay) and
        ``perception`` (``sensed`` or ``oracle`` furniture). ``object_name`` overrides the
        plan's object for judging the end (the dev set says which object a command is about);
        ``on_event(name, data)`` gets the task's events; ``stop`` (a
        :class:`threading.Event`) stops the robot at its next call; ``on_pose(pose)`` gets its
        true pose now and then; ``start`` (a :class:`~assistant.geometry.Pose2D`) is where the
        robot stands (default: the world's start pose; a conversation gives where the last task
        left it). Returns a ``fetch`` :class:`Result` whose ``data`` are the
        ``assistant fetch --json`` fields."""
        from assistant.world import load_world

        began = time.perf_counter()
        w = load_world(world) if isinstance(world, str) else world
        scene = w.scene(scene).name
        plan = self.parser(w).parse(text).plan
        source = make_furniture_source(perception, w, scene,
                                       detector=self.detector if perception == "sensed" else None)
        # the robot's object detector (the simulator's model of one): every object it sees on the
        # way becomes an ``objects_seen`` event for the memory
        detector = SimObjectDetector.for_scene(w.scene(scene), seed=seed)
        task = FetchTask(self.policies, object_detector=detector)
        with open_robot(robot, w, scene, seed=seed, noise=self.noise, start=start, clear=True) as bot:
            try:
                stoppable = StoppableRobot(bot, stop, on_pose)
                ctx = TaskContext.start(w, stoppable, source, max_sim_seconds=self.max_sim_seconds,
                                        on_event=on_event, look_first=start is not None)
                outcome = task.run(ctx, plan)
            except Stopped:
                stoppable.report_pose()
                return Result("fetch", Status.STOPPED, "stopped", {"text": text, "plan": plan.to_dict()},
                              furniture=source.furniture(), object=plan.object,
                              wall_seconds=time.perf_counter() - began)
            final_frame = bot.depth_frame()
            true_pose = getattr(bot, "ground_truth_pose", None)
            stoppable.report_pose()
        obj = object_name or plan.object
        end = _judge_end(w, scene, obj, outcome, final_frame, detector, source.furniture())
        data = _fetch_fields(text, w, scene, perception, seed, robot, plan, obj, outcome, end, true_pose)
        data["wall_seconds"] = round(time.perf_counter() - began, 3)
        status = Status.SUCCESS if data["failure"] is None else Status(data["failure"])
        message = outcome.message if outcome.success or status is not Status.NOT_VISIBLE else \
            f"{outcome.message}, but the {obj or 'object'} is not in view"
        return Result("fetch", status, message, data, task=outcome, seen=end["seen"],
                      furniture=source.furniture(), object=obj, object_seen=end["detected"],
                      wall_seconds=data["wall_seconds"])


def _judge_end(world, scene: str, obj: str | None, outcome, frame, detector, furniture) -> dict:
    """What the final frame shows: the object's pixels (simulator hit ids; None without them),
    whether the robot's own detector sees it, and every object seen (the task's latest
    sightings, updated with the final frame's)."""
    known = {o.name for o in world.scene(scene).objects}
    visibility = None if frame.hit_ids is None else object_visibility(frame, obj if obj in known else None)
    in_view = detector.detect(frame)
    final = {p.name: p for p in place_sightings(world, furniture, in_view)}
    seen = [final.pop(p.name, p) for p in outcome.seen] + list(final.values())
    detected = bool(obj) and any(s.name == obj for s in in_view)
    if not outcome.success:
        failure = outcome.status.value
    elif obj and not (is_visible(visibility) if visibility is not None else outcome.success):
        failure = Status.NOT_VISIBLE.value
    else:
        failure = None
    return {"visibility": visibility, "detected": detected, "seen": seen, "failure": failure}


def _fetch_fields(text, world, scene, perception, seed, robot, plan, obj, outcome, end, true_pose) -> dict:
    """The ``assistant fetch --json`` fields (DESIGN.md's command-line contract, plus more)."""
    placed = next((o for o in world.scene(scene).objects if o.name == obj), None)
    p = outcome.final_pose
    return {
        "text": text, "world": world.name, "scene": scene, "perception": perception, "seed": seed,
        "robot": robot if isinstance(robot, str) else type(robot).__name__, "plan": plan.to_dict(), "object": obj,
        "nodes": [n.to_dict() for n in outcome.nodes],
        "success": end["failure"] is None, "failure": end["failure"],
        "executor": {"status": outcome.status.value, "message": outcome.message,
                     "target_furniture": outcome.target_furniture, "recovered": outcome.recovered},
        "final_pose": None if p is None else [round(p.x, 3), round(p.y, 3), round(p.theta, 4)],
        "true_final_pose": None if true_pose is None else
        [round(true_pose.x, 3), round(true_pose.y, 3), round(true_pose.theta, 4)],
        "target_position": None if placed is None else [round(placed.x, 3), round(placed.y, 3)],
        "target_visible": end["visibility"] or {"pixels": 0, "distance": None},
        "target_detected": end["detected"],
        "seen": [s.to_dict() for s in end["seen"]],
        "seen_objects": sorted(s.name for s in end["seen"]),
        "sim_seconds": round(outcome.sim_seconds, 2),
    }

"""The parts the dialogue uses, behind small adapters so they load lazily (or in the
background) and so tests can hand in stand-ins.

* :class:`Services` — the command parser (grounding), the describer (generation) and the fetch
  runner (executor), built on first use; :meth:`Services.warm_up` builds them in a background
  thread so the chat prompt appears at once.
* :func:`fetch_report` — turns the fetch runner's result into the few fields the dialogue needs.
"""

from __future__ import annotations

import threading
import time
from dataclasses import dataclass, field


class Interrupted(Exception):
    """Raised from the fetch's progress callback when the person said "stop". ``furniture``:
    the furniture the robot had perceived when it stopped (set by :func:`run_trial` and
    :meth:`Services.search`), so what it saw can still be described."""

    furniture: list | None = None


@dataclass
class FetchReport:
    """What the dialogue needs from one fetch (all from the executor's result)."""

    success: bool  # the executor finished and the object is in the final view (simulator check)
    failure: str | None
    message: str  # the executor's own sentence ("facing the table in the bedroom")
    final_pose: list | None = None  # [x, y, heading] metres, radians
    target_furniture: dict | None = None  # {id, name, centre}
    object: str | None = None
    object_seen: bool = False
    wall_seconds: float = 0.0
    data: dict = field(default_factory=dict)
    seen: list = field(default_factory=list)  # placed Sightings: the latest of each object seen
    furniture: list | None = None  # the perceived furniture entities at the end (phrases)


def fetch_report(data: dict) -> FetchReport:
    """A :class:`FetchReport` from ``TrialOutcome.data`` (``assistant fetch --json`` fields);
    ``object_seen`` is the robot's own object detector on the final frame when the data has it
    (``target_detected``), else the simulator's visibility check."""
    executor = data.get("executor") or {}
    visible = data.get("target_visible") or {}
    if "target_detected" in data:
        seen = bool(data["target_detected"])
    else:
        try:
            from assistant.executor.trial import is_visible
            seen = bool(is_visible(visible))
        except ImportError:
            seen = bool(data.get("success"))
    return FetchReport(bool(data.get("success")), data.get("failure"), executor.get("message", ""),
                       data.get("final_pose"), executor.get("target_furniture"), data.get("object"),
                       seen, float(data.get("wall_seconds") or 0.0),
                       {k: v for k, v in data.items() if not k.startswith("_")},
                       list(data.get("_seen") or []), data.get("_furniture"))


class Services:
    """Lazily built parser / describer / fetch runner, shared by every conversation.

    ``perception``: ``oracle`` or ``sensed`` furniture perception for fetches and searches;
    ``search``: how "where is my X?" is answered when memory has nothing — ``sensed`` (the robot
    searches the home, :class:`~assistant.executor.search.SearchTask`) or ``oracle`` (the
    simulator's world file, labelled as such); ``parser``, ``describer``, ``fetcher``,
    ``searcher`` may be given (a fetcher is any callable ``(text, world, scene, on_event) ->
    FetchReport``, a searcher ``(name, world, scene, on_event) -> SearchResult``).
    """

    def __init__(self, perception: str = "oracle", parser=None, describer=None, fetcher=None,
                 seed: int = 0, search: str = "sensed", searcher=None):
        from assistant.errors import UnknownNameError
        from assistant.generation.types import SEARCH_MODES

        if search not in SEARCH_MODES:
            raise UnknownNameError("search", str(search), SEARCH_MODES)
        self.perception = perception
        self.search_mode = search
        self.seed = seed
        self._parser = parser
        self._describer = describer
        self._fetcher = fetcher
        self._searcher = searcher
        self._runner = None
        self._lock = threading.RLock()
        self._warm: threading.Thread | None = None
        self.warm_error: str | None = None

    # ---------------------------------------------------------------- lazy parts
    def parser(self, world):
        """A :class:`~assistant.grounding.CommandParser` for ``world`` (trained layers shared)."""
        from assistant.grounding import CommandParser

        with self._lock:
            if self._parser is None:
                self._parser = CommandParser.load(world=world)
            if getattr(self._parser, "world", None) is not world:
                self._parser = CommandParser(self._parser.language, self._parser.grounder, world)
            return self._parser

    @property
    def describer(self):
        with self._lock:
            if self._describer is None:
                from assistant.generation import Describer

                self._describer = Describer()
            return self._describer

    def runner(self):
        with self._lock:
            if self._runner is None:
                from assistant.executor.trial import FetchRunner

                self._runner = FetchRunner(parser=self._parser, taught=True) if self._parser is not None \
                    else FetchRunner(taught=True)
            return self._runner

    def fetch(self, text: str, world: str, scene: str, on_event=None, stop=None, on_pose=None) -> FetchReport:
        """Run one fetch command in the simulator (blocking; call it from a worker thread).
        ``stop``: a :class:`threading.Event`; once set, the robot's next call raises
        :class:`Interrupted`. ``on_pose(pose)``: the robot's true pose now and then (3D view)."""
        if self._fetcher is not None:
            return self._fetcher(text, world, scene, on_event)
        return fetch_report(run_trial(self.runner(), text, world, scene, self.perception, self.seed,
                                      on_event=on_event, stop=stop, on_pose=on_pose))

    def search(self, name: str, world: str, scene: str, on_event=None, stop=None, on_pose=None):
        """Search the simulated home for object ``name`` from the world's start pose (blocking;
        call it from a worker thread): the generation layer's
        :class:`~assistant.executor.search.SearchTask` with this session's furniture
        perception and the simulator's object detector, the robot wrapped in a
        :class:`StoppableRobot`. Returns its :class:`~assistant.executor.search.SearchResult`."""
        if self._searcher is not None:
            return self._searcher(name, world, scene, on_event)
        from assistant.executor.context import TaskContext
        from assistant.executor.search import SEARCH_BUDGET_S, SearchTask
        from assistant.executor.sensing import make_furniture_source
        from assistant.perception.objects import SimObjectDetector
        from assistant.robot import make_robot
        from assistant.world import load_world

        runner = self.runner()
        w = load_world(world)
        sc = w.scene(scene)
        source = make_furniture_source(self.perception, w, sc.name,
                                       detector=runner.detector if self.perception == "sensed" else None)
        detector = SimObjectDetector.for_scene(sc, seed=self.seed)
        with make_robot("sim", world=w, scene=sc.name, seed=self.seed, noise=runner.noise) as robot:
            try:
                ctx = TaskContext.start(w, StoppableRobot(robot, stop, on_pose), source,
                                        max_sim_seconds=SEARCH_BUDGET_S, on_event=on_event)
                return SearchTask(detector).run(ctx, " ".join(name.lower().split()))
            except Interrupted as error:
                error.furniture = source.furniture()
                raise

    def warm_up(self, world, background: bool = True, scene: str = "original") -> None:
        """Build the parser, describer (and its environment model) and fetch runner now (in a
        daemon thread when ``background``)."""
        def work():
            try:
                self.parser(world)
                self.describer  # noqa: B018 (property builds it)
                world_environment(world, world.scene(scene).name)
                known_object_names(world)
                if self._fetcher is None:
                    runner = self.runner()
                    runner.policies  # noqa: B018
                    if self.perception == "sensed":
                        runner.detector  # noqa: B018
            except Exception as error:  # reported when the part is used
                self.warm_error = f"{type(error).__name__}: {error}"

        if not background:
            work()
            return
        self._warm = threading.Thread(target=work, name="assistant-warm-up", daemon=True)
        self._warm.start()

    def wait_warm(self, timeout: float | None = None) -> bool:
        if self._warm is not None:
            self._warm.join(timeout)
            return not self._warm.is_alive()
        return True


class StoppableRobot:
    """Wraps a robot so that every call first checks a stop flag (raising :class:`Interrupted`)
    — the fetch task talks to the robot many times a second, so "stop" takes effect at once."""

    def __init__(self, robot, stop, on_pose=None, every: int = 20):
        self._robot = robot
        self._stop = stop
        self._on_pose = on_pose
        self._every = every
        self._calls = 0

    def __getattr__(self, name):
        value = getattr(self._robot, name)
        if not callable(value):
            return value

        def call(*args, **kwargs):
            if self._stop is not None and self._stop.is_set():
                raise Interrupted()
            out = value(*args, **kwargs)
            self._calls += 1
            if self._on_pose is not None and self._calls % self._every == 0:
                try:
                    self._on_pose(self._robot.ground_truth_pose)
                except Exception:  # drawing is a courtesy
                    pass
            return out

        return call


def run_trial(runner, text: str, world: str, scene: str = "original", perception: str = "oracle",
              seed: int = 0, on_event=None, stop=None, on_pose=None) -> dict:
    """One fetch the way :meth:`assistant.executor.trial.FetchRunner.run` does it (same parser,
    policies, detector, task and evaluation functions), with the robot wrapped in a
    :class:`StoppableRobot`. Returns the ``assistant fetch --json`` fields."""
    from assistant.executor.context import TaskContext
    from assistant.executor.fetch import FetchTask
    from assistant.executor.outcome import ExecutionStatus
    from assistant.executor.sensing import make_furniture_source
    from assistant.executor.trial import is_visible, object_visibility
    from assistant.perception.objects import SimObjectDetector
    from assistant.robot import make_robot
    from assistant.world import load_world

    start = time.perf_counter()
    w = load_world(world)
    scene = w.scene(scene).name
    plan = runner.parser(w).parse(text).plan
    source = make_furniture_source(perception, w, scene,
                                   detector=runner.detector if perception == "sensed" else None)
    # the robot's object detector (the simulator's model of one): every object it sees on the
    # way becomes an ``objects_seen`` event for the memory
    detector = SimObjectDetector.for_scene(w.scene(scene), seed=seed)
    task = FetchTask(runner.policies, object_detector=detector)
    with make_robot("sim", world=w, scene=scene, seed=seed, noise=runner.noise) as robot:
        try:
            ctx = TaskContext.start(w, StoppableRobot(robot, stop, on_pose), source,
                                    max_sim_seconds=runner.max_sim_seconds, on_event=on_event)
            result = task.run(ctx, plan)
        except Interrupted as error:
            error.furniture = source.furniture()
            raise
        final_frame = robot.depth_frame()
        true_pose = robot.ground_truth_pose
    obj = plan.object
    known = {o.name for o in w.scene(scene).objects}
    visibility = object_visibility(final_frame, obj if obj in known else None)
    in_view = detector.detect(final_frame)  # what the robot itself sees at the end
    seen = list(getattr(result, "seen", []) or [])
    if in_view:
        from assistant.executor.sightings import place_sightings

        final = {p.name: p for p in place_sightings(w, source.furniture(), in_view)}
        seen = [final.pop(p.name, p) for p in seen] + list(final.values())
    if not result.success:
        failure = result.status.value
    elif not is_visible(visibility):
        failure = ExecutionStatus.NOT_VISIBLE.value
    else:
        failure = None
    p = result.final_pose
    return {"text": text, "world": w.name, "scene": scene, "perception": perception, "plan": plan.to_dict(),
            "object": obj, "success": failure is None, "failure": failure,
            "executor": {"status": result.status.value, "message": result.message,
                         "target_furniture": result.target_furniture, "recovered": result.recovered},
            "final_pose": None if p is None else [round(p.x, 3), round(p.y, 3), round(p.theta, 4)],
            "true_final_pose": [round(true_pose.x, 3), round(true_pose.y, 3), round(true_pose.theta, 4)],
            "target_visible": visibility, "sim_seconds": round(result.sim_seconds, 2),
            "target_detected": bool(obj) and any(s.name == obj for s in in_view),
            "seen_objects": sorted(p.name for p in seen),
            "wall_seconds": round(time.perf_counter() - start, 3),
            "_seen": seen, "_furniture": source.furniture()}


def furniture_phrase(describer, world, scene: str, item, listener_in_room: bool = True) -> str:
    """A short phrase that singles furniture ``item`` out, "on the table in front of the couch",
    made by the describer for a thing placed on it (the generation layer's content selection)."""
    from assistant.geometry import Pose2D
    from assistant.perception.objects import Sighting

    sighting = Sighting("thing", item.x, item.y, 0.8, room=item.room, seen_from=Pose2D(item.x, item.y, 0.0))
    listener = _room_pose(world, item.room) if listener_in_room else None
    try:
        result = describer.describe(sighting, world_environment(world, scene), world.floorplan, listener_pose=listener)
    except Exception:  # a phrase is a courtesy; fall back to the word
        return f"on the {item.word}"
    text = result.description.strip().rstrip(".")
    for lead in ("The thing is ", "the thing is "):
        if text.startswith(lead):
            text = text[len(lead):]
    return text


#: (world name, scene) → (the World, its world-file furniture); the World is kept so that a
#: world of the same name loaded again (another file) is not served the old furniture
_ENV_CACHE: dict = {}
#: world name → (the World, the object names the robot can look for there)
_KNOWN: dict = {}


def world_environment(world, scene: str) -> list:
    """The world file's furniture of ``scene`` as environment entities (the ``oracle``
    environment the simulator-backed answers are composed from), built once per world."""
    from assistant.generation import oracle_environment

    key = (world.name, scene)
    hit = _ENV_CACHE.get(key)
    if hit is None or hit[0] is not world:
        hit = _ENV_CACHE[key] = (world, oracle_environment(world, scene))
    return hit[1]


def known_object_names(world) -> list[str]:
    """Object names the robot can look for in ``world`` (the generation layer's list), built
    once per world."""
    from assistant.generation import known_objects

    hit = _KNOWN.get(world.name)
    if hit is None or hit[0] is not world:
        hit = _KNOWN[world.name] = (world, list(known_objects(world)))
    return hit[1]


def _room_pose(world, room: str):
    from assistant.geometry import Pose2D

    for r in world.floorplan.rooms:
        if r.name == room:
            c = r.centre
            return Pose2D(float(c[0]), float(c[1]), 0.0)
    return None


def timed(fn, *args, **kwargs):
    """``(result, seconds)`` of one call (for the benchmark and the transcript)."""
    start = time.perf_counter()
    out = fn(*args, **kwargs)
    return out, time.perf_counter() - start

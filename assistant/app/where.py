"""The "where is my X?" use case: search, then describe — written once.

:meth:`Finder.where_is` finds the object one of three ways and composes the answer with the
generation layer's :class:`~assistant.generation.Describer`:

* ``search="sensed"`` (the product's way): the robot searches the home room by room with its
  own perception (:class:`~assistant.executor.search.SearchTask`) and the description is
  composed from the environment model it built;
* ``remembered``: a position the caller remembers (the dialogue's object memory), described
  among the world file's furniture;
* ``search="oracle"``: the object's position and the furniture read from the world file,
  labelled as such (it separates the language from the search).

The answer is a ``where`` :class:`~assistant.app.result.Result`: ``success`` when found,
``not_found`` (the honest "I looked in … and did not find …") or ``timeout``; its ``data`` are
the ``assistant where --json`` fields.
"""

from __future__ import annotations

import time

from assistant.app.result import Result, Status
from assistant.app.robots import DEFAULT_ROBOT, open_robot
from assistant.app.stopping import StoppableRobot, Stopped
from assistant.errors import UnknownNameError
from assistant.executor.context import TaskContext
from assistant.executor.search import SEARCH_BUDGET_S, SearchTask
from assistant.executor.sensing import make_furniture_source
from assistant.generation.types import SEARCH_MODES
from assistant.geometry import Pose2D
from assistant.perception.objects import SimObjectDetector

__all__ = ["Finder", "asked_object", "known_object_names", "world_environment"]

#: words said before the thing asked about that are no part of its name ("my keys", "the phone")
POSSESSIVES = frozenset({"my", "the", "a", "an", "your", "our", "his", "her", "their", "some", "any", "mine"})

#: (world name, scene) → (the World, its world-file furniture); the World is kept so that a
#: world of the same name loaded again (another file) is not served the old furniture
_ENV_CACHE: dict = {}
#: world name → (the World, the object names the robot can look for there)
_KNOWN: dict = {}


def world_environment(world, scene: str) -> list:
    """The world file's furniture of ``scene`` as environment entities (the ``oracle``
    environment), built once per world."""
    from assistant.generation import oracle_environment

    key = (world.name, scene)
    hit = _ENV_CACHE.get(key)
    if hit is None or hit[0] is not world:
        hit = _ENV_CACHE[key] = (world, oracle_environment(world, scene))
    return hit[1]


def asked_object(said: str) -> str:
    """The name to look for when a person asks for ``said``: the catalogue's name of the thing
    ("my keys" → ``keys``, "phone" → ``cell phone``, "key" → ``keys``), else the words without
    "my"/"the" in the number they were said in ("my umbrella" → ``umbrella``, "my slippers" →
    ``slippers``: no detector knows such a thing by name, and the answer says it back)."""
    from assistant.grounding.objects import is_object_word, object_kind, plural

    words = " ".join(str(said).lower().split()).split()
    while len(words) > 1 and words[0] in POSSESSIVES:
        words.pop(0)
    if not words:
        return ""
    kind = object_kind(" ".join(words))
    if not is_object_word(kind) and words[-1] == plural(kind).split()[-1] != kind.split()[-1]:
        return plural(kind)
    return kind


def known_object_names(world) -> list[str]:
    """Object names the robot can look for in ``world``, built once per world."""
    from assistant.generation import known_objects

    hit = _KNOWN.get(world.name)
    if hit is None or hit[0] is not world:
        hit = _KNOWN[world.name] = (world, list(known_objects(world)))
    return hit[1]


class Finder:
    """Shared, slow-to-build parts of "where is" answers: the ``describer`` (default: learnt
    from the repository's corpus) and the ``furniture_detector`` of sensed searches (built on
    first use). ``noise``: the simulator's odometry noise."""

    def __init__(self, describer=None, furniture_detector=None, noise: bool = True):
        self._describer = describer
        self._detector = furniture_detector
        self.noise = noise

    @property
    def describer(self):
        if self._describer is None:
            from assistant.generation import Describer

            self._describer = Describer()
        return self._describer

    @property
    def furniture_detector(self):
        if self._detector is None:
            from assistant.perception import FurnitureDetector

            self._detector = FurnitureDetector()
        return self._detector

    def where_is(self, name: str, world, scene: str = "original", *, robot: str = DEFAULT_ROBOT,
                 search: str = "sensed", perception: str = "sensed", remembered=None, listener=None,
                 style: str | None = None, question: str | None = None, miss_rate: float = 0.0,
                 seed: int = 0, on_event=None, stop=None, on_pose=None, searched=None,
                 **search_params) -> Result:
        """Find ``name`` in ``world`` (name or :class:`~assistant.world.World`) and say where it
        is (module docstring). ``listener``: the asking person's pose (a :class:`Pose2D` or ``(x, y, heading)``)
        (default: the world's start, where the robot was asked); ``style``: ``static`` or
        ``dynamic`` (default: from ``question``, else static); ``remembered``: a
        :class:`~assistant.perception.objects.Sighting` to describe instead of searching;
        ``searched``: a finished :class:`~assistant.executor.search.SearchResult` to describe
        instead of searching again; ``perception``: the search's furniture perception;
        ``miss_rate``: the simulated object detector's miss rate; ``stop`` / ``on_pose`` /
        ``on_event``: as for a fetch; ``search_params`` go to the
        :class:`~assistant.executor.search.SearchTask`."""
        from assistant.generation import style_for_question
        from assistant.world import load_world

        if search not in SEARCH_MODES:
            raise UnknownNameError("search", str(search), SEARCH_MODES)
        w = load_world(world) if isinstance(world, str) else world
        scene = w.scene(scene).name
        key = asked_object(name)
        pose = w.start if listener is None else listener if isinstance(listener, Pose2D) else Pose2D(*listener)
        style = style or (style_for_question(question) if question else "static")
        if remembered is not None or search == "oracle":
            return self._from_world_file(key, w, scene, pose, style, remembered)
        if searched is None:
            try:
                searched = self.search(key, w, scene, robot=robot, perception=perception, miss_rate=miss_rate,
                                       seed=seed, on_event=on_event, stop=stop, on_pose=on_pose, **search_params)
            except Stopped as stopped:
                return Result("where", Status.STOPPED, "stopped", {"object": key, "found": False},
                              furniture=stopped.args[0] if stopped.args else None, object=key)
        answer = self.describer.describe_search(searched, w.floorplan, listener_pose=pose, style=style)
        status = Status.SUCCESS if searched.found else searched.status
        return Result("where", status, answer.description, answer.to_dict(), task=searched, description=answer,
                      seen=sorted(searched.seen.values(), key=lambda s: s.name), furniture=searched.furniture,
                      object=key, object_seen=searched.found, wall_seconds=searched.wall_seconds)

    def search(self, name: str, world, scene: str, *, robot: str = DEFAULT_ROBOT, perception: str = "sensed",
               miss_rate: float = 0.0, seed: int = 0, start=None, on_event=None, stop=None, on_pose=None,
               max_sim_seconds: float = SEARCH_BUDGET_S, **params):
        """The robot's search for ``name`` (a :class:`~assistant.executor.search.SearchResult`),
        from the world's start pose (or ``start``) on the simulator. Raises
        :class:`~assistant.app.stopping.Stopped` (its argument: the furniture perceived so far)
        when ``stop`` is set."""
        detector = SimObjectDetector.for_scene(world.scene(scene), miss_rate=miss_rate, seed=seed)
        source = make_furniture_source(perception, world, scene,
                                       detector=self.furniture_detector if perception == "sensed" else None)
        with open_robot(robot, world, scene, seed=seed, noise=self.noise, start=start, clear=True) as bot:
            stoppable = StoppableRobot(bot, stop, on_pose)
            try:
                ctx = TaskContext.start(world, stoppable, source, max_sim_seconds=max_sim_seconds,
                                        on_event=on_event, look_first=start is not None)
                return SearchTask(detector, **params).run(ctx, name)
            except Stopped as stopped:
                raise Stopped(source.furniture()) from stopped
            finally:
                stoppable.report_pose()

    def _from_world_file(self, name: str, world, scene: str, pose: Pose2D, style: str, remembered) -> Result:
        """The answer from a remembered position, or from the world file (``oracle``)."""
        from assistant.generation import not_found_description, oracle_sighting

        start = time.perf_counter()
        sighting = remembered if remembered is not None else oracle_sighting(world, scene, name)
        search_s = time.perf_counter() - start
        if sighting is None:
            answer = not_found_description(name, world.floorplan.room_names)
        else:
            answer = self.describer.describe(sighting, world_environment(world, scene), world.floorplan,
                                             listener_pose=pose, style=style)
        answer.search_seconds = search_s
        status = Status.SUCCESS if answer.found else Status.NOT_FOUND
        return Result("where", status, answer.description, answer.to_dict(), description=answer,
                      object=name, object_seen=False, wall_seconds=search_s)

"""The parts the dialogue uses, built lazily (or in the background) and replaceable in tests.

:class:`Services` holds the command parser (grounding), the describer (generation) and the
application layer's use cases — :class:`~assistant.app.Fetcher` for fetch commands and
:class:`~assistant.app.Finder` for "where is my X?" — with the session's robot spec,
perception and seed; :meth:`Services.warm_up` builds them in a background thread so the chat
prompt appears at once. A fetch and a search both end in an :class:`~assistant.app.Result`.
"""

from __future__ import annotations

import threading

from assistant.app import DEFAULT_ROBOT, Fetcher, Finder, known_object_names, world_environment


class Services:
    """Lazily built parser / describer / use cases, shared by every conversation.

    ``perception``: ``oracle`` or ``sensed`` furniture perception for fetches and searches;
    ``search``: how "where is my X?" is answered when memory has nothing — ``sensed`` (the robot
    searches the home) or ``oracle`` (the simulator's world file, labelled as such); ``robot``:
    the robot spec tasks run with (:func:`~assistant.robot.make_robot`); ``parser``,
    ``describer``, ``fetcher``, ``searcher`` may be given (a fetcher is any callable ``(text,
    world, scene, on_event) -> Result``, a searcher ``(name, world, scene, on_event) ->
    SearchResult``, whose result is then described).
    """

    def __init__(self, perception: str = "oracle", parser=None, describer=None, fetcher=None,
                 seed: int = 0, search: str = "sensed", searcher=None, robot: str = DEFAULT_ROBOT):
        from assistant.errors import UnknownNameError
        from assistant.generation.types import SEARCH_MODES

        if search not in SEARCH_MODES:
            raise UnknownNameError("search", str(search), SEARCH_MODES)
        self.perception = perception
        self.search_mode = search
        self.seed = seed
        self.robot = robot
        self._parser = parser
        self._describer = describer
        self._fetcher = fetcher
        self._searcher = searcher
        self._fetch_case: Fetcher | None = None
        self._finder: Finder | None = None
        self._lock = threading.RLock()
        self._warm: threading.Thread | None = None
        self.warm_error: str | None = None

    def using(self, fetcher=None, searcher=None) -> "Services":
        """A copy that shares this one's parser, describer and use cases but fetches with
        ``fetcher`` and searches with ``searcher`` (None: the real ones) — stand-ins in tests,
        without building the models again."""
        copy = Services(self.perception, self._parser, self._describer, fetcher, self.seed, self.search_mode,
                        searcher, self.robot)
        copy._fetch_case, copy._finder = self._fetch_case, self._finder
        return copy

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

    def fetcher(self) -> Fetcher:
        """The fetch use case (sharing this session's parser when it has one)."""
        with self._lock:
            if self._fetch_case is None:
                self._fetch_case = Fetcher(parser=self._parser, taught=True) if self._parser is not None \
                    else Fetcher(taught=True)
            return self._fetch_case

    def finder(self) -> Finder:
        """The "where is" use case (sharing the describer and the fetches' furniture detector)."""
        with self._lock:
            if self._finder is None:
                detector = self.fetcher().detector if self.perception == "sensed" else None
                self._finder = Finder(self.describer, detector)
            return self._finder

    # ---------------------------------------------------------------- the use cases
    def fetch(self, text: str, world: str, scene: str, on_event=None, stop=None, on_pose=None, start=None):
        """Run one fetch command (blocking; call it from a worker thread): an
        :class:`~assistant.app.Result`, ``stopped`` once ``stop`` (a
        :class:`threading.Event`) is set. ``on_pose(pose)``: the robot's true pose now and then;
        ``start``: where the robot stands (the pose the last task left it at; None: the
        world's start pose)."""
        if self._fetcher is not None:
            return self._fetcher(text, world, scene, on_event)
        return self.fetcher().fetch(text, world, scene, self.perception, robot=self.robot, seed=self.seed,
                                    on_event=on_event, stop=stop, on_pose=on_pose, start=start)

    def search(self, name: str, world, scene: str, on_event=None, stop=None, on_pose=None, style: str = "static",
               start=None):
        """Search the home for object ``name`` from where the robot stands (``start``; None: the
        world's start pose), then describe where it is to a person where the robot started
        (blocking; call it from a worker thread): a ``where`` :class:`~assistant.app.Result`."""
        from assistant.world import load_world

        w = load_world(world) if isinstance(world, str) else world
        searched = self._searcher(name, w.name, scene, on_event) if self._searcher is not None else None
        return self.finder().where_is(name, w, scene, robot=self.robot, perception=self.perception, style=style,
                                      seed=self.seed, on_event=on_event, stop=stop, on_pose=on_pose,
                                      searched=searched, start=start)

    def describe(self, name: str, world, scene: str, style: str = "static", remembered=None):
        """Where ``name`` is from the world file (``oracle``) or from a ``remembered``
        :class:`~assistant.perception.objects.Sighting`, to a person where the robot started:
        a ``where`` :class:`~assistant.app.Result`."""
        return self.finder().where_is(name, world, scene, search="oracle", remembered=remembered, style=style)

    def warm_up(self, world, background: bool = True, scene: str = "original") -> None:
        """Build the parser, describer (and its environment model) and fetch parts now (in a
        daemon thread when ``background``)."""
        def work():
            try:
                self.parser(world)
                self.describer  # noqa: B018 (property builds it)
                world_environment(world, world.scene(scene).name)
                known_object_names(world)
                if self._fetcher is None:
                    fetcher = self.fetcher()
                    fetcher.policies  # noqa: B018
                    if self.perception == "sensed":
                        fetcher.detector  # noqa: B018
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


def furniture_phrase(describer, world, scene: str, item, listener_in_room: bool = True) -> str:
    """A short phrase that singles furniture ``item`` out, "on the table in front of the couch",
    made by the describer for a thing placed on it (the generation layer's content selection)."""
    from assistant.errors import AssistantError
    from assistant.geometry import Pose2D
    from assistant.perception.objects import Sighting

    sighting = Sighting("thing", item.x, item.y, 0.8, room=item.room, seen_from=Pose2D(item.x, item.y, 0.0))
    listener = _room_pose(world, item.room) if listener_in_room else None
    try:
        result = describer.describe(sighting, world_environment(world, scene), world.floorplan,
                                    listener_pose=listener)
    except AssistantError:  # a phrase is a courtesy; fall back to the word
        return f"on the {item.word}"
    text = result.description.strip().rstrip(".")
    for lead in ("The thing is ", "the thing is "):
        if text.startswith(lead):
            text = text[len(lead):]
    return text


def _room_pose(world, room: str):
    from assistant.geometry import Pose2D

    for r in world.floorplan.rooms:
        if r.name == room:
            c = r.centre
            return Pose2D(float(c[0]), float(c[1]), 0.0)
    return None

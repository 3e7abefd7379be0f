"""The describer: a sighting and an environment model in, a human-like description out.

:class:`Describer` runs content selection (:mod:`assistant.generation.content`) and surface
realization (:mod:`assistant.generation.realize`) with a :class:`GenerationModel` learned from
the corpus. The search that produces the :class:`Sighting` is separate: today the
command line uses the *oracle search* (:func:`oracle_sighting`, the world file's position)
and the *oracle environment* (:func:`oracle_environment`, the world file's furniture); the
robot's search with perception will produce the same types.
"""

from __future__ import annotations

import time
from collections.abc import Iterator
from typing import NamedTuple

from assistant.errors import AssistantError, UnknownNameError
from assistant.generation.types import STYLES, GeneratedDescription
from assistant.grounding.objects import article
from assistant.perception.objects import Sighting

__all__ = ["DYNAMIC_QUESTION_WORDS", "Describer", "room_only_description", "known_objects", "not_found_description", "OracleCase", "oracle_cases",
           "oracle_environment", "oracle_sighting", "style_for_question"]

#: questions that ask for the way, not the place ("how do I get to my mug?")
DYNAMIC_QUESTION_WORDS = ("how do i get", "how do i find", "how can i get", "how can i find",
                          "how do i reach", "take me to", "way to")


def style_for_question(question: str) -> str:
    """``dynamic`` for "how do I get to my X?", else ``static`` ("where is my X?")."""
    q = " ".join(question.lower().split())
    return "dynamic" if any(w in q for w in DYNAMIC_QUESTION_WORDS) else "static"


class Describer:
    """Describes where a sighted object is. ``model``: a fitted
    :class:`~assistant.generation.model.GenerationModel` (default: trained from the repository
    corpus, cached); ``policies``: the :class:`~assistant.policy.library.PolicyLibrary` whose
    models also give furniture relations their probability (``"default"``: the repository's
    demonstrations; None, the default: the spatial relations alone — chosen by measurement,
    ``docs/generation.md``: with the policy models the descriptions are longer, median 16 →
    more words, because the learned "beside" model rates "by the bed" lower than the spatial
    layer does)."""

    def __init__(self, model=None, alpha: float | None = None, policies=None):
        if model is None:
            from assistant.generation.model import load_generation_model
            model = load_generation_model()
        self.model = model
        from assistant.generation.policy_score import PolicyRelationScore
        # P_Γ(y) of furniture relations also from the learned policy models (None: spatial only)
        self.policy_score = None if policies is None else PolicyRelationScore(
            None if policies == "default" else policies)
        from assistant.generation.content import ALPHA
        self.alpha = ALPHA if alpha is None else alpha
        self._warm_up()

    @staticmethod
    def _warm_up() -> None:
        """Load the spatial layer and fill its caches now, not when the object is found."""
        import assistant.generation.realize  # noqa: F401
        import assistant.generation.route  # noqa: F401
        from assistant.geometry import GridMap, box_polygon
        from assistant.spatial import dir_srv, dist_srv
        from assistant.world import Entity, EntityKind

        grid = GridMap(0.05, 0.0, 0.0, 40, 40)
        a = Entity.from_polygon("a", "couch", EntityKind.SHORT_TERM, box_polygon(0.2, 0.2, 0.8, 0.6), grid, 0.0)
        b = Entity.from_polygon("b", "table", EntityKind.SHORT_TERM, box_polygon(1.2, 1.2, 1.6, 1.6), grid)
        dir_srv(a, b)
        dist_srv(a, b)

    def describe(self, sighting: Sighting, environment_entities: list, floorplan,
                 listener_pose=None, style: str = "static") -> GeneratedDescription:
        """Describe ``sighting`` using the furniture in ``environment_entities`` (entities with
        ``name``, ``room`` and cells on one grid) and the floor plan. ``listener_pose``
        (:class:`~assistant.geometry.Pose2D`) filters the room out when the listener is in it
        and is where a ``dynamic`` description starts from."""
        from assistant.generation.content import candidate_nodes, select_content, support_of
        from assistant.generation.realize import chunk_options, realize
        from assistant.generation.route import route_nodes

        if style not in STYLES:
            raise UnknownNameError("description style", style, STYLES)
        if style == "dynamic" and listener_pose is None:
            raise AssistantError("a how-to-find (dynamic) description needs the listener's pose: "
                                 "give --listener X,Y,HEADING")
        start = time.perf_counter()
        furniture = [e for e in environment_entities if getattr(e, "kind", None) is None or
                     str(getattr(e.kind, "value", e.kind)) == "short_term"]
        furniture = [e for e in furniture if plausible_size(e)]
        support = support_of(sighting, furniture)
        if support is None:
            raise AssistantError(f"no furniture under the {sighting.name} at ({sighting.x_m:.2f}, "
                                 f"{sighting.y_m:.2f}) in the environment model; the generator "
                                 "describes objects lying on furniture")
        room = support.room or sighting.room
        route = route_nodes(floorplan, listener_pose, support, room) if style == "dynamic" else []
        says_room = any(n.key == "enter" for n in route)
        candidates = candidate_nodes(sighting, support, furniture, floorplan, listener_pose,
                                     include_room=not says_room, policy_score=self.policy_score)
        candidates = [c for c in candidates if c.forced or c.node.kind == "size"
                      or chunk_options(self.model, c.node, style)]
        listener_inside = (listener_pose is not None and
                           floorplan.room(room).contains(listener_pose.x, listener_pose.y))
        distractors = [e for e in furniture if e is not support and e.name == support.name
                       and (not (listener_inside or says_room) or e.room == room)]
        selected, value, ambiguous = select_content(candidates, self.model, distractors, self.alpha)
        size = [n for n in selected if n.kind == "size"]
        selected = [n for n in selected if n.kind != "size"]
        for n in selected:
            if n.kind == "support" and size:
                n.words = {**n.words, "support": size[0].words["support"]}
        nodes = route + selected
        text, top, said = realize(self.model, nodes, sighting.name, style)
        said = said + size
        tree = top[0] if len(top) == 1 else _wrap(top)
        elapsed = time.perf_counter() - start
        return GeneratedDescription(
            found=True, description=text, object=sighting.name, style=style, sighting=sighting,
            selected=said, candidates=[c.node for c in candidates], tree=tree, objective=value,
            ambiguous=ambiguous, composition_seconds=elapsed)


    def describe_search(self, result, floorplan, listener_pose=None, style: str = "static"
                        ) -> GeneratedDescription:
        """The answer after a sensed search (:class:`~assistant.executor.search.SearchResult`):
        composed from the environment model the search built (its perceived furniture), or the
        honest "I looked in … and did not find …" when it was not seen. ``search_seconds`` is
        the search's wall-clock time up to the sighting; the search report (rooms searched,
        path, simulated time…) is attached as ``search_report``."""
        report = result.to_dict()
        report.pop("furniture", None)
        report["furniture_perceived"] = len(result.furniture)
        search_s = result.found_at_wall_s if result.found_at_wall_s is not None else result.wall_seconds
        if not result.found:
            out = not_found_description(result.object, list(result.rooms_searched))
        else:
            try:
                out = self.describe(result.sighting, result.furniture, floorplan,
                                    listener_pose=listener_pose, style=style)
            except AssistantError as error:
                if "no furniture under" not in str(error):
                    raise
                out = room_only_description(result.sighting, style)
        out.search = "sensed"
        out.environment = "perceived"
        out.search_seconds = search_s
        out.searched_rooms = list(result.rooms_searched)
        out.search_report = report
        return out


#: the longest footprint side (metres) a perceived item of a category can have: a "chair"
#: 2 m long is a couch seen end-on, and a reference the perception has wrong makes a false
#: sentence — such items are left out of the description (not out of the model)
MAX_EXTENT_M = {"chair": 1.4}


def plausible_size(entity) -> bool:
    """Whether an entity's footprint fits its category word (see :data:`MAX_EXTENT_M`)."""
    limit = MAX_EXTENT_M.get(getattr(entity, "name", None))
    if limit is None or not len(getattr(entity, "cells", ())):
        return True
    pts = entity.points_m()
    extent = float((pts.max(axis=0) - pts.min(axis=0)).max()) + entity.grid.resolution_m
    return extent <= limit


def room_only_description(sighting: Sighting, style: str = "static") -> GeneratedDescription:
    """When perception found no furniture under the object: say only its room (true, short)."""
    verb = is_are(sighting.name)
    where = f" in the {sighting.room}" if sighting.room else " here"
    text = f"The {sighting.name} {verb}{where}."
    return GeneratedDescription(found=True, description=text, object=sighting.name, style=style,
                                sighting=sighting)


def _wrap(top):
    from assistant.generation.types import ChunkNode
    return ChunkNode("S", [], None, 1.0, [], list(top))


# ------------------------------------------------------------------------------ oracle search
def known_objects(world=None) -> list[str]:
    """Object names the robot knows how to look for: every object of the packaged worlds (and
    of ``world``)."""
    from assistant.world import load_world, world_names

    names = set()
    for name in world_names():
        w = load_world(name)
        for scene in w.scenes.values():
            names.update(o.name for o in scene.objects)
    if world is not None:
        for scene in world.scenes.values():
            names.update(o.name for o in scene.objects)
    return sorted(names)


def oracle_sighting(world, scene: str, name: str) -> Sighting | None:
    """The object's position from the world file (the oracle search), or None when the scene
    has no such object (any thing may be asked about)."""
    key = " ".join(name.lower().split())
    sc = world.scene(scene)
    for obj in sc.objects:
        if obj.name.lower() == key:
            room = world.floorplan.room_at(obj.x, obj.y)
            return Sighting(obj.name, obj.x, obj.y, sc.object_height_m(obj),
                            room=room.name if room else sc.item(obj.on).room, seen_from=world.start)
    return None  # any thing can be asked about; this scene has none (open vocabulary, issue 16)


def oracle_environment(world, scene: str, resolution_m: float = 0.05) -> list:
    """The ground-truth furniture of the scene as entities (oracle environment model)."""
    from assistant.world import furniture_entities, world_grid

    return furniture_entities(world, scene, world_grid(world, resolution_m))


class OracleCase(NamedTuple):
    """One object of one scene, with the oracle environment of that scene."""

    world_name: str  # as given (a packaged name or a world-file path)
    world: object
    scene: str
    obj: object  # the PlacedObject
    environment: list
    sighting: Sighting


def oracle_cases(world_names, scenes=("original", "modified")) -> Iterator[OracleCase]:
    """Every object of every scene of the named worlds, read from the world files (the
    evaluation's and the benchmark's cases); the environment is built once per scene."""
    from assistant.world import load_world

    for name in world_names:
        world = load_world(name)
        for scene in scenes:
            environment = oracle_environment(world, scene)
            for obj in world.scene(scene).objects:
                yield OracleCase(name, world, scene, obj, environment,
                                 oracle_sighting(world, scene, obj.name))


def some(name: str) -> str:
    """The object said as one of its kind: "a wallet", "an envelope", "any keys", "any mail"."""
    from assistant.world.catalogue import load_catalogue

    if load_catalogue().number(name) != "one":
        return f"any {name}"
    return f"{article(name)} {name}"


def is_are(name: str) -> str:
    """The verb "be" agreeing with an object's name: "the keys are", "the mail is"."""
    from assistant.world.catalogue import load_catalogue

    return "are" if load_catalogue().number(name) == "plural" else "is"


def it_them(name: str) -> str:
    """The pronoun for an object: "them" for the keys, "it" for the wallet or the mail."""
    from assistant.world.catalogue import load_catalogue

    return "them" if load_catalogue().number(name) == "plural" else "it"


def not_found_description(name: str, rooms: list[str]) -> GeneratedDescription:
    """The honest answer when the search found nothing."""
    rooms = [r for r in rooms]
    if not rooms:
        where = "anywhere I could reach"
    elif len(rooms) == 1:
        where = f"in the {rooms[0]}"
    else:
        where = "in the " + ", the ".join(rooms[:-1]) + f" and the {rooms[-1]}"
    text = f"I looked {where} and did not find {some(name)}."
    return GeneratedDescription(found=False, description=text, object=name, searched_rooms=rooms)

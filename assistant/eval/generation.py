"""``assistant eval generation``: Table 6-1 of the dissertation, reproduced on this product.

The 24 objects of the four study homes in both scenes (48 descriptions). For each, the simulated
robot first *searches* the home from the world's start pose (:mod:`assistant.executor.search`:
room by room, furniture perceived from depth, the object seen by the simulator's object
detector), and the description is composed from the environment model that search built
(``--search oracle``: the world file's object position and furniture instead). Search success
(found, and found where it is) is reported first; then each description is scored:

(a) **truth** — the sentence is *parsed back* (``assistant.language`` + ``assistant.grounding``:
    text → plan → RDT nodes) and every stated relation is checked against the world's ground
    truth with the spatial layer: the stated room is the object's room, the stated support is
    the furniture it lies on, a furniture direction is the strongest of the reference's four
    DIR-SRV words (front, left, back, right; weight ≥ 0.4) and its DIST-SRV is not mostly
    ``far``, ``beside`` is near (DIST-SRV superposition + near ≥ 0.5), a wall is within
    0.6 m of the support on the stated side (seen on entering the room), "the middle of the
    room" is within a quarter of the room's width of its centre, "near the door" within 1 m.
    ``unique``: the stated room and relations hold for no other furniture with the support's
    word. ``recovered``: the parse found every relation the generator meant to say.
(b) **listener** — each description is handed to the simulated robot as a fetch command
    (the application layer's :meth:`~assistant.app.Fetcher.fetch`, ``assistant fetch``'s, from the world's start pose, with sensed perception by
    default, ``--listener-perception oracle`` to separate language from perception errors) and
    counts when the object ends up in the final camera view. ``--no-listener`` skips it.
(c) **brevity and fluency** — word count, repeated phrases, and agreement with the corpus's
    human static descriptions of the same object in the same home: BLEU-2 (NLTK, smoothed)
    against them, and the share of our stated relations (reference-direction) that people also
    used there.

Targets (issue "Where is my X?"): 48/48 with every stated relation true and no repeated phrase,
median length ≤ 16 words.
"""

from __future__ import annotations

import math
import statistics
import time
from dataclasses import dataclass

from assistant.eval.progress import Progress, no_progress
from assistant.world import load_catalogue

STUDY_WORLDS = ("apartment", "hk-studio", "one-bedroom-house", "two-bedrooms-house")
SCENES = ("original", "modified")
MIN_DIRECTION = 0.4
WALL_MAX_M = 0.6
DOOR_MAX_M = 1.0
#: the dissertation's Table 6-1: descriptions with every stated relation true, of 48
DISSERTATION_TRUE = (43, 48)


# ------------------------------------------------------------------------------ ground truth
def _check_rdt(rdt, support, entities, room, floorplan, heading) -> tuple[bool, str]:
    """Whether one stated RDT (reference, direction, target) holds for ``support``."""
    from assistant.generation.content import BACK_DEPTH, room_depth, wall_side
    from assistant.spatial import dir_srv, dist_srv

    ref, direction, target = rdt.reference, rdt.direction, rdt.target
    if target != support.name:
        return False, f"target {target!r} is not the {support.name} it lies on"
    if ref == "room" and direction == "center":
        poly = room.polygon_array
        size = float(min(poly.max(axis=0) - poly.min(axis=0)))
        centre = (poly.max(axis=0) + poly.min(axis=0)) / 2
        d = float(((support.centroid_m - centre) ** 2).sum() ** 0.5)
        return d <= 0.25 * size, f"{d:.2f} m from the room centre (max {0.25 * size:.2f})"
    if ref == "room" and direction == "back":
        if heading is None:
            return False, "the back of the room cannot be told (no door)"
        u = room_depth(room, heading, support.centroid_m)
        return u >= BACK_DEPTH, f"{u:.2f} of the way into the room (min {BACK_DEPTH:.2f})"
    if ref == "wall":
        if heading is None or direction not in ("left", "right", "back"):
            return False, f"wall side {direction!r} cannot be told"
        offset = {"left": math.pi / 2, "right": -math.pi / 2, "back": 0.0}[direction]
        _, axis, coord = wall_side(room, heading + offset)
        d = float(abs(support.points_m()[:, axis] - coord).min())
        return d <= WALL_MAX_M, f"{d:.2f} m from the {direction} wall"
    if ref == "door":
        doors = floorplan.doors_of(room.name)
        d = min((float(min(((support.points_m() - door.centre) ** 2).sum(axis=1)) ** 0.5)
                 for door in doors), default=math.inf)
        return d <= DOOR_MAX_M, f"{d:.2f} m from a door"
    refs = [e for e in entities if e.name == ref and e.room == room.name and e is not support]
    if not refs:
        return False, f"no {ref} in the {room.name}"
    reasons = []
    for e in refs:
        dist = dist_srv(e, support).as_dict()
        if direction == "beside":
            near = dist["superposition"] + dist["near"]
            if near >= 0.5:
                return True, f"{e.id}: near {near:.2f}"
            reasons.append(f"{e.id}: near {near:.2f}")
            continue
        d = dir_srv(e, support, heading)
        if d is None:
            reasons.append(f"{e.id}: no frame")
            continue
        outer = {w: d[w] for w in ("front", "left", "back", "right")}
        best = max(outer, key=outer.get)
        far = max(dist, key=dist.get) == "far"
        if best == direction and outer[direction] >= MIN_DIRECTION and not far:
            return True, f"{e.id}: {direction} {outer[direction]:.2f}"
        reasons.append(f"{e.id}: strongest {best} {outer[best]:.2f}, {direction} "
                       f"{outer.get(direction, 0):.2f}{', far' if far else ''}")
    return False, "; ".join(reasons)


def _holds_for(rdts, item, entities, room, floorplan, heading) -> bool:
    return all(_check_rdt(r, item, entities, room, floorplan, heading)[0] for r in rdts)


# ------------------------------------------------------------------------------ corpus agreement
def _human_descriptions(corpus_paths=None) -> dict:
    """(world, object) → list of (tokens, set of reference-direction) of static descriptions."""
    from assistant.generation.model import corpus_files
    from assistant.grounding import read_chunk_groundings
    from assistant.language import read_corpus

    xmls, csvs = corpus_files(corpus_paths)
    out: dict = {}
    for i, x in enumerate(xmls):
        descs = read_corpus(x).descriptions
        labels = {c.number: c for c in read_chunk_groundings(csvs[min(i, len(csvs) - 1)]).commands}
        for d in descs:
            if d.attributes.get("kind") != "static":
                continue
            key = (d.attributes.get("world"), d.attributes.get("object"))
            cmd = labels.get(str(d.number))
            pairs = set()
            if cmd is not None:
                for g in cmd.groundings:
                    if g.reference and g.direction:
                        pairs.add(f"{g.reference}-{g.direction}")
            out.setdefault(key, []).append(([w.lower() for w in d.tree.words], pairs))
    return out


def _bleu2(words: list[str], references: list[list[str]]) -> float | None:
    if not references:
        return None
    from nltk.translate.bleu_score import SmoothingFunction, sentence_bleu

    return float(sentence_bleu(references, words, weights=(0.5, 0.5),
                               smoothing_function=SmoothingFunction().method1))


# ------------------------------------------------------------------------------ run
@dataclass
class _Tools:
    """What every case of one evaluation uses: the describer, the parser (``None``: check the
    generator's own nodes), the corpus's human descriptions, the listener's fetcher (the
    application layer's fetch use case, ``None`` without the listener), the "where is" use case
    (search, then describe) and the furniture detector of the searches (``None`` when not
    needed)."""

    describer: object
    parser: object
    parser_note: str | None
    humans: dict
    runner: object
    listener_note: str
    furniture_detector: object
    finder: object = None


def _tools(corpus_paths, parse: bool, listener: bool, search: str, policies: bool) -> _Tools:
    from assistant.generation import Describer, load_generation_model

    describer = Describer(load_generation_model(corpus_paths), policies="default" if policies else None)
    parser = None
    parser_note = None
    if parse:
        try:
            from assistant.grounding import CommandParser
            parser = CommandParser.load(corpus_paths=corpus_paths)
        except (ImportError, AttributeError) as error:  # the language layer is not usable
            parser_note = f"parser unavailable ({error}); checked the generator's own nodes"
    humans = _human_descriptions(corpus_paths)
    runner = None
    listener_note = "not measured (--no-listener)"
    furniture_detector = None
    if listener or search == "sensed":
        from assistant.perception import FurnitureDetector

        furniture_detector = FurnitureDetector()
    from assistant.app import Fetcher, Finder

    if listener:
        runner = Fetcher(parser=parser, detector=furniture_detector) if parser is not None \
            else Fetcher(detector=furniture_detector)
    return _Tools(describer, parser, parser_note, humans, runner, listener_note, furniture_detector,
                  Finder(describer, furniture_detector))


def evaluate(worlds=STUDY_WORLDS, corpus_paths=None, parse: bool = True,
             progress: Progress = no_progress, listener: bool = False, search: str = "oracle",
             miss_rate: float = 0.0, listener_perception: str = "sensed",
             searches: dict | None = None, policies: bool = False) -> dict:
    """Search (``sensed``) or read (``oracle``) each object, compose and score the
    descriptions; returns ``{"rows": [...], "summary": {...}, "searches": {...}}``.
    ``searches`` (``(world, scene, object) → SearchResult``) reuses finished searches instead of
    searching again; the returned ``searches`` are this run's. ``progress`` hears one line per
    description."""
    from assistant.generation import oracle_cases

    tools = _tools(corpus_paths, parse, listener, search, policies)
    rows = []
    done: dict = {}
    t_start = time.perf_counter()
    for case in oracle_cases(worlds, SCENES):
        found = None
        if search == "sensed":
            found = (searches or {}).get((case.world_name, case.scene, case.obj.name))
            if found is None:
                found = tools.finder.search(case.obj.name, case.world, case.scene, miss_rate=miss_rate)
            done[(case.world_name, case.scene, case.obj.name)] = found
        row = score_case(case, found, tools, listener_perception)
        rows.append(row)
        progress(_case_line(row), len(rows))
    summary = summarise(rows, tools, search, listener_perception)
    summary["wall_seconds"] = round(time.perf_counter() - t_start, 1)
    summary["targets"] = {"true_and_no_repeat": len(rows), "median_words_max": 16,
                          "listener_min": math.ceil(0.95 * len(rows))}
    return {"rows": rows, "summary": summary, "searches": done}


def _case_line(row: dict) -> str:
    extra = ""
    if row["search"]:
        extra += f" [search {'found' if row['search']['found'] else 'NOT found'} in {row['search']['wall_seconds']} s]"
    if row["listener"] is not None:
        extra += f" [listener {'ok' if row['listener']['success'] else row['listener']['failure']}]"
    return f"{row['world']} {row['scene']} {row['object']}: {row['description']}{extra}"


def _search_row(found, obj, room) -> dict:
    """How the robot's search for ``obj`` went, against the ground truth."""
    error_m = (math.hypot(found.sighting.x_m - obj.x, found.sighting.y_m - obj.y)
               if found.found else None)
    right_place = bool(found.found and found.sighting.room == room.name and error_m <= 0.3)
    return {"found": found.found, "right_place": right_place,
            "position_error_m": None if error_m is None else round(error_m, 3),
            "room_seen": found.sighting.room if found.found else None,
            "support_perceived": found.sighting.furniture_category if found.sighting else None,
            "rooms_searched": found.rooms_searched, "path_m": round(found.path_m, 2),
            "sim_seconds": round(found.sim_seconds, 1),
            "wall_seconds": round(found.wall_seconds, 2),
            "furniture_perceived": len(found.furniture), "status": found.status}


def _stated(result, parser, obj, meant) -> tuple:
    """(room, object, support, RDTs) the description states: parsed back from its text, or the
    generator's own nodes without a parser."""
    from assistant.grounding.types import RDT

    if parser is not None:
        plan = parser.parse(result.description).plan
        rdts = [r for node in plan.nodes for r in node.rdts]
        rdts = [r for r in rdts if not (str(r) == f"room-center-{r.target}"
                                        and f"room-center-{r.target}" not in meant)]
        return plan.room, plan.object, (plan.nodes[-1].target if plan.nodes else None), rdts
    room = next((n.words["room"] for n in result.selected if n.kind == "room"), None)
    support = next((n.words.get("support") for n in result.selected if n.kind == "support"), None)
    if support in _size_words():  # "end table" is a table
        support = "table"
    return room, obj.name, support, [RDT.parse(r) for r in sorted(meant)]


def _truth(result, stated, case, support, room, heading, said_room) -> tuple[list, list]:
    """(problems, checks): each stated fact against the ground truth."""
    stated_room, stated_object, stated_support, rdts = stated
    problems, checks = [], []
    if stated_object != case.obj.name:
        problems.append(f"object read as {stated_object!r}")
    if said_room and stated_room != room.name:
        problems.append(f"room read as {stated_room!r}, is {room.name!r}")
    if result.tree is not None and stated_support != support.name:
        problems.append(f"support read as {stated_support!r}, is {support.name!r}")
    size = _support_size_problem(result.description, support)
    if size:
        problems.append(size)
    for r in rdts:
        ok, why = _check_rdt(r, support, case.environment, room, case.world.floorplan, heading)
        checks.append({"rdt": str(r), "true": ok, "why": why})
        if not ok:
            problems.append(f"{r}: {why}")
    return problems, checks


def _singles_out(result, rdts, case, support, room, said_room, listener_pose) -> bool:
    """Whether the stated room and relations hold for no other furniture with the support's word."""
    from assistant.generation.entry import entry_heading

    env, floorplan, text = case.environment, case.world.floorplan, result.description
    same = [e for e in env if e is not support and e.name == support.name
            and (not said_room or e.room == room.name)]
    return bool(result.found) and not any(
        _holds_for(rdts, e, env, floorplan.room(e.room), floorplan,
                   entry_heading(floorplan, e.room, listener_pose)) and not _size_rules_out(text, e)
        for e in same)


def listener_check(fetcher, result, world_name: str, scene: str, object_name: str,
                   perception: str = "sensed", on_pose=None) -> dict | None:
    """(b), the listener: a description (``result``, the describer's
    :class:`~assistant.generation.types.GeneratedDescription`) handed to the simulated robot as a
    fetch command from the world's start pose (``fetcher``: an :class:`~assistant.app.Fetcher`,
    None for no check); ``{"success", "failure", "message", "target", "nodes"}`` — success
    when ``object_name`` ends up in the robot's final camera view; ``on_pose(pose)`` hears the
    robot's true pose now and then."""
    from assistant.errors import AssistantError

    if fetcher is None:
        return None
    if not result.found:
        return {"success": False, "failure": "not found by the search"}
    try:
        outcome = fetcher.fetch(result.description, world_name, scene, perception, object_name=object_name,
                                on_pose=on_pose)
        return {"success": outcome.success, "failure": outcome.data.get("failure"),
                "message": outcome.data["executor"]["message"],
                "target": (outcome.data["executor"].get("target_furniture") or {}).get("centre"),
                "nodes": [n.get("rdt") for n in outcome.data.get("nodes", [])]}
    except (AssistantError, RuntimeError, ValueError, KeyError) as error:
        return {"success": False, "failure": f"error: {error}"}


def score_case(case, found, tools: _Tools, listener_perception: str = "sensed") -> dict:
    """One row of Table 6-1: ``case`` (an :class:`~assistant.generation.describer.OracleCase`)
    described from the finished search ``found`` (``None``: from the world file), its truth,
    uniqueness, listener fetch, brevity and agreement with people."""
    from assistant.generation import repeated_phrases
    from assistant.generation.content import support_of
    from assistant.generation.entry import entry_heading

    # ground truth (evaluation only): the object's true support and the true furniture
    support = support_of(case.sighting, case.environment)
    floorplan = case.world.floorplan
    room = floorplan.room(support.room)
    # the person asking stands where the robot was asked, the world's start pose: walls are
    # named ("the back wall") as they walk into the room from there
    listener_pose = case.world.start
    heading = entry_heading(floorplan, room.name, listener_pose)
    t0 = time.perf_counter()
    # where is it: described from the finished search, or (oracle) from the world file
    result = tools.finder.where_is(case.obj.name, case.world, case.scene, listener=listener_pose,
                                   search="sensed" if found is not None else "oracle", searched=found).description
    compose_ms = (time.perf_counter() - t0) * 1000
    text = result.description
    meant = {n.rdt for n in result.selected if n.kind == "relation"}
    said_room = any(n.kind == "room" for n in result.selected)
    if result.found:
        stated = _stated(result, tools.parser, case.obj, meant)
        problems, checks = _truth(result, stated, case, support, room, heading, said_room)
    else:
        stated = (None, None, None, [])
        problems, checks = ["not found by the search"], []
    rdts = stated[3]
    words = [w.strip(",.").lower() for w in text.split()]
    refs = tools.humans.get((case.world_name, case.obj.name), [])
    ours = {f"{r.reference}-{r.direction}" for r in rdts}
    people = set().union(*[p for _, p in refs]) if refs else set()
    return {
        "listener": listener_check(tools.runner, result, case.world_name, case.scene, case.obj.name,
                                   listener_perception),
        "search": None if found is None else _search_row(found, case.obj, room),
        "world": case.world_name, "scene": case.scene, "object": case.obj.name, "description": text,
        "support_id": support.id, "support_at": [round(float(v), 2) for v in support.centroid_m],
        "nodes": result.nodes, "stated": [str(r) for r in rdts],
        "true": result.found and not problems, "problems": problems, "checks": checks,
        "unique": _singles_out(result, rdts, case, support, room, said_room, listener_pose),
        "flagged_ambiguous": result.ambiguous, "recovered": meant <= {str(r) for r in rdts},
        "words": len(words), "repeated": repeated_phrases(text),
        "bleu2": _bleu2(words, [w for w, _ in refs]),
        "human_relation_agreement": (len(ours & people) / len(ours)) if ours and refs else None,
        "human_descriptions": len(refs),
        "compose_ms": compose_ms,
    }


def summarise(rows: list[dict], tools: _Tools, search: str, listener_perception: str) -> dict:
    """The summary figures of Table 6-1's rows (without the run's time and the targets)."""
    n = len(rows)
    bleus = [r["bleu2"] for r in rows if r["bleu2"] is not None]
    agree = [r["human_relation_agreement"] for r in rows if r["human_relation_agreement"] is not None]
    searched = [r["search"] for r in rows if r["search"]]
    listened = sum(bool(r["listener"] and r["listener"]["success"]) for r in rows)
    return {
        "descriptions": n,
        "search": search,
        "search_found": sum(s["found"] for s in searched) if searched else None,
        "search_right_place": sum(s["right_place"] for s in searched) if searched else None,
        "median_search_wall_seconds": statistics.median(s["wall_seconds"] for s in searched) if searched else None,
        "median_search_sim_seconds": statistics.median(s["sim_seconds"] for s in searched) if searched else None,
        "median_search_path_m": statistics.median(s["path_m"] for s in searched) if searched else None,
        "all_relations_true": sum(r["true"] for r in rows),
        "no_repeated_phrase": sum(not r["repeated"] for r in rows),
        "true_and_no_repeat": sum(r["true"] and not r["repeated"] for r in rows),
        "unique": sum(r["unique"] for r in rows),
        "flagged_ambiguous": sum(r["flagged_ambiguous"] for r in rows),
        "recovered_by_parse": sum(r["recovered"] for r in rows) if tools.parser is not None else None,
        "median_words": statistics.median(r["words"] for r in rows) if rows else None,
        "max_words": max((r["words"] for r in rows), default=None),
        "median_bleu2": statistics.median(bleus) if bleus else None,
        "mean_human_relation_agreement": statistics.fmean(agree) if agree else None,
        "median_compose_ms": statistics.median(r["compose_ms"] for r in rows) if rows else None,
        "truth_checked_by": "parse" if tools.parser is not None else "generator nodes",
        "parser_note": tools.parser_note,
        "listener_success": listened if tools.runner is not None else None,
        "listener": (f"{listened}/{n} descriptions followed by the simulated robot (assistant fetch "
                     f"from the start pose, {listener_perception} perception) to a view of the object"
                     if tools.runner is not None else tools.listener_note),
    }


def _size_words() -> dict[str, str]:
    """Table words that claim one size (``desk`` → large table), from the catalogue."""
    catalogue = load_catalogue()
    return {w: c for w in catalogue.words.furniture
            if (c := catalogue.suggested_category(w)) in ("small table", "large table")}


def _said_support_word(text: str) -> str | None:
    t = " ".join(text.lower().split())
    for word in _size_words():
        if f"the {word}" in t:
            return word
    return None


def _support_size_problem(text: str, support) -> str | None:
    word = _said_support_word(text)
    if word is None:
        return None
    if support.category != _size_words()[word]:
        return f"said {word!r} for a {support.category}"
    return None


def _size_rules_out(text: str, item) -> bool:
    word = _said_support_word(text)
    return word is not None and item.category != _size_words()[word]

"""``assistant eval generation``: Table 6-1 of the dissertation, reproduced on this product.

The 24 objects of the four study homes in both scenes (48 descriptions). For each, the simulated
robot first *searches* the home from the world's start pose (:mod:`assistant.generation.search`:
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
    (``assistant fetch``'s runner, from the world's start pose, with sensed perception by
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

from assistant.world import load_catalogue

STUDY_WORLDS = ("apartment", "hk-studio", "one-bedroom-house", "two-bedrooms-house")
SCENES = ("original", "modified")
MIN_DIRECTION = 0.4
WALL_MAX_M = 0.6
DOOR_MAX_M = 1.0


def add_arguments(parser) -> None:
    from assistant.cli.common import miss_probability
    from assistant.generation.types import SEARCH_MODES

    parser.add_argument("--worlds", nargs="+", default=list(STUDY_WORLDS), metavar="WORLD",
                        help="worlds to describe (default: the four study homes)")
    parser.add_argument("--corpus", action="append", metavar="PATH",
                        help="annotated corpus to learn from (default: the repository's corpus/)")
    parser.add_argument("--search", choices=SEARCH_MODES, default="sensed",
                        help="sensed (default): the simulated robot searches and the description "
                             "uses its perceived furniture; oracle: the world file")
    parser.add_argument("--miss-rate", type=miss_probability, default=0.0, metavar="P",
                        help="object detector miss rate during the search (default 0)")
    parser.add_argument("--save-searches", metavar="FILE",
                        help="write the finished searches to FILE (pickle) to re-score later")
    parser.add_argument("--searches", metavar="FILE",
                        help="re-use searches written by --save-searches instead of searching again "
                             "(the descriptions and the listener test are run anew)")
    parser.add_argument("--listener", action="store_true", default=True,
                        help="hand each description to the simulated robot as a fetch command "
                             "(the default; a few seconds per description)")
    parser.add_argument("--no-listener", dest="listener", action="store_false",
                        help="skip the listener test")
    parser.add_argument("--listener-perception", choices=("sensed", "oracle"), default="sensed",
                        help="the listener robot's furniture perception (default sensed)")
    parser.add_argument("--policy-probabilities", action="store_true",
                        help="furniture relations' P also from the learned policy models (geometric "
                             "mean with the spatial relations'); default: spatial relations alone")
    parser.add_argument("--no-parse", action="store_true",
                        help="check the generator's own selected nodes instead of parsing the "
                             "sentence back (faster; does not test the wording)")


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
    from assistant.generation.model import _corpus_files
    from assistant.grounding import read_chunk_groundings
    from assistant.language import read_corpus

    xmls, csvs = _corpus_files(corpus_paths)
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
def evaluate(worlds=STUDY_WORLDS, corpus_paths=None, parse: bool = True, log=None,
             listener: bool = False, search: str = "oracle", miss_rate: float = 0.0,
             listener_perception: str = "sensed", searches: dict | None = None,
             policies: bool = False) -> dict:
    """Search (``sensed``) or read (``oracle``) each object, compose and score the
    descriptions; returns ``{"rows": [...], "summary": {...}}``. ``searches`` (``(world,
    scene, object) → SearchResult``) reuses finished searches instead of searching again."""
    from assistant.errors import AssistantError
    from assistant.generation import Describer, load_generation_model, oracle_cases, repeated_phrases
    from assistant.generation.content import entry_heading, support_of
    from assistant.grounding.types import RDT

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
    if listener:
        try:
            from assistant.executor.trial import FetchRunner
            runner = FetchRunner(parser=parser, detector=furniture_detector) if parser is not None \
                else FetchRunner(detector=furniture_detector)
        except ImportError as error:
            listener_note = f"not measured: assistant fetch is not available ({error})"
    rows = []
    done: dict = {}
    t_start = time.perf_counter()
    for wname, world, scene, obj, env, sighting in oracle_cases(worlds, SCENES):
        # ground truth (evaluation only): the object's true support and the true furniture
        support = support_of(sighting, env)
        room = world.floorplan.room(support.room)
        # the person asking stands where the robot was asked, the world's start pose: walls are
        # named ("the back wall") as they walk into the room from there
        listener_pose = world.start
        heading = entry_heading(world.floorplan, room.name, listener_pose)
        search_row = None
        if search == "sensed":
            from assistant.generation.search import search_for

            found = (searches or {}).get((wname, scene, obj.name))
            if found is None:
                found = search_for(obj.name, world, scene, furniture_detector=furniture_detector,
                                   miss_rate=miss_rate)
            done[(wname, scene, obj.name)] = found
            t0 = time.perf_counter()
            result = describer.describe_search(found, world.floorplan, listener_pose=listener_pose)
            compose_ms = (time.perf_counter() - t0) * 1000
            error_m = (math.hypot(found.sighting.x - obj.x, found.sighting.y - obj.y)
                       if found.found else None)
            right_place = bool(found.found and found.sighting.room == room.name and error_m <= 0.3)
            search_row = {"found": found.found, "right_place": right_place,
                          "position_error_m": None if error_m is None else round(error_m, 3),
                          "room_seen": found.sighting.room if found.found else None,
                          "support_perceived": found.placed.furniture_category if found.placed else None,
                          "rooms_searched": found.rooms_searched, "path_m": round(found.path_m, 2),
                          "sim_seconds": round(found.sim_seconds, 1),
                          "wall_seconds": round(found.wall_seconds, 2),
                          "furniture_perceived": len(found.furniture), "status": found.status}
        else:
            t0 = time.perf_counter()
            result = describer.describe(sighting, env, world.floorplan, listener_pose=listener_pose)
            compose_ms = (time.perf_counter() - t0) * 1000
        text = result.description
        meant = {n.rdt for n in result.selected if n.kind == "relation"}
        if not result.found:
            rdts, problems, checks = [], ["not found by the search"], []
            stated_room = stated_object = stated_support = None
        elif parser is not None:
            plan = parser.parse(text).plan
            stated_room = plan.room
            stated_object = plan.object
            stated_support = plan.nodes[-1].target if plan.nodes else None
            rdts = [r for node in plan.nodes for r in node.rdts]
            rdts = [r for r in rdts if not (str(r) == f"room-center-{r.target}"
                                            and f"room-center-{r.target}" not in meant)]
        else:
            stated_room = next((n.words["room"] for n in result.selected if n.kind == "room"), None)
            stated_object = obj.name
            stated_support = next((n.words.get("support") for n in result.selected if n.kind == "support"),
                                  None)
            if stated_support in _size_words():  # "end table" is a table
                stated_support = "table"
            rdts = [RDT.parse(r) for r in sorted(meant)]
        said_room = any(n.kind == "room" for n in result.selected)
        if result.found:
            problems, checks = [], []
            if stated_object != obj.name:
                problems.append(f"object read as {stated_object!r}")
            if said_room and stated_room != room.name:
                problems.append(f"room read as {stated_room!r}, is {room.name!r}")
            if result.tree is not None and stated_support != support.name:
                problems.append(f"support read as {stated_support!r}, is {support.name!r}")
            size = _support_size_problem(text, support)
            if size:
                problems.append(size)
            for r in rdts:
                ok, why = _check_rdt(r, support, env, room, world.floorplan, heading)
                checks.append({"rdt": str(r), "true": ok, "why": why})
                if not ok:
                    problems.append(f"{r}: {why}")
        same = [e for e in env if e is not support and e.name == support.name
                and (not said_room or e.room == room.name)]
        unique = bool(result.found) and not any(
            _holds_for(rdts, e, env, world.floorplan.room(e.room), world.floorplan,
                       entry_heading(world.floorplan, e.room, listener_pose)) and not _size_rules_out(text, e)
            for e in same)
        recovered = meant <= {str(r) for r in rdts}
        words = [w.strip(",.").lower() for w in text.split()]
        refs = humans.get((wname, obj.name), [])
        ours = {f"{r.reference}-{r.direction}" for r in rdts}
        people = set().union(*[p for _, p in refs]) if refs else set()
        fetched = None
        if runner is not None and result.found:
            try:
                outcome = runner.run(text, wname, scene, listener_perception, object_name=obj.name)
                fetched = {"success": outcome.success, "failure": outcome.data.get("failure"),
                           "message": outcome.data["executor"]["message"],
                           "target": (outcome.data["executor"].get("target_furniture") or {}).get("centre"),
                           "nodes": [n.get("rdt") for n in outcome.data.get("nodes", [])]}
            except (AssistantError, RuntimeError, ValueError, KeyError) as error:
                fetched = {"success": False, "failure": f"error: {error}"}
        elif runner is not None:
            fetched = {"success": False, "failure": "not found by the search"}
        rows.append({
            "listener": fetched, "search": search_row,
            "world": wname, "scene": scene, "object": obj.name, "description": text,
            "support_id": support.id, "support_at": [round(float(v), 2) for v in support.centroid_m],
            "nodes": result.nodes, "stated": [str(r) for r in rdts],
            "true": result.found and not problems, "problems": problems, "checks": checks,
            "unique": unique, "flagged_ambiguous": result.ambiguous, "recovered": recovered,
            "words": len(words), "repeated": repeated_phrases(text),
            "bleu2": _bleu2(words, [w for w, _ in refs]),
            "human_relation_agreement": (len(ours & people) / len(ours)) if ours and refs else None,
            "human_descriptions": len(refs),
            "compose_ms": compose_ms,
        })
        if log:
            extra = ""
            if search_row:
                extra += f" [search {'found' if search_row['found'] else 'NOT found'} in {search_row['wall_seconds']} s]"
            if fetched is not None:
                extra += f" [listener {'ok' if fetched['success'] else fetched['failure']}]"
            log(f"{wname} {scene} {obj.name}: {text}{extra}")
    n = len(rows)
    bleus = [r["bleu2"] for r in rows if r["bleu2"] is not None]
    agree = [r["human_relation_agreement"] for r in rows if r["human_relation_agreement"] is not None]
    searched = [r["search"] for r in rows if r["search"]]
    summary = {
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
        "recovered_by_parse": sum(r["recovered"] for r in rows) if parser is not None else None,
        "median_words": statistics.median(r["words"] for r in rows) if rows else None,
        "max_words": max((r["words"] for r in rows), default=None),
        "median_bleu2": statistics.median(bleus) if bleus else None,
        "mean_human_relation_agreement": statistics.fmean(agree) if agree else None,
        "median_compose_ms": statistics.median(r["compose_ms"] for r in rows) if rows else None,
        "truth_checked_by": "parse" if parser is not None else "generator nodes",
        "parser_note": parser_note,
        "listener_success": (sum(bool(r["listener"] and r["listener"]["success"]) for r in rows)
                             if runner is not None else None),
        "listener": (f"{sum(bool(r['listener'] and r['listener']['success']) for r in rows)}/{n} "
                     "descriptions followed by the simulated robot (assistant fetch from the start "
                     f"pose, {listener_perception} perception) to a view of the object"
                     if runner is not None else listener_note),
        "wall_seconds": round(time.perf_counter() - t_start, 1),
        "targets": {"true_and_no_repeat": n, "median_words_max": 16, "listener_min": math.ceil(0.95 * n)},
    }
    return {"rows": rows, "summary": summary, "searches": done}


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


def run(args) -> int:
    import sys

    from assistant.cli.common import emit_json, print_table

    searches = None
    if args.searches:
        import pickle

        from assistant.errors import DataFileError

        try:
            with open(args.searches, "rb") as fh:
                searches = pickle.load(fh)
        except (OSError, pickle.UnpicklingError, EOFError, AttributeError) as error:
            raise DataFileError(args.searches, "searches", f"cannot be read ({error}); write it with "
                                "--save-searches") from error
    report = evaluate(args.worlds, args.corpus, parse=not args.no_parse,
                      log=None if args.json else (lambda m: print(m, file=sys.stderr, flush=True)),
                      listener=args.listener, search=args.search, miss_rate=args.miss_rate,
                      listener_perception=args.listener_perception, searches=searches,
                      policies=args.policy_probabilities)
    if args.save_searches:
        import pickle

        from assistant.fileio import atomic_write_bytes

        atomic_write_bytes(args.save_searches, pickle.dumps(report.pop("searches")))
    else:
        report.pop("searches", None)
    if args.json:
        emit_json(report)
        return 0
    rows = report["rows"]
    s = report["summary"]
    print(f"Table 6-1 (reproduced): generated descriptions of the study objects, {s['search']} search\n")

    def lis(r):
        if r["listener"] is None:
            return "-"
        return "yes" if r["listener"]["success"] else r["listener"]["failure"]

    def found(r):
        if r["search"] is None:
            return "oracle"
        return ("yes" if r["search"]["right_place"] else "wrong") if r["search"]["found"] else "NO"

    print_table([(i + 1, r["world"], r["scene"][:4], r["object"], found(r), r["description"], r["words"],
                  "yes" if r["true"] else "NO", "yes" if r["unique"] else "no",
                  ", ".join(r["repeated"]) or "-", lis(r),
                  "-" if r["bleu2"] is None else f"{r['bleu2']:.2f}",
                  "-" if r["human_relation_agreement"] is None else f"{r['human_relation_agreement']:.2f}")
                 for i, r in enumerate(rows)],
                ["#", "world", "scene", "object", "found", "description", "words", "true", "unique",
                 "repeated", "listener", "BLEU-2", "agree"])
    bad = [r for r in rows if not r["true"]]
    if bad:
        print("\nfalse relations:")
        for r in bad:
            print(f"  {r['world']} {r['scene']} {r['object']}: {'; '.join(r['problems'])}")
    missed = [r for r in rows if r["listener"] and not r["listener"]["success"]]
    if missed:
        print("\nlistener failures:")
        for r in missed:
            li = r["listener"]
            print(f"  {r['world']} {r['scene']} {r['object']} (on {r['support_id']} at {r['support_at']}): "
                  f"{li['failure']} — {li.get('message', '')}; went to {li.get('target')}")
    print()
    if s["search_found"] is not None:
        print(f"search: found {s['search_found']}/{s['descriptions']} (at the right place "
              f"{s['search_right_place']}/{s['descriptions']}); median {s['median_search_wall_seconds']:.1f} s "
              f"computer time, {s['median_search_sim_seconds']:.0f} s robot time, "
              f"{s['median_search_path_m']:.1f} m driven")
    print(f"every stated relation true: {s['all_relations_true']}/{s['descriptions']} "
          f"(checked by {s['truth_checked_by']}); no repeated phrase: "
          f"{s['no_repeated_phrase']}/{s['descriptions']}; both: {s['true_and_no_repeat']}/"
          f"{s['descriptions']} (target {s['descriptions']}/{s['descriptions']}; dissertation 43/48)")
    recovered = ("not parsed" if s["recovered_by_parse"] is None
                 else f"{s['recovered_by_parse']}/{s['descriptions']}")
    print(f"support singled out: {s['unique']}/{s['descriptions']} (the generator found no "
          f"true wording that does for {s['flagged_ambiguous']}); meant relations recovered by "
          f"the parse: {recovered}")
    print(f"median length {s['median_words']} words (target <= 16), longest {s['max_words']}")
    if s["median_bleu2"] is not None:
        print(f"agreement with the corpus's human descriptions: median BLEU-2 {s['median_bleu2']:.3f}, "
              f"mean share of stated relations people also used {s['mean_human_relation_agreement']:.2f}")
    print(f"median composition {s['median_compose_ms']:.1f} ms")
    print(f"listener: {s['listener']} (target >= {s['targets']['listener_min']})")
    print(f"evaluation took {s['wall_seconds']:.0f} s")
    if s["parser_note"]:
        print(s["parser_note"])
    return 0

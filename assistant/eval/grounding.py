"""``assistant eval grounding``: dissertation Tables 4-3 and 4-4 for the three grounders.

(a) On our corpus with the dissertation's protocol (4.4.3): two thirds of the commands train,
one third test, 10 bootstrap rounds (seeded), accuracies averaged.
(b) Trained on all of our corpus, tested on a separate label file — by default the CSISL
template chunk labels in ``../shared/realdata/csisl/`` when that folder exists (``--test``).

Accuracy per grounding type is the fraction of chunks whose field is right; *whole command*
is the fraction of commands with every chunk right in every field.
"""

from __future__ import annotations

import random
from pathlib import Path

from assistant.eval.progress import Progress, no_progress

FIELD_ROWS = (("target room", "Target room"), ("target object", "Target Object"),
              ("reference", "Reference"), ("direction", "Direction"), ("target", "Target"),
              ("whole command", "The whole spatial command"))
#: the dissertation's figures (Tables 4-3, 4-4), printed beside ours for comparison
DISSERTATION = {"learned": {"target room": 0.985, "target object": 0.971, "reference": 0.971,
                            "direction": 0.960, "target": 1.0, "whole command": 0.897},
                "scored": {"whole command": 0.879}}
GROUNDER_NAMES = ("scored", "learned", "combined")
#: the home of the CSISL fetch study (dissertation 4.3 IV): hallway, living room on the right
CSISL_WORLD = "apartment"


def default_test_path() -> Path | None:
    """The CSISL template chunk labels, when they are there."""
    from assistant.eval.csisl import csisl_folder

    path = csisl_folder() / "csisl_templates149_chunk_groundings.csv"
    return path if path.exists() else None


def bootstrap(name: str, commands, rounds: int, seed: int) -> dict[str, float]:
    """Mean accuracies over ``rounds`` random 2/3–1/3 splits of the commands."""
    from assistant.grounding.training import make_grounder

    totals: dict[str, float] = {}
    for r in range(rounds):
        shuffled = list(commands)
        random.Random(seed + r).shuffle(shuffled)
        cut = (2 * len(shuffled)) // 3
        train, test = shuffled[:cut], shuffled[cut:]
        grounder = make_grounder(name).fit([x for c in train for x in c.records],
                                           [g for c in train for g in c.groundings])
        for key, value in grounder.accuracy(test).items():
            totals[key] = totals.get(key, 0.0) + value / rounds
    return totals


def plan_agreement(parser, descriptions, commands, limit: int = 10) -> dict:
    """Parse every description's text (in its own world, as ``parse --world`` would) and compare
    (room, nodes, object) with the plan its annotation gives (its gold tree with its gold chunk
    groundings). Per family as well."""
    from assistant.grounding.plan import assemble_plan

    from assistant.world import load_world, world_names

    by_number = {c.number: c for c in commands}
    known_worlds = set(world_names())
    worlds: dict = {}
    total = agree = skipped = 0
    families: dict[str, list[int]] = {}
    disagreements = []
    for description in descriptions:
        command = by_number.get(str(description.number))
        own = [tuple(t.text for t in chunk.own_tokens) for chunk, _, _ in description.tree.chunks()]
        if command is None or [r.words for r in command.records] != own:
            skipped += 1  # label rows that are not this description's chunks
            continue
        gold = assemble_plan(description.tree, list(command.groundings))
        name = description.attributes.get("world")
        if name in known_worlds and name not in worlds:
            worlds[name] = load_world(name)
        parser.world = worlds.get(name)  # the home the description was given in
        got = parser.parse(description.text).plan
        same = (got.room, got.node_strings, got.object) == (gold.room, gold.node_strings, gold.object)
        family = description.attributes.get("family", "-")
        counts = families.setdefault(family, [0, 0])
        counts[0] += same
        counts[1] += 1
        total += 1
        agree += same
        if not same and len(disagreements) < limit:
            disagreements.append({"number": description.number, "text": description.text,
                                  "gold": [gold.room, gold.node_strings, gold.object],
                                  "parsed": [got.room, got.node_strings, got.object]})
    return {"descriptions": total, "skipped": skipped, "agreement": agree / total if total else 0.0,
            "families": {f: c[0] / c[1] for f, c in sorted(families.items())},
            "disagreements": disagreements}


def evaluate_grounding(corpus=None, test=None, test_world: str | None = None, *, rounds: int = 10,
                       seed: int = 0, grounders=None, plans: bool = True, errors: int = 0,
                       descriptions=None, descriptions_world: str = CSISL_WORLD,
                       progress: Progress = no_progress) -> dict:
    """Experiments (a) bootstrap on the corpus, (b) the held-out ``test`` label file (default: the
    CSISL templates when present, given in ``test_world``) and (c) every corpus description parsed
    from its text, for each of ``grounders`` (default all three). ``errors``: list up to that many
    wrongly grounded test chunks per grounder. ``descriptions``: annotated description files for
    (d), each parsed in ``descriptions_world`` (:func:`description_coverage`). Returns the JSON
    report."""
    from assistant.errors import AssistantError
    from assistant.grounding.training import load_labels, split_corpus_paths

    names = list(grounders or GROUNDER_NAMES)
    csvs, xmls = split_corpus_paths(corpus)
    labels = load_labels(csvs, xmls)
    if len(labels.commands) < 3:
        raise AssistantError(f"need at least 3 labelled commands to split, found {len(labels.commands)} "
                             f"in {', '.join(map(str, csvs))}")
    test_path, test_set, test_world = _test_set(test, test_world)

    result: dict = {"corpus": {"files": [str(p) for p in csvs], "commands": len(labels.commands),
                               "chunks": len(labels.records), "problems": labels.problems[:20]},
                    "protocol": {"rounds": rounds, "train_fraction": "2/3", "seed": seed},
                    "corpus_split": {}, "test": None, "dissertation": DISSERTATION}
    for number, name in enumerate(names):
        progress(f"(a) bootstrap rounds of the {name} grounder", number, len(names))
        result["corpus_split"][name] = bootstrap(name, labels.commands, rounds, seed)
    if plans:
        progress("(c) parsing every corpus description from its text")
        result["plans"] = plans_agreement(names, labels, corpus, xmls, limit=errors)
    if descriptions:
        progress("(d) parsing the annotated descriptions")
        result["descriptions"] = description_coverage(names, corpus, descriptions, descriptions_world, errors)
    if test_set is not None:
        progress(f"(b) testing on {test_path}")
        result["test"] = held_out_accuracy(names, labels, test_set, errors)
        result["test"] = {"file": str(test_path), "world": test_world, **result["test"]}
    return result


def _test_set(test, test_world):
    """(path, label set with its world set, world) of experiment (b); (None, None, world)
    without a test file."""
    from assistant.grounding.labels import read_chunk_groundings, with_world

    test_path = Path(test) if test else default_test_path()
    test_set = read_chunk_groundings(test_path) if test_path else None
    if test_world is None and test_path is not None and test_path == default_test_path():
        test_world = CSISL_WORLD
    if test_set is not None and test_world:
        test_set.commands = [with_world(c, test_world) for c in test_set.commands]
    return test_path, test_set, test_world


def plans_agreement(names, labels, corpus, xmls, limit: int = 0) -> dict:
    """Experiment (c) for each grounder (trained on all of ``labels``): :func:`plan_agreement`
    over the descriptions of the ``xmls`` corpus files."""
    from assistant.grounding.parser import CommandParser
    from assistant.grounding.training import make_grounder
    from assistant.language.corpus import read_corpora

    descriptions = read_corpora(xmls).descriptions if xmls else []
    out = {}
    language = None
    for name in names:
        grounder = make_grounder(name).fit(labels.records, labels.groundings)
        if language is None:
            language = CommandParser.load(name, corpus).language
        out[name] = plan_agreement(CommandParser(language, grounder), descriptions,
                                   labels.commands, limit=limit)
    return out


def held_out_accuracy(names, labels, test_set, errors: int = 0) -> dict:
    """Experiment (b): each grounder trained on all of ``labels``, its accuracies on
    ``test_set`` and, with ``errors``, up to that many wrong chunks per grounder."""
    from assistant.grounding.base import command_errors
    from assistant.grounding.training import make_grounder

    out: dict = {"commands": len(test_set.commands), "chunks": len(test_set.records),
                 "problems": test_set.problems[:20], "accuracy": {}}
    wrong: dict[str, list] = {}
    for name in names:
        grounder = make_grounder(name).fit(labels.records, labels.groundings)
        out["accuracy"][name] = grounder.accuracy(test_set.commands)
        if errors:
            wrong[name] = [
                {"command": number, "label": rec.label, "words": " ".join(rec.words),
                 "gold": truth.to_dict(), "guess": guess.to_dict()}
                for number, rec, truth, guess in command_errors(grounder, test_set.commands)[:errors]]
    if wrong:
        out["errors"] = wrong
    return out


def description_coverage(names, corpus, paths, world_name: str, limit: int = 0) -> dict:
    """Experiment (d): for each grounder, the share of the annotated descriptions in ``paths``
    whose plan names the object they name and leaves no spatial word unused
    (:func:`~assistant.grounding.coverage.plan_coverage`), parsed in the home ``world_name``."""
    from assistant.grounding.coverage import plan_coverage
    from assistant.grounding.parser import CommandParser
    from assistant.language.corpus import read_corpora
    from assistant.world import load_world

    read = read_corpora(paths)
    world = load_world(world_name)
    out = {}
    for name in names:
        cov = plan_coverage(CommandParser.load(name, corpus, world), read.descriptions, limit=limit)
        out[name] = {"files": [str(f) for f in read.files], "world": world_name, **cov}
    return out

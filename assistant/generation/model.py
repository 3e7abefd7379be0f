"""What the generator learns from the annotated corpus (dissertation 6.2 II.D, II.E).

From the descriptions (``corpus/*.xml``, chunk trees) and their chunk groundings
(``corpus/chunk_groundings.csv``) a :class:`GenerationModel` counts three things:

* **co-occurrence weights** ``v`` — how often two kinds of content (``room``, ``support``,
  ``furniture-front``, ``wall-left``…) are said in the same description: ``P(a | b)``;
* **chunk texts** ``P(text, type | key)`` — each grounded chunk's own words with the object,
  furniture and room words replaced by slots (``in front of the {ref}``, FURRP);
* **chunk relations** ``P(v | η_A, η_B)`` for the six relations NL, NR, PL, PR, CL, CR between
  chunk types, read off the chunk trees.

Everything is counted, so training is deterministic; :func:`load_generation_model` caches the
fitted model under :func:`~assistant.fileio.cache_dir` keyed by a hash of the corpus files.
"""

from __future__ import annotations

import hashlib
from collections import Counter, defaultdict
from pathlib import Path

from assistant.errors import AssistantError, NotFittedError

__all__ = ["RELATIONS", "INVERSE", "GenerationModel", "GenerationModelNotFittedError",
           "chunk_key", "infer_kind", "load_generation_model", "template_from_chunk"]

#: the six chunk relations of A to B (dissertation Fig. 6)
RELATIONS = ("NL", "NR", "PL", "PR", "CL", "CR")
#: the relation of B to A, given that of A to B
INVERSE = {"NL": "NR", "NR": "NL", "PL": "CL", "CL": "PL", "PR": "CR", "CR": "PR"}
#: references that are not furniture keep their own word in the key
STRUCTURE = ("wall", "door", "room", "robot", "move")
#: description kinds whose chunk trees teach the chunk relations of each style
STYLE_KINDS = {"static": ("static",), "dynamic": ("dynamic", "mixed")}
#: bumped when the learned content changes, so old caches are not reused
MODEL_VERSION = 5

SLOT_OBJECT, SLOT_SUPPORT, SLOT_REF, SLOT_ROOM = "{object}", "{support}", "{ref}", "{room}"


#: the one :class:`~assistant.errors.NotFittedError` (this name kept for callers)
GenerationModelNotFittedError = NotFittedError


def chunk_key(label: str, grounding, pos: tuple[str, ...] = ()) -> str | None:
    """The content key a grounded chunk realizes, or None (fillers, hedges, unnamed parts).

    ``object`` (names the target object), ``support`` (a target furniture, no reference),
    ``<reference class>-<direction>`` (``furniture-front``, ``wall-left``, ``move-right``),
    ``room`` (names the target room), ``enter`` (an ORMTP that moves into a room: "go into the
    room")."""
    if grounding.object:
        return "object"
    if grounding.reference and grounding.direction:
        ref = grounding.reference if grounding.reference in STRUCTURE else "furniture"
        return f"{ref}-{grounding.direction}"
    if grounding.target:
        return "support"
    if label == "ORMTP" and "RM" in pos and "VB" in pos:
        return "enter"
    if grounding.room or (label == "ORMTP" and "RM" in pos):
        return "room"
    return None


def template_from_chunk(key: str, words: tuple[str, ...], pos: tuple[str, ...],
                        object_name: str | None = None) -> tuple[tuple[str, str], ...] | None:
    """The chunk's own words as a template of ``(word, pos)`` with slots, or None when the
    chunk's words cannot be generalised (no slot for what the key needs)."""
    w = [x.lower() for x in words]
    p = list(pos)
    out: list[tuple[str, str]] = []
    i = 0
    obj = object_name.lower().split() if object_name else []
    filled = False
    while i < len(w):
        if key == "object" and obj and w[i:i + len(obj)] == obj:
            out.append((SLOT_OBJECT, "NN"))
            i += len(obj)
            filled = True
            continue
        if key in ("room", "enter") and p[i] in ("NN", "RM"):
            j = i
            while j < len(w) and p[j] == "NN":
                j += 1
            if j < len(w) and p[j] == "RM":
                out.append((SLOT_ROOM, "RM"))
                i = j + 1
                filled = True
                continue
        if p[i] == "FUR" and key != "object":
            out.append((SLOT_SUPPORT if key == "support" else SLOT_REF, "FUR"))
            i += 1
            filled = True
            continue
        out.append((w[i], p[i]))
        i += 1
    needs_slot = key in ("object", "support", "room", "enter") or key.startswith("furniture-")
    if needs_slot and not filled:
        return None
    return tuple(out)


def infer_kind(keys) -> str:
    """A description's kind when the corpus does not say it (the ``kind`` attribute of
    ``<S>``): ``dynamic`` (only route steps), ``mixed`` (route steps and furniture) or
    ``static`` (no route step)."""
    route = any(k == "enter" or (k or "").startswith("move-") for k in keys)
    place = any(k in ("support",) or (k or "").startswith("furniture-") for k in keys)
    if route:
        return "mixed" if place else "dynamic"
    return "static"


class GenerationModel:
    """Counts learned from an annotated corpus; see the module docstring.

    Parameters: ``kinds`` — description kinds (the ``kind`` attribute of ``<S>``) whose chunks
    train the static content and texts; dynamic route texts come from every kind.
    """

    def __init__(self, kinds: tuple[str, ...] = ("static", "mixed")):
        self.kinds = kinds

    # ------------------------------------------------------------------------------ fit
    def fit(self, descriptions, commands) -> "GenerationModel":
        """``descriptions``: :class:`~assistant.language.Description` list; ``commands``: the
        :class:`~assistant.grounding.LabelledCommand` list numbered like the descriptions."""
        by_number = {str(c.number): c for c in commands}
        templates: dict[str, Counter] = defaultdict(Counter)
        key_counts: Counter = Counter()
        pair_counts: Counter = Counter()
        relation_counts = {style: defaultdict(Counter) for style in STYLE_KINDS}
        presence = {style: Counter() for style in STYLE_KINDS}
        n_desc = 0
        used = 0
        for d in descriptions:
            cmd = by_number.get(str(d.number))
            if cmd is None:
                continue
            chunks = [c for c, _, _ in d.tree.chunks()]
            if len(chunks) != len(cmd.records):
                continue
            used += 1
            keys = [chunk_key(r.label, g, r.pos) for r, g in zip(cmd.records, cmd.groundings)]
            kind = d.attributes.get("kind") or infer_kind(keys)
            obj = d.attributes.get("object") or next(
                (g.object for g in cmd.groundings if g.object), None)
            keys_here: Counter = Counter()
            for key, record in zip(keys, cmd.records):
                if key is None:
                    continue
                if kind in self.kinds or key in ("enter",) or key.startswith("move-"):
                    t = template_from_chunk(key, record.words, record.pos, obj)
                    if t is not None:
                        templates[key][(record.label, t)] += 1
                if kind in self.kinds and key not in ("object", "enter"):
                    keys_here[key] += 1
            if kind in self.kinds:
                n_desc += 1
                for k, n in keys_here.items():
                    key_counts[k] += 1
                    if n > 1:
                        pair_counts[(k, k)] += 1
                ks = sorted(keys_here)
                for i, a in enumerate(ks):
                    for b in ks[i + 1:]:
                        pair_counts[(a, b)] += 1
                        pair_counts[(b, a)] += 1
            for style, style_kinds in STYLE_KINDS.items():
                if kind in style_kinds:
                    self._count_relations(d.tree, relation_counts[style], presence[style])
        if not used:
            raise AssistantError("no description of the corpus has chunk groundings that match its "
                                 "chunk tree; check corpus/*.xml against corpus/chunk_groundings.csv")
        self.templates_ = {k: dict(v) for k, v in templates.items()}
        self.key_counts_ = dict(key_counts)
        self.pair_counts_ = dict(pair_counts)
        self.n_descriptions_ = n_desc
        self.relation_counts_ = {style: {k: dict(v) for k, v in counts.items()}
                                 for style, counts in relation_counts.items()}
        self.presence_ = {style: dict(c) for style, c in presence.items()}
        return self

    @staticmethod
    def _count_relations(tree, counts, presence) -> None:
        """Six relations between chunks that are siblings or parent and child."""
        chunks = tree.chunks()
        labels = [c.label for c, _, _ in chunks]
        for i, a in enumerate(labels):
            for j, b in enumerate(labels):
                if i != j:
                    presence[(a, b)] += 1

        def visit(items, parent):
            kids = [x for x in items if hasattr(x, "label")]
            for i, a in enumerate(kids):
                for b in kids[i + 1:]:
                    counts[(a.label, b.label)]["NL"] += 1
                    counts[(b.label, a.label)]["NR"] += 1
            if parent is not None:
                first_own = next((k for k, x in enumerate(items) if not hasattr(x, "label")), None)
                for k, x in enumerate(items):
                    if hasattr(x, "label"):
                        side = "L" if first_own is not None and k < first_own else "R"
                        counts[(x.label, parent.label)]["C" + side] += 1
                        counts[(parent.label, x.label)]["P" + side] += 1
            for x in kids:
                visit(x.items, x)

        visit(tree.items, None)

    # ------------------------------------------------------------------------------ use
    def _check(self) -> None:
        if not hasattr(self, "templates_"):
            raise GenerationModelNotFittedError("the generation model is not fitted; call fit() "
                                                "or load_generation_model()")

    def cooccurrence(self, a: str, b: str) -> float:
        """``v_ab``: the mean of ``P(a | b)`` and ``P(b | a)`` over the corpus descriptions
        (symmetric, so the objective does not depend on the order of the candidates)."""
        self._check()
        both = self.pair_counts_.get((a, b), 0)
        na, nb = self.key_counts_.get(a, 0), self.key_counts_.get(b, 0)
        p_ab = both / nb if nb else 0.0
        p_ba = both / na if na else 0.0
        return 0.5 * (p_ab + p_ba)

    def texts(self, key: str) -> list[tuple[float, str, tuple[tuple[str, str], ...]]]:
        """``[(P(text, type | key), type, template)]``, most probable first (ties by text)."""
        self._check()
        table = self.templates_.get(key, {})
        total = sum(table.values())
        rows = [(n / total, label, t) for (label, t), n in table.items()]
        rows.sort(key=lambda r: (-r[0], r[1], " ".join(w for w, _ in r[2])))
        return rows

    def relation(self, a: str, b: str, style: str = "static") -> tuple[str | None, float]:
        """The most probable relation of chunk type ``a`` to ``b`` and ``P(v | a, b)`` (the count
        of ``v`` over the number of chunk pairs of these types in the same description), learned
        from the descriptions of ``style`` (:data:`STYLE_KINDS`)."""
        self._check()
        counts = self.relation_counts_[style].get((a, b), {})
        seen = self.presence_[style].get((a, b), 0)
        if not counts or not seen:
            return None, 0.0
        v = max(RELATIONS, key=lambda r: (counts.get(r, 0), -RELATIONS.index(r)))
        return v, counts.get(v, 0) / seen

    def relation_probability(self, a: str, b: str, v: str, style: str = "static") -> float:
        self._check()
        seen = self.presence_[style].get((a, b), 0)
        return self.relation_counts_[style].get((a, b), {}).get(v, 0) / seen if seen else 0.0


# ---------------------------------------------------------------------------------- loading
def corpus_files(corpus_paths=None) -> tuple[list[Path], list[Path]]:
    """(XML files, chunk-grounding CSV files) of the corpus (``--corpus`` or the repository's)."""
    from assistant.language.corpus import default_corpus_paths

    paths = [Path(p) for p in (corpus_paths if corpus_paths is not None else default_corpus_paths())]
    files: list[Path] = []
    for p in paths:
        if p.is_dir():
            files.extend(sorted(p.glob("*.xml")) + sorted(p.glob("*.csv")))
        else:
            files.append(p)
    xmls = [p for p in files if p.suffix.lower() == ".xml"]
    csvs = [p for p in files if p.suffix.lower() == ".csv"]
    if not csvs:
        for x in xmls:
            csvs.extend(sorted(x.parent.glob("*chunk_groundings*.csv")))
        csvs = sorted(set(csvs))
    missing = [str(p) for p in paths if not p.exists()]
    if missing:
        raise AssistantError(f"corpus file(s) not found: {', '.join(missing)}")
    if not xmls or not csvs:
        raise AssistantError("the generation model needs annotated descriptions (*.xml) and their "
                             "chunk groundings (*.csv); give both with --corpus")
    return xmls, csvs


def load_generation_model(corpus_paths=None, use_cache: bool = True) -> GenerationModel:
    """Fit (or load from the cache) the generation model on the corpus files.

    Only one XML file and one CSV file are paired by description number; with several, each
    XML file is paired with the CSV whose name shares its stem, else the first CSV."""
    from assistant.fileio import cache_dir, cached

    xmls, csvs = corpus_files(corpus_paths)
    digest = hashlib.sha256(f"generation-v{MODEL_VERSION}".encode())
    for p in xmls + csvs:
        digest.update(p.name.encode())
        digest.update(p.read_bytes())
    path = cache_dir() / f"generation-{digest.hexdigest()[:16]}.pkl"
    return cached(path, lambda: _fit(xmls, csvs), GenerationModel, use_cache=use_cache)


def _fit(xmls: list[Path], csvs: list[Path]) -> GenerationModel:
    """The generation model fitted on the paired corpus files (see :func:`train_generation`)."""
    from assistant.grounding.labels import read_chunk_groundings
    from assistant.language.corpus import read_corpus

    descriptions, commands = [], []
    for i, x in enumerate(xmls):
        csv = next((c for c in csvs if c.stem.split("_chunk")[0] == x.stem.split("_annotated")[0]),
                   csvs[min(i, len(csvs) - 1)])
        result = read_corpus(x)
        labels = read_chunk_groundings(csv)
        prefix = f"{i}:"
        for d in result.descriptions:
            d = type(d)(d.number, d.tree, d.attributes, d.source)
            d.number = f"{prefix}{d.number}"
            descriptions.append(d)
        for c in labels.commands:
            commands.append(type(c)(f"{prefix}{c.number}", c.records, c.groundings, c.source))
    from assistant.progress import working

    with working("training the description model (first use; cached after)"):
        return GenerationModel().fit(descriptions, commands)

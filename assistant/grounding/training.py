"""Training grounders from label files, with the trained-model cache.

The product trains from the repository's corpus (``corpus/*.csv`` chunk-grounding labels,
with the chunk trees of ``corpus/*.xml`` for parent/child chunk types); ``--corpus PATH`` points
it at other files in the same formats (folders stand for their ``*.csv`` and ``*.xml``). A
trained grounder is pickled under ``cache_dir()``, keyed by a hash of the label and tree files'
content, the grounder's parameters and :data:`GROUNDING_VERSION`.
"""

from __future__ import annotations

import hashlib
import logging
import os
from collections.abc import Iterable
from pathlib import Path

from assistant.errors import AssistantError, UnknownNameError
from assistant.fileio import cache_dir, cached
from assistant.grounding.combined import CombinedGrounder
from assistant.grounding.labels import ChunkGroundingFile, attach_structures, read_chunk_groundings
from assistant.grounding.learned import LearnedGrounder
from assistant.grounding.scored import ScoredGrounder

log = logging.getLogger(__name__)

#: bump when a grounder's features or scoring change: cached grounders are then retrained
GROUNDING_VERSION = "grounding-7"
#: grounder name → class; ``DEFAULT_GROUNDER`` was picked by measurement (docs/grounding.md)
GROUNDERS = {"scored": ScoredGrounder, "learned": LearnedGrounder, "combined": CombinedGrounder}
DEFAULT_GROUNDER = "combined"
_ENV_CORPUS = "ASSISTANT_CORPUS"


def repo_corpus_dir() -> Path:
    return Path(__file__).resolve().parents[2] / "corpus"


def split_corpus_paths(paths: Iterable[str | os.PathLike] | None) -> tuple[list[Path], list[Path]]:
    """(label CSV files, corpus XML files) among ``paths``; folders stand for their files.

    ``None`` means ``$ASSISTANT_CORPUS`` if set, else the repository's ``corpus/``.
    """
    if paths is None:
        env = os.environ.get(_ENV_CORPUS)
        paths = [p for p in env.split(os.pathsep) if p.strip()] if env else [repo_corpus_dir()]
    csvs: list[Path] = []
    xmls: list[Path] = []
    for p in paths:
        path = Path(p)
        if not path.exists():
            raise AssistantError(f"corpus path {path} does not exist; give a folder or .csv/.xml files")
        if path.is_dir():
            csvs.extend(sorted(path.glob("*.csv")))
            xmls.extend(sorted(path.glob("*.xml")))
        elif path.suffix.lower() == ".csv":
            csvs.append(path)
        elif path.suffix.lower() == ".xml":
            xmls.append(path)
        else:
            raise AssistantError(f"corpus file {path} is neither .csv (chunk groundings) nor .xml (descriptions)")
    return csvs, xmls


def load_labels(csv_paths: list[Path], xml_paths: list[Path] | None = None) -> ChunkGroundingFile:
    """Read label files and, when the descriptions' XML is given, attach each row's parent and
    child chunk types (rows and tree chunks matched in pre-order, by command number)."""
    if not csv_paths:
        raise AssistantError("no chunk-grounding labels (*.csv) to train the grounder on; the "
                             "repository's corpus/ has none — give them with --corpus PATH")
    labels = read_chunk_groundings(csv_paths)
    if xml_paths:
        from assistant.language.corpus import read_corpora

        corpus = read_corpora(xml_paths)
        trees, worlds = {}, {}
        for description in corpus.descriptions:
            stem = Path(description.source).stem if description.source else ""
            for key in (str(description.number), f"{stem}:{description.number}"):
                if key not in trees:
                    trees[key] = description.tree
                    worlds[key] = description.attributes.get("world")
        labels.commands, _ = attach_structures(labels.commands, trees, worlds)
    return labels


def files_key(paths: Iterable[Path], extra: str) -> str:
    digest = hashlib.sha256((GROUNDING_VERSION + extra).encode())
    for path in paths:
        try:
            digest.update(hashlib.sha256(Path(path).read_bytes()).digest())
        except OSError as error:
            raise AssistantError(f"cannot read corpus file {path}: {error.strerror or error}") from error
    return digest.hexdigest()[:20]


def make_grounder(name: str, **params):
    try:
        cls = GROUNDERS[name]
    except KeyError:
        raise UnknownNameError("grounder", name, GROUNDERS) from None
    return cls(**params)


def train_grounder(name: str = DEFAULT_GROUNDER, corpus_paths=None, *, use_cache: bool = True, **params):
    """A fitted grounder trained on the corpus labels (cached)."""
    csvs, xmls = split_corpus_paths(corpus_paths)
    grounder = make_grounder(name, **params)
    key = files_key([*csvs, *xmls], f"{name}{sorted(grounder.get_params().items())}")
    cache_file = cache_dir() / f"grounder-{name}-{key}.pickle"

    def fit():
        from assistant.progress import working

        with working(f"training the {name} grounder (first use; cached after)"):
            labels = load_labels(csvs, xmls)
            if not labels.commands:
                raise AssistantError(f"no readable rows in {', '.join(map(str, csvs))}: "
                                     + ("; ".join(labels.problems[:3]) or "the files are empty"))
            for problem in labels.problems[:5]:
                log.warning("%s", problem)
            grounder.fit(labels.records, labels.groundings)
        grounder.training_files_ = [str(p) for p in csvs]
        return grounder

    return cached(cache_file, fit, type(grounder), use_cache=use_cache)

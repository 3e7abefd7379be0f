"""All RDT policy models, trained from the demonstration files and cached.

``PolicyLibrary(directory)`` groups the demonstrations under ``directory`` by RDT, trains one
:class:`PolicyModel` per RDT and caches the trained models under
``cache_dir()/policy/<hash>.pkl``, the hash covering every demonstration file's bytes, the
model parameters and the model code. An RDT with no demonstrations falls back to a trained
model with the same direction and the same kind of reference (robot, furniture, room, wall),
then one with the same direction, then one with the same kind of reference; ties go to the
RDT earlier in Table 5-1. ``model(rdt)`` says which model it used. With ``taught=True`` the
demonstrations the user taught (:func:`assistant.policy.taught.taught_directory`, never the
held-back ones) are trained on too; the evaluations leave them out.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from pathlib import Path

from assistant.errors import UnknownNameError
from assistant.fileio import cache_dir, cached
from assistant.policy.demonstration import load_demonstrations
from assistant.policy.model import PolicyModel
from assistant.policy.rdt import RDT, TABLE_RDTS, parse_rdt

DEFAULT_DIRECTORY = Path(__file__).resolve().parents[2] / "corpus" / "demonstrations"
_CODE_FILES = ("model.py", "demonstration.py", "rdt.py")


@dataclass(frozen=True)
class ModelChoice:
    """The model used for a requested RDT: ``rdt`` asked for, ``used`` the model's RDT."""

    model: PolicyModel
    rdt: str
    used: str

    @property
    def fallback(self) -> bool:
        return self.rdt != self.used


class PolicyLibrary:
    """Policy models of every demonstrated RDT (``directory``: demonstration files)."""

    def __init__(self, directory: str | Path | None = None, use_cache: bool = True, taught: bool = False,
                 **model_params):
        self.directory = Path(directory) if directory is not None else DEFAULT_DIRECTORY
        self.taught_directory: Path | None = None
        if taught:
            from assistant.policy.taught import taught_directory

            self.taught_directory = taught_directory()
        self.use_cache = use_cache
        self.model_params = model_params
        self._models: dict[str, PolicyModel] | None = None
        self.cache_path: Path | None = None
        self.loaded_from_cache = False

    def _directories(self) -> list[Path]:
        extra = self.taught_directory
        return [self.directory] + ([extra] if extra is not None and extra.is_dir() else [])

    def _key(self) -> str:
        h = hashlib.sha256()
        for n, directory in enumerate(self._directories()):
            for path in sorted(directory.rglob("*.json")):
                h.update(f"{n}:{path.relative_to(directory)}".encode())
                h.update(path.read_bytes())
        h.update(repr(sorted(self.model_params.items())).encode())
        here = Path(__file__).resolve().parent
        for name in _CODE_FILES:
            h.update((here / name).read_bytes())
        return h.hexdigest()[:24]

    @property
    def models(self) -> dict[str, PolicyModel]:
        if self._models is None:
            self._models = self._load_or_train()
        return self._models

    def _load_or_train(self) -> dict[str, PolicyModel]:
        if not self.directory.is_dir():
            raise UnknownNameError("demonstration directory", str(self.directory), [str(DEFAULT_DIRECTORY)])
        trained = []

        def train() -> dict[str, PolicyModel]:
            from assistant.progress import counted

            demos = [d for directory in self._directories() for d in load_demonstrations(directory)]
            by_rdt: dict[str, list] = {}
            for demo in demos:
                by_rdt.setdefault(demo.rdt, []).append(demo)
            trained.append(True)
            return {rdt: PolicyModel(rdt, **self.model_params).fit(by_rdt[rdt])
                    for rdt in counted(sorted(by_rdt), "training the policy models (first use; cached after)")}

        if not self.use_cache:
            return train()
        self.cache_path = cache_dir() / "policy" / f"{self._key()}.pkl"
        models = cached(self.cache_path, train, dict)
        self.loaded_from_cache = not trained
        return models

    def rdts(self) -> list[str]:
        return sorted(self.models)

    def model(self, rdt: str | RDT) -> ModelChoice:
        """The model of ``rdt``, or the nearest one (see the module docstring)."""
        want = parse_rdt(rdt)
        models = self.models
        if want.name in models:
            return ModelChoice(models[want.name], want.name, want.name)
        order = {name: i for i, name in enumerate(TABLE_RDTS)}
        known = sorted(models, key=lambda n: (order.get(n, len(order)), n))
        tests = (lambda r: r.direction == want.direction and r.reference_kind == want.reference_kind
                 and r.has_target == want.has_target,
                 lambda r: r.direction == want.direction and r.reference_kind == want.reference_kind,
                 lambda r: r.direction == want.direction,
                 lambda r: r.reference_kind == want.reference_kind and r.has_target == want.has_target)
        for test in tests:
            for name in known:
                if test(RDT.parse(name)):
                    return ModelChoice(models[name], want.name, name)
        raise UnknownNameError("RDT (no policy model and no model to fall back to)", want.name, known)

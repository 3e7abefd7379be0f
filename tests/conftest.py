"""Shared fixtures: loaded worlds (loaded once per session) and a private model cache."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from assistant.runtime import limit_openmp_threads

limit_openmp_threads()  # as the command line does at start-up

SHARED = Path(__file__).resolve().parents[1].parent / "shared"


@pytest.fixture(scope="session", autouse=True)
def _private_cache(tmp_path_factory):
    """Tests train into their own cache so they never read a developer's stale models. The
    workers of a parallel run (``pytest -n``, as ``make test`` runs) share one: a model is
    trained by the first worker that needs it while the others wait (``fileio.cached``)."""
    if "ASSISTANT_CACHE" not in os.environ:
        base = tmp_path_factory.getbasetemp()
        if os.environ.get("PYTEST_XDIST_WORKER"):
            base = base.parent  # the run's folder, above each worker's own
        cache = base / "model-cache"
        cache.mkdir(mode=0o700, exist_ok=True)
        os.environ["ASSISTANT_CACHE"] = str(cache)
    yield


@pytest.fixture(scope="session")
def apartment():
    from assistant.world import load_world

    return load_world("apartment")


@pytest.fixture(scope="session")
def all_worlds():
    from assistant.world import load_world, world_names

    return {name: load_world(name) for name in world_names()}


@pytest.fixture(scope="session")
def shared_dir() -> Path:
    if not SHARED.exists():
        pytest.skip("../shared is not beside this checkout")
    return SHARED

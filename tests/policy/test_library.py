"""Training every RDT model from the corpus, caching, falling back."""

from __future__ import annotations

import pytest

from assistant.errors import UnknownNameError
from assistant.policy.library import PolicyLibrary
from assistant.policy.rdt import TABLE_RDTS, RDT


def test_library_trains_caches_and_falls_back(tmp_path, monkeypatch):
    monkeypatch.setenv("ASSISTANT_CACHE", str(tmp_path))
    library = PolicyLibrary()
    assert library.rdts() == sorted(TABLE_RDTS)
    assert not library.loaded_from_cache and library.cache_path.is_file()
    again = PolicyLibrary()
    assert again.rdts() == library.rdts() and again.loaded_from_cache
    assert again.model("couch-front-table").used == "couch-front-table"
    assert again.model("desk-left-table").used == "bed-left-table"     # same direction, furniture
    assert again.model("sofa-front-table").used == "couch-front-table"
    assert again.model("robot-front-table").used == "move-front-non"   # same direction
    assert again.model("desk-left-table").fallback


def test_unknown_directory(tmp_path):
    with pytest.raises(UnknownNameError):
        PolicyLibrary(tmp_path / "none").models


def test_rdt_names():
    rdt = RDT.parse("couch-front-table")
    assert (rdt.reference_kind, rdt.has_target) == ("furniture", True)
    assert RDT.parse("move-left-non").reference_kind == "robot"
    with pytest.raises(Exception, match="reference-direction-target"):
        RDT.parse("couch")

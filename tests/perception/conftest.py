"""Fixtures for the perception tests: a tiny rendered database and models trained on it."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="session")
def tiny_database():
    """Eight random views of four study models (rendered in a few seconds)."""
    from assistant.perception.database import ViewPlan, render_database, study_items

    items = [i for i in study_items() if i.name in ("wood chair", "couch", "coffee table", "bed")]
    return render_database(items, ViewPlan(grid=False, random_per_item=8, jitter=0.1, seed=7),
                           keep_points=True)


@pytest.fixture(scope="session")
def tiny_models(tiny_database):
    from assistant.perception.models import fit_models

    return fit_models(tiny_database, method="gsvm")

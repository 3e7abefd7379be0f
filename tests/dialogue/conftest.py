"""The dialogue tests' shared parts: the apartment's services (real parser and describer, oracle
perception), built once per test module."""

import pytest


@pytest.fixture(scope="module")
def services():
    from assistant.dialogue import Services
    from assistant.world import load_world

    s = Services(perception="oracle")
    s.warm_up(load_world("apartment"), background=False)
    return s

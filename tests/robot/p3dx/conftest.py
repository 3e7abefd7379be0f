"""Shared pieces of the P3-DX tests: a fake controller with short watchdogs, thread and fd counts."""

from __future__ import annotations

import os
import threading

import pytest

from assistant.robot.p3dx import P3DXParams
from assistant.robot.p3dx.fake import FakeArcosController, Faults, patient_params


def reader_threads() -> list[threading.Thread]:
    return [t for t in threading.enumerate() if t.name.startswith(("arcos-reader", "fake-arcos"))]


def open_fds() -> int:
    return len(os.listdir("/proc/self/fd"))


@pytest.fixture
def params() -> P3DXParams:
    """Long watchdogs: tests of the watchdogs themselves override this fixture with quick ones."""
    return patient_params()


@pytest.fixture
def robots():
    """Robots a test opens outside a ``with`` block: closed after it, even when it fails."""
    opened: list = []
    yield opened
    for robot in opened:
        robot.close()


@pytest.fixture
def fake(params, robots):
    """A fake controller with the test's ``params``; closed (thread joined) after the test, after
    the test's robots, and then no driver or controller thread may be left."""
    controller = FakeArcosController(params, faults=Faults())
    yield controller
    for robot in robots:
        robot.close()
    controller.close()
    assert not reader_threads(), f"threads left behind: {reader_threads()}"

"""Helpers for the scene-view tests: decode a static page's scene messages, watch processes."""

from __future__ import annotations

import base64
import re
import time

import pytest
import umsgpack

_MESSAGE = re.compile(r'handle_command_bytearray\(base64ToBytes\("([A-Za-z0-9+/=]+)"\)\)')


def page_commands(page: str) -> list[dict]:
    """The meshcat commands (decoded msgpack) a static HTML page replays, in order."""
    return [umsgpack.unpackb(base64.b64decode(m)) for m in _MESSAGE.findall(page)]


def gone(pid: int, timeout_s: float = 5.0) -> bool:
    """True once no process ``pid`` exists (zombies count as gone)."""
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        try:
            with open(f"/proc/{pid}/stat") as handle:
                state = handle.read().rsplit(")", 1)[1].split()[0]
            if state in ("Z", "X"):
                return True
        except FileNotFoundError:
            return True
        time.sleep(0.05)
    return False


@pytest.fixture(scope="module")
def drawn_apartment(apartment):
    """The apartment drawn in a server-less view (shared by a module's read-only tests)."""
    from assistant.viz import SceneView

    view = SceneView(open_server=False)
    view.draw_world(apartment, "original")
    return view

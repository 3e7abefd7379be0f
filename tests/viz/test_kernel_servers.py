"""A meshcat server a notebook starts listens on 127.0.0.1 only and ends with its kernel —
when the kernel is shut down without the notebook closing the view, and when it is killed."""

from __future__ import annotations

import os
import signal
import time
from pathlib import Path

import pytest

from tests.viz.conftest import gone
from tests.viz.test_loopback import listening, listening_inodes, socket_inodes

ROOT = Path(__file__).resolve().parents[2]
START = "from assistant.viz import SceneView\nview = SceneView()\nprint(view.server_process.pid)"


def start_kernel():
    """A python3 kernel with the worktree first on its path, and a client on it."""
    manager_module = pytest.importorskip("jupyter_client.manager")
    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    manager, client = manager_module.start_new_kernel(kernel_name="python3", env=env, cwd=str(ROOT))
    return manager, client


def server_pid_in(client) -> int:
    """Run START in the kernel and return the meshcat server's pid it printed."""
    printed = []
    reply = client.execute_interactive(
        START, timeout=120,
        output_hook=lambda msg: printed.append(msg["content"].get("text", "")) if msg["msg_type"] == "stream" else None)
    assert reply["content"]["status"] == "ok", reply["content"]
    return int("".join(printed).split()[-1])


@pytest.mark.parametrize("how", ["shutdown", "kill"])
def test_a_notebook_server_is_on_loopback_and_ends_with_its_kernel(how):
    manager, client = start_kernel()
    try:
        pid = server_pid_in(client)
        sockets = listening(pid)
        assert sockets and all(address == "127.0.0.1" for address, _ in sockets), sockets
        held = socket_inodes(pid) & listening_inodes()
        assert held
    finally:
        client.stop_channels()
        if how == "kill":
            os.kill(manager.provisioner.process.pid, signal.SIGKILL)  # no clean-up in the kernel
            manager.shutdown_kernel(now=True)
        else:
            manager.shutdown_kernel(now=False)
    assert gone(pid, timeout_s=15.0), f"the server outlived its kernel ({how})"
    deadline = time.monotonic() + 10.0  # the OS closes its sockets as the process ends
    while held & listening_inodes() and time.monotonic() < deadline:
        time.sleep(0.1)
    assert not held & listening_inodes()

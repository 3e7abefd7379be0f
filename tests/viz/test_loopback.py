"""The viewer's server listens on 127.0.0.1 only and ends when its parent is killed."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap

import psutil

from assistant.viz import SceneView
from tests.viz.conftest import gone


def listening(pid: int) -> list[tuple[str, int]]:
    """(address, port) of every TCP socket process ``pid`` listens on (IPv4 and IPv6)."""
    return [(c.laddr.ip, c.laddr.port) for c in psutil.Process(pid).net_connections(kind="tcp")
            if c.status == psutil.CONN_LISTEN]


def listening_ports() -> set[int]:
    return {c.laddr.port for c in psutil.net_connections(kind="tcp") if c.status == psutil.CONN_LISTEN}


def test_every_socket_of_the_view_server_is_on_loopback():
    with SceneView() as view:
        sockets = listening(view.server_process.pid)
        ports = {port for _, port in sockets}
        from urllib.parse import urlparse

        assert urlparse(view.url).port in ports and urlparse(view.zmq_url).port in ports
        assert sockets and all(address == "127.0.0.1" for address, _ in sockets), sockets


PARENT = textwrap.dedent("""
    import sys, time
    from assistant.viz import SceneView
    view = SceneView()
    print(view.server_process.pid, flush=True)
    time.sleep(120)
""")


def test_kill_9_of_the_parent_leaves_no_server_and_no_listening_socket():
    parent = subprocess.Popen([sys.executable, "-c", PARENT], stdout=subprocess.PIPE, text=True,
                              env=dict(os.environ, PYTHONWARNINGS="ignore"))
    try:
        server_pid = int(parent.stdout.readline())
        ports = {port for _, port in listening(server_pid)}
        assert ports
    finally:
        parent.send_signal(signal.SIGKILL)
        parent.wait()
    assert gone(server_pid, timeout_s=5.0), "the server outlived its parent"
    assert not ports & listening_ports()

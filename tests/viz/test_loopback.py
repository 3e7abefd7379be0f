"""The viewer's server listens on 127.0.0.1 only and ends when its parent is killed."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import time

import psutil

from assistant.viz import SceneView
from tests.viz.conftest import gone


def listening(pid: int) -> list[tuple[str, int]]:
    """(address, port) of every TCP socket process ``pid`` listens on (IPv4 and IPv6)."""
    return [(c.laddr.ip, c.laddr.port) for c in psutil.Process(pid).net_connections(kind="tcp")
            if c.status == psutil.CONN_LISTEN]


def socket_inodes(pid: int) -> set[str]:
    """The inodes of the sockets process ``pid`` holds open (``/proc/PID/fd``)."""
    out = set()
    for fd in os.listdir(f"/proc/{pid}/fd"):
        try:
            target = os.readlink(f"/proc/{pid}/fd/{fd}")
        except OSError:
            continue
        if target.startswith("socket:["):
            out.add(target[8:-1])
    return out


def listening_inodes() -> set[str]:
    """Inodes of every listening TCP socket of the machine (``/proc/net/tcp``, ``tcp6``): a
    socket is matched by inode, not port, since other programs may reuse a port at once."""
    out = set()
    for table in ("/proc/net/tcp", "/proc/net/tcp6"):
        with open(table) as handle:
            next(handle)
            for line in handle:
                fields = line.split()
                if fields[3] == "0A":  # TCP_LISTEN
                    out.add(fields[9])
    return out


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
        assert listening(server_pid)
        sockets = socket_inodes(server_pid) & listening_inodes()
        assert sockets
    finally:
        parent.send_signal(signal.SIGKILL)
        parent.wait()
    assert gone(server_pid, timeout_s=15.0), "the server outlived its parent"
    deadline = time.monotonic() + 10.0  # the kernel closes them as the process ends
    while sockets & listening_inodes() and time.monotonic() < deadline:
        time.sleep(0.1)
    assert not sockets & listening_inodes()

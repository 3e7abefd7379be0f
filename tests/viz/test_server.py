"""The meshcat server a SceneView starts: it serves, receives the scene and always ends."""

from __future__ import annotations

import base64
import os
import re
import signal
import socket
import subprocess
import sys
import threading
import time
import urllib.request
from urllib.parse import urlparse

import pytest
import umsgpack
import zmq

from assistant.viz import SceneView, ViewerError
from tests.viz.conftest import gone


def port_is_free(port: int) -> bool:
    """True when nothing listens on 127.0.0.1:port (a new server could bind it)."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as probe:
        probe.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            probe.bind(("127.0.0.1", port))
        except OSError:
            return False
    return True


def server_scene_paths(zmq_url: str) -> set[str]:
    """Paths of the objects a running meshcat-server holds (asked with its get_scene)."""
    sock = zmq.Context.instance().socket(zmq.REQ)
    sock.setsockopt(zmq.RCVTIMEO, 5000)
    sock.setsockopt(zmq.LINGER, 0)
    sock.connect(zmq_url)
    try:
        sock.send(b"get_scene")
        page = sock.recv().decode("utf-8")
    finally:
        sock.close()
    found = re.findall(r"data:application/octet-binary;base64,([A-Za-z0-9+/=]+)", page)
    commands = [umsgpack.unpackb(base64.b64decode(m)) for m in found]
    return {c["path"] for c in commands if c["type"] == "set_object"}


def test_server_serves_the_view_receives_the_scene_and_ends_on_close():
    view = SceneView()
    try:
        process = view.server_process
        assert process is not None and process.poll() is None
        url = urlparse(view.url)
        assert url.scheme == "http" and url.hostname == "127.0.0.1"
        with urllib.request.urlopen(view.url, timeout=5) as reply:
            assert reply.status == 200 and b"main.min.js" in reply.read()
        view.draw_robot((1.0, 2.0, 0.5))
        view.draw_path("route", [(0, 0), (1, 1)])
        assert server_scene_paths(view.zmq_url) == set(view.object_paths())
        zmq_port = urlparse(view.zmq_url).port
    finally:
        view.close()
    assert process.poll() is not None, "the meshcat-server process has ended"
    assert port_is_free(url.port) and port_is_free(zmq_port)
    view.close()  # twice is fine
    assert view.url is None and view.zmq_url is None
    view.draw_robot((0.0, 0.0, 0.0), name="another")  # a closed view goes on recording
    assert "/meshcat/robots/another/body" in view.object_paths()
    assert "/meshcat/paths/route/line" in view.object_paths()


def test_a_server_that_died_gives_a_clear_error_and_the_scene_is_kept():
    with SceneView(timeout_s=1.0) as view:
        view.server_process.kill()
        view.server_process.wait()
        with pytest.raises(ViewerError, match="did not answer.*save_html"):
            view.draw_robot((0.0, 0.0, 0.0))
        assert "/meshcat/robots/robot/body" in view.object_paths()


def test_with_block_ends_the_server_even_when_drawing_fails():
    with pytest.raises(ZeroDivisionError):
        with SceneView() as view:
            process = view.server_process
            1 / 0
    assert process.poll() is not None


def test_an_unreachable_server_fails_fast_with_advice():
    with socket.socket() as probe:  # a port nobody listens on
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    started = time.monotonic()
    with pytest.raises(ViewerError, match="meshcat-server"):
        SceneView(zmq_url=f"tcp://127.0.0.1:{port}", timeout_s=0.3)
    assert time.monotonic() - started < 3.0


def test_a_view_on_someone_elses_server_leaves_it_running():
    with SceneView() as owner:
        guest = SceneView(zmq_url=owner.zmq_url)
        assert guest.server_process is None and guest.url == owner.url
        guest.draw_robot((0.0, 0.0, 0.0), name="guest")
        guest.close()
        assert owner.server_process.poll() is None
        assert "/meshcat/robots/guest/body" in server_scene_paths(owner.zmq_url)


def test_wait_returns_when_the_server_dies():
    with SceneView() as view:
        view.server_process.kill()
        started = time.monotonic()
        view.wait(timeout_s=10)
        assert time.monotonic() - started < 2.0


def test_wait_returns_on_sigterm_so_the_server_is_closed():
    """`kill PID` of `assistant world NAME --view` must not leave its server behind."""
    received = []

    def record(*_):
        received.append("outside wait")

    safety = signal.signal(signal.SIGTERM, record)
    try:
        with SceneView() as view:
            timer = threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGTERM))
            timer.start()
            started = time.monotonic()
            view.wait(timeout_s=20)
            timer.join()
            assert time.monotonic() - started < 10 and not received
            assert signal.getsignal(signal.SIGTERM) is record, "wait() restores the handler"
            process = view.server_process
        assert process.poll() is not None
    finally:
        signal.signal(signal.SIGTERM, safety)


def test_a_server_left_open_ends_with_the_interpreter():
    code = ("from assistant.viz import SceneView\n"
            "view = SceneView()\n"
            "print(view.server_process.pid, flush=True)\n")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                            timeout=60, check=True)
    pid = int(result.stdout.split()[-1])
    assert gone(pid)

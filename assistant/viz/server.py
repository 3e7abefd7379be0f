"""The meshcat side of the scene view: a recorded scene tree and an owned ``meshcat-server``.

meshcat 0.3.2's ``Visualizer`` sends each drawing command to a ``meshcat-server`` subprocess
over ZeroMQ. Two things in it do not fit a product that must not leak processes or hang:

* ``Visualizer.close()`` calls a ``ViewerWindow.close()`` that does not exist, and the server
  subprocess it starts (``ViewerWindow.server_proc``) lives on until interpreter exit; its
  stdout/stderr pipes are never read after start-up, so a long session can fill them.
* its ZeroMQ socket has no time-outs: a server that died or never existed blocks forever.
* its server listens on every network interface and outlives a parent killed with ``kill -9``
  (it runs in a session of its own). The server started here is :mod:`assistant.viz.loopback`:
  meshcat's own server bound to 127.0.0.1, ending when its parent ends.

:class:`RecordingWindow` stands in for meshcat's ``ViewerWindow`` behind an ordinary
``meshcat.Visualizer``. It keeps the scene tree exactly as the server does (meshcat's own
``SceneTree`` and message packing), so a static HTML page can be written with or without a
server, and forwards every command to a :class:`MeshcatServer` when there is one.
:class:`MeshcatServer` starts (or connects to) a server, drains its output, applies time-outs
and ends the process it started in :meth:`MeshcatServer.close` — and at interpreter exit.
"""

from __future__ import annotations

import atexit
import collections
import contextlib
import io
import os
import subprocess
import sys
import threading
import weakref

import umsgpack
import zmq
from meshcat.servers.tree import SceneTree, find_node
from meshcat.visualizer import ViewerWindow

from assistant.errors import AssistantError

__all__ = ["MeshcatServer", "RecordingWindow", "ViewerError"]


class ViewerError(AssistantError):
    """The meshcat server could not be started or reached."""


#: the longest a new server may take to print its address (it imports tornado and meshcat)
STARTUP_S = 20.0

# Servers this process started and has not yet ended; ended at interpreter exit.
_LIVE: "weakref.WeakSet[MeshcatServer]" = weakref.WeakSet()


@atexit.register
def _close_live_servers() -> None:
    for server in list(_LIVE):
        server.close()


class _TimedViewerWindow(ViewerWindow):
    """meshcat's ``ViewerWindow`` with send/receive time-outs and no lingering messages."""

    timeout_ms = 10_000

    def connect_zmq(self):
        self.zmq_socket = self.context.socket(zmq.REQ)
        self.zmq_socket.setsockopt(zmq.RCVTIMEO, self.timeout_ms)
        self.zmq_socket.setsockopt(zmq.SNDTIMEO, self.timeout_ms)
        self.zmq_socket.setsockopt(zmq.LINGER, 0)
        self.zmq_socket.connect(self.zmq_url)


def _start_loopback_server(timeout_s: float) -> tuple[subprocess.Popen, str]:
    """Start :mod:`assistant.viz.loopback` (127.0.0.1 only, ends with this process); return the
    process and its ZeroMQ address."""
    process = subprocess.Popen(
        [sys.executable, "-u", "-m", "assistant.viz.loopback", "--parent", str(os.getpid())],
        stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
        start_new_session=True)  # Ctrl-C in a chat does not reach it; close() and the parent watch end it
    result: dict[str, str] = {}

    def read_url() -> None:
        for raw in iter(process.stdout.readline, b""):
            line = raw.decode("utf-8", "replace").strip()
            if line.startswith("zmq_url="):
                result["zmq_url"] = line.split("=", 1)[1]
                return

    reader = threading.Thread(target=read_url, daemon=True)
    reader.start()
    reader.join(timeout_s)
    if "zmq_url" not in result:
        process.kill()
        process.wait()
        detail = process.stderr.read().decode("utf-8", "replace").strip().splitlines()
        raise RuntimeError(f"the meshcat server did not start within {timeout_s:g} s"
                           + (f" ({detail[-1]})" if detail else ""))
    return process, result["zmq_url"]


def _drain(stream, tail: collections.deque) -> None:
    """Read a server pipe to its end so the server never blocks on a full pipe."""
    try:
        for line in iter(stream.readline, b""):
            tail.append(line.decode("utf-8", "replace").rstrip())
    except (OSError, ValueError):  # pipe closed under us while ending the server
        pass


class MeshcatServer:
    """A connection to a ``meshcat-server``: started here (and owned) or found at ``zmq_url``.

    ``timeout_s`` bounds every exchange with the server; a server that does not answer in
    time raises :class:`ViewerError` instead of hanging.
    """

    def __init__(self, zmq_url: str | None = None, timeout_s: float = 10.0):
        self.process: subprocess.Popen | None = None
        self._tail: collections.deque[str] = collections.deque(maxlen=40)
        self._threads: list[threading.Thread] = []
        self._closed = False
        window_cls = type("_Window", (_TimedViewerWindow,), {"timeout_ms": int(timeout_s * 1000)})
        owned = zmq_url is None
        try:
            if owned:
                self.process, zmq_url = _start_loopback_server(max(timeout_s, STARTUP_S))
                _LIVE.add(self)
            with contextlib.redirect_stdout(io.StringIO()):  # meshcat prints the URL; see web_url
                self._window = window_cls(zmq_url=zmq_url, start_server=False, server_args=[])
        except zmq.Again:
            self.close()
            raise ViewerError(f"no meshcat server answered at {zmq_url} within {timeout_s:g} s; "
                              "start one with `meshcat-server` or leave zmq_url unset to start "
                              "one here") from None
        except (RuntimeError, OSError, zmq.ZMQError) as exc:
            self.close()
            raise ViewerError(f"could not start a meshcat server: {exc}") from exc
        self.zmq_url: str = self._window.zmq_url
        self.web_url: str = self._window.web_url
        if owned:
            for stream in (self.process.stdout, self.process.stderr):
                thread = threading.Thread(target=_drain, args=(stream, self._tail), daemon=True,
                                          name=f"meshcat-server-{self.process.pid}-drain")
                thread.start()
                self._threads.append(thread)

    @property
    def owns_process(self) -> bool:
        return self.process is not None

    @property
    def alive(self) -> bool:
        """True while the connection is open and (for an owned server) the process runs."""
        if self._closed:
            return False
        return self.process is None or self.process.poll() is None

    def send(self, command_type: str, path: str, packed: bytes) -> None:
        """Send one packed meshcat command and wait for the server's acknowledgement."""
        if self._closed:
            raise ViewerError("this scene view's meshcat server is closed")
        socket = self._window.zmq_socket
        try:
            socket.send_multipart([command_type.encode("utf-8"), path.encode("utf-8"), packed])
            socket.recv()
        except zmq.Again:
            self._window.connect_zmq()  # a REQ socket is unusable after a missed reply
            detail = f" (server said: {self._tail[-1]})" if self._tail else ""
            raise ViewerError(f"the meshcat server at {self.zmq_url} did not answer"
                              f"{detail}; the scene is still recorded and save_html() works") from None

    def close(self, timeout_s: float = 3.0) -> None:
        """Close the connection; end the server process if this object started it.

        Safe to call twice. The process gets SIGTERM, then SIGKILL if it has not ended within
        ``timeout_s``; its ports are free when this returns.
        """
        if self._closed:
            return
        self._closed = True
        with contextlib.suppress(Exception):  # no window when the server failed to start
            self._window.zmq_socket.close(linger=0)
        process = self.process
        if process is not None:
            _LIVE.discard(self)
            if process.poll() is None:
                process.terminate()
                try:
                    process.wait(timeout=timeout_s)
                except subprocess.TimeoutExpired:
                    process.kill()
                    process.wait(timeout=timeout_s)
            for thread in self._threads:
                thread.join(timeout=1.0)
            for stream in (process.stdout, process.stderr):
                with contextlib.suppress(Exception):
                    stream.close()

    def __del__(self):  # last resort; close() is the way
        with contextlib.suppress(Exception):
            self.close(timeout_s=1.0)


class RecordingWindow:
    """A stand-in for meshcat's ``ViewerWindow``: records the scene tree, forwards to a server.

    Pass it to ``meshcat.Visualizer(window=...)``. The tree (``self.tree``, meshcat's own
    ``SceneTree``) holds the packed commands the way ``meshcat-server`` holds them, so
    :func:`assistant.viz.html.scene_html` can write the page without asking a server.
    """

    def __init__(self, server: MeshcatServer | None = None):
        self.server = server
        self.tree = SceneTree()

    @property
    def web_url(self) -> str | None:
        return None if self.server is None else self.server.web_url

    def send(self, command) -> None:
        data = command.lower()
        packed = umsgpack.packb(data)
        self.record(data["type"], data["path"], packed)
        if self.server is not None:
            self.server.send(data["type"], data["path"], packed)

    def record(self, command_type: str, path: str, packed: bytes) -> None:
        """Apply one command to the tree as ``meshcat-server`` does."""
        parts = [p for p in path.split("/") if p]
        if command_type == "set_object":
            node = find_node(self.tree, parts)
            node.object = packed
            node.properties = []
        elif command_type == "set_transform":
            find_node(self.tree, parts).transform = packed
        elif command_type == "set_property":
            find_node(self.tree, parts).properties.append(packed)
        elif command_type == "set_animation":
            find_node(self.tree, parts).animation = packed
        elif command_type == "delete":
            if parts:
                parent = find_node(self.tree, parts[:-1])
                parent.pop(parts[-1], None)
            else:
                self.tree = SceneTree()

    def object_paths(self) -> list[str]:
        """Paths (``/meshcat/world/furniture/couch_1``…) of every node holding an object."""
        out: list[str] = []

        def visit(node, prefix: str) -> None:
            if node.object is not None:
                out.append(prefix or "/")
            for key in sorted(node):
                visit(node[key], f"{prefix}/{key}")

        visit(self.tree, "")
        return out

    def node(self, path: str):
        """The tree node at ``path``, or None when nothing was drawn there."""
        node = self.tree
        for part in (p for p in path.split("/") if p):
            if part not in node:
                return None
            node = node[part]
        return node

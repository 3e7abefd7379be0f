"""The meshcat server program the product starts: loopback only, and it ends with its parent.

Run as ``python -m assistant.viz.loopback --parent PID``. It is meshcat's own
``ZMQWebSocketBridge`` with two changes:

* meshcat 0.3.2 calls tornado's ``Application.listen(port)`` without an address, so its web
  server listens on every interface (``0.0.0.0`` and ``[::]``): anyone on the home network
  could watch the house plan. Here the application listens on ``127.0.0.1`` only, whatever
  address it is asked for; the ZeroMQ socket was already bound to ``127.0.0.1``.
* meshcat starts its server in a new session, so a parent killed with ``kill -9`` leaves it
  running, ports open. Here the server watches the parent process (its pid, given on the
  command line, every 0.25 s) and ends as soon as the parent is gone; on Linux the kernel also
  sends it SIGTERM when the parent dies (``prctl(PR_SET_PDEATHSIG)``).

The first two lines it prints are meshcat's ``zmq_url=…`` and ``web_url=…``, which
:class:`assistant.viz.server.MeshcatServer` reads.
"""

from __future__ import annotations

import argparse
import os
import signal
import sys

#: the only address the viewer's servers listen on
LOOPBACK = "127.0.0.1"
#: how often the server checks that its parent still lives (seconds)
PARENT_CHECK_S = 0.25
_PR_SET_PDEATHSIG = 1


def parent_alive(pid: int) -> bool:
    """True while ``pid`` is this process's parent and still runs (not a zombie)."""
    if os.getppid() != pid:  # re-parented: the parent has died
        return False
    try:
        with open(f"/proc/{pid}/stat") as handle:
            state = handle.read().rsplit(")", 1)[1].split()[0]
        return state not in ("Z", "X")
    except FileNotFoundError:
        return False
    except OSError:  # no /proc (not Linux): the re-parenting check above is what we have
        return True


def die_with_parent() -> None:
    """Ask the Linux kernel to send SIGTERM when the parent ends (no-op elsewhere)."""
    if not sys.platform.startswith("linux"):
        return
    import ctypes

    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(_PR_SET_PDEATHSIG, int(signal.SIGTERM), 0, 0, 0)
    except (OSError, AttributeError):  # no prctl: the parent watch alone
        pass


def make_bridge():
    """meshcat's bridge with its web server bound to 127.0.0.1 (imported here: the import
    starts a ZeroMQ context, which only the server process should pay for)."""
    import tornado.web
    from meshcat.servers import zmqserver

    class LoopbackApplication(tornado.web.Application):
        def listen(self, port, address=None, **kwargs):  # noqa: ARG002 - any address is refused
            return super().listen(port, address=LOOPBACK, **kwargs)

    class LoopbackBridge(zmqserver.ZMQWebSocketBridge):
        def make_app(self):
            return LoopbackApplication([
                (r"/static/(.*)", zmqserver.StaticFileHandlerNoCache,
                 {"path": zmqserver.VIEWER_ROOT, "default_filename": zmqserver.VIEWER_HTML}),
                (r"/", zmqserver.WebSocketHandler, {"bridge": self}),
            ])

    return LoopbackBridge(host=LOOPBACK)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description="meshcat server on 127.0.0.1 that ends with its parent")
    parser.add_argument("--parent", type=int, required=True, help="pid to watch; the server ends with it")
    args = parser.parse_args(argv)
    die_with_parent()
    if not parent_alive(args.parent):  # the parent died before the watch began
        return 0
    import tornado.ioloop

    bridge = make_bridge()
    print(f"zmq_url={bridge.zmq_url}", flush=True)
    print(f"web_url={bridge.web_url}", flush=True)

    def check_parent() -> None:
        if not parent_alive(args.parent):
            bridge.ioloop.stop()

    tornado.ioloop.PeriodicCallback(check_parent, PARENT_CHECK_S * 1000).start()
    try:
        bridge.run()
    except KeyboardInterrupt:
        pass
    return 0


if __name__ == "__main__":
    sys.exit(main())

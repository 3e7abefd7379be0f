"""Benchmark: the P3-DX driver over the fake ARCOS controller (a pseudo-terminal, no robot).

    .venv/bin/python benchmarks/bench_p3dx_link.py [--repeats 10]

Prints medians (and min/max) over repeated runs of:
  * connect: open the port, SYNC0/1/2, OPEN, limits, ENABLE, first status packet;
  * stop(): from the call until the controller has the STOP command;
  * a silent controller / garbage on the line: from the last valid status packet the controller
    sent until it has STOP (the driver's link watchdog is 0.6 s here, as in the fault tests; 0.5 s in
    hardware/p3dx.yaml);
  * the port vanishing: from the fault until the driver raises LinkLostError, and until the
    controller's own watchdog (1.0 s here) stops the motors.
The fake runs in this process's threads, so the figures are the driver's and the fake's together
on a shared machine; on a robot, add the serial line's transfer time (about 1 ms per 10 bytes
at 9600 baud).
"""

from __future__ import annotations

import argparse
import statistics
import time

from assistant.robot.errors import LinkLostError
from assistant.robot.p3dx import P3DX
from assistant.robot.p3dx.fake import FakeArcosController, quick_params


def _stats(values: list[float]) -> str:
    return (f"median {statistics.median(values) * 1000:7.1f} ms   "
            f"min {min(values) * 1000:7.1f}   max {max(values) * 1000:7.1f}")


def _driving(fake, params) -> P3DX:
    """A robot driving before the fault (a start that a starved machine trips is tried again)."""
    for _ in range(3):
        robot = P3DX(fake.port, params=params)
        robot.connect()
        try:
            robot.send_velocity(0.3, 0.0)
            robot.advance(0.3)
            return robot
        except LinkLostError:
            robot.close()
    raise RuntimeError("the link kept tripping before any fault: the machine is too loaded to measure")


def _until(fake, predicate, start: float) -> float:
    if not fake.wait_until(predicate, 3.0):
        raise RuntimeError("the controller never saw the expected stop")
    return time.monotonic() - start


def _fault_to_stop(params, inject) -> float:
    with FakeArcosController(params) as fake:
        robot = _driving(fake, params)
        start = time.monotonic()
        inject(fake)
        try:
            robot.advance(3.0)
        except LinkLostError:
            pass
        _until(fake, lambda: fake.log.stop_commands, start)
        stop = fake.log.stop_commands[0]
        took = stop - max(t for t in fake.log.sips_sent if t <= stop)
        robot.close()
    return took


def _vanish(params) -> tuple[float, float]:
    with FakeArcosController(params) as fake:
        robot = _driving(fake, params)
        start = time.monotonic()
        fake.vanish()
        try:
            robot.advance(3.0)
        except LinkLostError:
            raised = time.monotonic() - start
        stopped = _until(fake, lambda: fake.log.watchdog_stops, start)
        robot.close()
    return raised, stopped


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=10)
    args = parser.parse_args(argv)
    params = quick_params()
    connect, stop, silent, garbage, raised, watchdog = [], [], [], [], [], []
    for _ in range(args.repeats):
        with FakeArcosController(params) as fake:
            robot = P3DX(fake.port, params=params)
            start = time.monotonic()
            robot.connect()
            connect.append(time.monotonic() - start)
            robot.send_velocity(0.3, 0.0)
            robot.advance(0.2)
            start = time.monotonic()
            robot.stop()
            stop.append(_until(fake, lambda: fake.log.stop_commands, start))
            robot.close()
        silent.append(_fault_to_stop(params, lambda f: setattr(f.faults, "silent", True)))
        garbage.append(_fault_to_stop(params, lambda f: setattr(f.faults, "garbage", True)))
        r, w = _vanish(params)
        raised.append(r)
        watchdog.append(w)
    print(f"P3-DX over the fake controller, {args.repeats} repeats "
          f"(link watchdog {params.link_watchdog_s:g} s, controller watchdog {params.controller_watchdog_s:g} s)")
    print(f"  connect (handshake → first SIP)        {_stats(connect)}")
    print(f"  stop() → controller has STOP           {_stats(stop)}")
    print(f"  silent controller: last SIP → STOP     {_stats(silent)}")
    print(f"  garbage on the line: last SIP → STOP   {_stats(garbage)}")
    print(f"  port vanished → LinkLostError          {_stats(raised)}")
    print(f"  port vanished → controller watchdog    {_stats(watchdog)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

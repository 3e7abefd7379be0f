"""What a person waits for: the chat's first reply after its greeting, and the longest silence
of a command run in a terminal.

``first-reply``: start ``assistant chat --world apartment`` in a pseudo-terminal (as ``make
run`` does, after ``assistant warm-up``), wait for the greeting, type a first command at once,
and time from the greeting to the robot's first words. Target ≤ 2 s. Repeated ``--repeats``
times; the median and the worst are printed.

``silence``: run one command in a pseudo-terminal (so progress is shown as a person sees it)
and report the longest time with no new output while it runs. Target ≤ 3 s. ``--fresh-cache``
runs it on an empty model cache (first use: every model trains).

``exit``: how long a command takes to end after its work is done — the CPU time of the
interpreter's finalization (the process's CPU time from the kernel minus its CPU time when its
last atexit handler ran) and the wall time from the command's last output to its end — run as
the ``assistant`` program (``program()``, which prepares a quick exit) and, with ``--plain``,
as ``main()`` alone (the interpreter's default finalization, as before issue 21's fix).
CPU time is the figure to trust on a shared machine.

    .venv/bin/python benchmarks/bench_trust.py first-reply [--repeats 5]
    .venv/bin/python benchmarks/bench_trust.py silence [--fresh-cache] -- assistant parse "go to the kitchen"
    .venv/bin/python benchmarks/bench_trust.py exit [--plain] [--repeats 3] -- assistant warm-up

``chat-silence``: start ``assistant chat --world apartment`` in a pseudo-terminal, type one
command (``--say``, default "where is my mug?") at the first prompt, and report the time to the
first line on screen and the longest gap between lines until the chat has been quiet for
``--settle`` seconds after its last words (then it is left with Ctrl-D).

    .venv/bin/python benchmarks/bench_trust.py chat-silence [--say "where is my mug?"]
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pexpect

ROOT = Path(__file__).resolve().parents[1]
FIRST_COMMAND = "where is my mug?"


def _env(extra: dict | None = None) -> dict:
    env = dict(os.environ, PYTHONPATH=str(ROOT), TERM="xterm", PYTHONWARNINGS="ignore")
    env.update(extra or {})
    return env


def first_reply(data_dir: str) -> float:
    """Seconds from the greeting to the robot's first reply to :data:`FIRST_COMMAND`."""
    child = pexpect.spawn(sys.executable, ["-m", "assistant", "chat", "--world", "apartment"],
                          env=_env({"ASSISTANT_DATA": data_dir}), encoding="utf-8", timeout=300,
                          dimensions=(40, 200))
    try:
        child.expect("Hello!")
        greeted = time.monotonic()
        child.expect("you> ")
        child.sendline(FIRST_COMMAND)
        child.expect_exact(FIRST_COMMAND)  # the echo of what was typed
        child.expect(r"\S")  # the first character the robot prints after it
        return time.monotonic() - greeted
    finally:
        child.sendcontrol("c")
        child.sendcontrol("c")
        child.close(force=True)


def longest_silence(command: list[str], env: dict) -> tuple[float, float, int, str]:
    """(longest gap between outputs, total seconds, exit status, what was printed after the
    gap) of ``command`` on a pty."""
    child = pexpect.spawn(command[0], command[1:], env=env, encoding="utf-8", timeout=None,
                          dimensions=(40, 200))
    start = last = time.monotonic()
    longest, after = 0.0, ""
    while True:
        try:
            text = child.read_nonblocking(4096, timeout=0.05)
            now = time.monotonic()
            if now - last > longest:
                longest, after = now - last, text
            last = now
        except pexpect.TIMEOUT:
            continue
        except pexpect.EOF:
            break
    end = time.monotonic()
    if end - last > longest:
        longest, after = end - last, "(the end)"
    child.close()
    return longest, end - start, child.exitstatus if child.exitstatus is not None else -1, after


#: run inside the measured process: the command as the program runs it (or main() alone with
#: "plain"), and the process's CPU time written when its last atexit handler runs
EXIT_PROBE = """
import atexit, sys, time
out = open(sys.argv[1], "w")
atexit.register(lambda: (out.write(repr(time.process_time())), out.close()))  # registered first: runs last
import assistant.cli as cli
plain = sys.argv[2] == "plain"
sys.argv = ["assistant", *sys.argv[3:]]
raise SystemExit(cli.main() if plain else cli.program())
"""


def exit_cost(command: list[str], plain: bool) -> tuple[float, float]:
    """(CPU seconds of finalization, wall seconds from the last output to the end) of one run of
    ``assistant`` ``command``."""
    with tempfile.NamedTemporaryFile("r", suffix=".cpu") as mark:
        started = time.monotonic()
        child = subprocess.Popen([sys.executable, "-c", EXIT_PROBE, mark.name, "plain" if plain else "program",
                                  *command], env=_env(), stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        last = started
        while child.stdout.read1(4096):
            last = time.monotonic()
        _, status, usage = os.wait4(child.pid, 0)
        ended = time.monotonic()
        if status != 0:
            raise SystemExit(f"assistant {' '.join(command)} failed (wait status {status})")
        at_last_handler = float(mark.read())
    return usage.ru_utime + usage.ru_stime - at_last_handler, ended - last


def chat_silence(say: str, settle_s: float, data_dir: str) -> tuple[float, float, str, float]:
    """(seconds to the first output, longest gap after it, what ended that gap, seconds from the
    command typed to the chat's last output) of one chat."""
    child = pexpect.spawn(sys.executable, ["-m", "assistant", "chat", "--world", "apartment"],
                          env=_env({"ASSISTANT_DATA": data_dir}), encoding="utf-8", timeout=None,
                          dimensions=(40, 200))
    started = last = time.monotonic()
    first, longest, after, typed, typed_at = None, 0.0, "", False, 0.0
    try:
        while time.monotonic() - last < settle_s:
            try:
                text = child.read_nonblocking(4096, timeout=0.05)
            except pexpect.TIMEOUT:
                continue
            now = time.monotonic()
            if first is None:
                first = now - started
            elif now - last > longest:
                longest, after = now - last, text
            last = now
            if not typed and "you> " in text:
                child.sendline(say)
                typed, typed_at = True, time.monotonic()
    except pexpect.EOF:
        pass
    finally:
        child.sendeof()  # Ctrl-D leaves the chat; a slow exit under load must not lose the figures
        try:
            child.expect(pexpect.EOF, timeout=60)
        except pexpect.ExceptionPexpect:
            pass
        try:
            child.close(force=True)
        except pexpect.ExceptionPexpect:
            pass
    return first or 0.0, longest, after, last - typed_at if typed else 0.0


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="what", required=True)
    first = sub.add_parser("first-reply")
    first.add_argument("--repeats", type=int, default=5)
    silence = sub.add_parser("silence")
    silence.add_argument("--fresh-cache", action="store_true")
    silence.add_argument("command", nargs=argparse.REMAINDER)
    chat = sub.add_parser("chat-silence")
    chat.add_argument("--say", default=FIRST_COMMAND)
    chat.add_argument("--settle", type=float, default=45.0, help="seconds of quiet that end the run")
    ending = sub.add_parser("exit")
    ending.add_argument("--plain", action="store_true", help="main() alone: the interpreter's default finalization")
    ending.add_argument("--repeats", type=int, default=3)
    ending.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    if args.what == "chat-silence":
        with tempfile.TemporaryDirectory() as data:
            first, longest, after, busy = chat_silence(args.say, args.settle, data)
        print(f"chat: first line after {first:.2f} s, then the longest gap {longest:.2f} s (target <= 3 s) "
              f"around {args.say!r} ({busy:.1f} s from typing it to the last line)\n"
              f"  it ended with: {after.strip()[-120:]!r}")
        return 0
    if args.what == "exit":
        command = [c for c in args.command if c != "--"]
        command = command[1:] if command and command[0] == "assistant" else command
        runs = [exit_cost(command, args.plain) for _ in range(args.repeats)]
        cpu, wall = (statistics.median(r[i] for r in runs) for i in (0, 1))
        print(f"after its work, {'main() alone' if args.plain else 'the assistant program'} took median "
              f"{cpu:.2f} s of CPU to end ({wall:.2f} s wall from its last output) over {len(runs)} runs: "
              f"assistant {' '.join(command)}")
        return 0
    if args.what == "first-reply":
        with tempfile.TemporaryDirectory() as data:
            times = [first_reply(data) for _ in range(args.repeats)]
        print(f"first reply after the greeting: median {statistics.median(times):.2f} s, "
              f"worst {max(times):.2f} s over {len(times)} chats (target <= 2 s)")
        return 0
    command = [c for c in args.command if c != "--"]
    if command and command[0] == "assistant":
        command = [sys.executable, "-m", "assistant", *command[1:]]
    cache = tempfile.mkdtemp(prefix="fresh-cache-") if args.fresh_cache else None
    try:
        env = _env({"ASSISTANT_CACHE": cache} if cache else None)
        longest, total, status, after = longest_silence(command, env)
    finally:
        if cache:
            shutil.rmtree(cache, ignore_errors=True)
    print(f"longest silence {longest:.2f} s in {total:.1f} s (exit {status}; target <= 3 s): "
          f"{' '.join(args.command)}\n  the longest silence ended with: {after.strip()[:120]!r}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

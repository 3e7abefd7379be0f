"""The ``assistant`` console script: one subcommand per module of this package.

Each command module exposes ``register(subparsers)`` and imports only ``argparse`` at module
level, so that ``assistant parse`` does not pay for open3d. Heavy imports happen inside the
handler. A handler returns an exit status; an :class:`~assistant.errors.AssistantError` becomes
one line on stderr and status 2, and the process never shows a traceback for bad input.
"""

from __future__ import annotations

import argparse
import importlib
import sys
import time

from assistant.errors import AssistantError
from assistant.runtime import limit_openmp_threads, prepare_to_exit

#: Command modules under ``assistant.cli``, in the order ``--help`` lists them.
COMMAND_MODULES = (
    "world",
    "sim",
    "parse",
    "relations",
    "perceive",
    "fetch",
    "where",
    "teach",
    "chat",
    "record",
    "listen",
    "enrol",
    "eval",
    "doctor",
    "warmup",
)


#: commands that talk with the person (a terminal line ticking beside them would be in the way)
INTERACTIVE_COMMANDS = frozenset({"chat", "teach", "record", "enrol"})


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="assistant",
        description="A home robot you direct with ordinary spatial language.",
    )
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND")
    subparsers.required = True
    for name in COMMAND_MODULES:
        try:
            module = importlib.import_module(f"assistant.cli.{name}")
        except ModuleNotFoundError as error:  # a command whose module is not built yet
            if error.name != f"assistant.cli.{name}":
                raise
            continue
        module.register(subparsers)
    return parser


def json_output(args: argparse.Namespace) -> bool:
    """Whether the command prints JSON: its ``--json``, or an evaluation's (``eval NAME … --json``)."""
    return bool(getattr(args, "json", False)) or "--json" in (getattr(args, "options", None) or [])


def main(argv: list[str] | None = None) -> int:
    """A command line (``argv`` None: this process's) → its exit status."""
    limit_openmp_threads()
    from assistant.cli.common import join_negative_values

    parser = build_parser()
    args = parser.parse_args(join_negative_values(sys.argv[1:] if argv is None else list(argv)))
    import assistant.progress as progress

    # training on first use shows its progress on a terminal; quiet with --json or in a pipe
    hook = progress.hook_for(json_output(args))
    progress.set_hook(hook)
    # a command that works a while before it prints says so (not the interactive ones)
    heartbeat = progress.Heartbeat(f"assistant {args.command}",
                                   since=time.monotonic() - progress.process_age())  # start-up counts
    if hook is not progress.quiet and args.command not in INTERACTIVE_COMMANDS and not getattr(args, "view", False):
        heartbeat.start()
    try:
        return int(args.handler(args) or 0)
    except AssistantError as error:
        print(f"assistant {args.command}: {error}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:  # e.g. `assistant world apartment --json | head`
        return 0
    finally:
        heartbeat.stop()
        if hasattr(hook, "close"):
            hook.close()  # the last progress line ends (and stops ticking)
        progress.set_hook(None)


def program() -> int:
    """The ``assistant`` program (the console script and ``python -m assistant``): :func:`main`
    on the process's arguments, then :func:`~assistant.runtime.prepare_to_exit`, so the process
    ends at once after its last line instead of spending a second or more freeing its models.
    A speech synthesis still hung at that point ends the process at once with the command's
    status (:func:`~assistant.dialogue.speech.tts.leave_if_synthesis_hung`)."""
    try:
        code = main()
        tts = sys.modules.get("assistant.dialogue.speech.tts")  # loaded only when a command spoke
        if tts is not None:
            tts.leave_if_synthesis_hung(code)
        return code
    finally:
        prepare_to_exit()

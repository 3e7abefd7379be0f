"""Helpers shared by the command modules: JSON output, batch requests, pose arguments."""

from __future__ import annotations

import argparse
import json
import math
import os
import re
import sys
from collections.abc import Callable, Iterable
from typing import Any

from assistant.errors import AssistantError
from assistant.fileio import check_readable_file, check_writable_target


def to_jsonable(value: Any) -> Any:
    """Convert numpy scalars/arrays, tuples and dataclass-like objects for ``json.dumps``."""
    if hasattr(value, "to_dict"):
        return to_jsonable(value.to_dict())
    if isinstance(value, dict):
        return {str(k): to_jsonable(v) for k, v in value.items()}
    if isinstance(value, (list, tuple, set, frozenset)):
        return [to_jsonable(v) for v in value]
    if hasattr(value, "tolist"):  # numpy array or scalar
        return to_jsonable(value.tolist())
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def emit_json(obj: Any, stream=None) -> None:
    """Print exactly one JSON object on one line of stdout."""
    stream = stream or sys.stdout
    stream.write(json.dumps(to_jsonable(obj), ensure_ascii=False) + "\n")
    stream.flush()


def show_report(args, report, print_report) -> int:
    """The end of every ``assistant eval NAME``: the report as one JSON line with ``--json``,
    else ``print_report(report)``'s tables; exit status 0."""
    if getattr(args, "json", False):
        emit_json(report)
    else:
        print_report(report)
    return 0


#: longest batch line read, in bytes; a longer line is answered with an error and skipped
MAX_LINE_BYTES = 64 * 1024
#: how much of one over-long line is skipped before the batch ends (``/dev/zero`` never ends one)
MAX_SKIPPED_BYTES = 16 * 2**20


def _finite_float(text: str) -> float:
    value = float(text)
    if not math.isfinite(value):
        raise ValueError(f"number {text} is out of range")
    return value


def _no_constant(name: str):
    raise ValueError(f"{name} is not a number a request may hold")


def parse_request(line: str) -> dict:
    """One JSON request object; numbers must be finite (``1e400``, ``NaN`` are refused)."""
    try:
        request = json.loads(line, parse_float=_finite_float, parse_constant=_no_constant)
    except json.JSONDecodeError as error:
        raise AssistantError(f"not JSON: {error.msg}") from None
    if not isinstance(request, dict):
        raise AssistantError("expected a JSON object")
    return request


def check_command_text(text) -> str:
    """The command text, refused when empty or longer than the parser takes
    (:data:`assistant.grounding.parser.MAX_CHARS`)."""
    from assistant.grounding.parser import MAX_CHARS as MAX_COMMAND_CHARS

    if not isinstance(text, str):
        raise AssistantError(f"the command must be text, got {type(text).__name__}")
    if not text.strip():
        raise AssistantError("the command is empty; say what to fetch, e.g. \"the mug is on the table\"")
    if len(text) > MAX_COMMAND_CHARS:
        raise AssistantError(f"the command has {len(text)} characters, more than {MAX_COMMAND_CHARS}; "
                             "give one command at a time")
    return text


def request_int(request: dict, key: str, default: int, low: int = 0, high: int = 2**31 - 1) -> int:
    """An integer field of a batch request (e.g. ``seed``), in ``[low, high]``."""
    value = request.get(key, default)
    if isinstance(value, float) and value.is_integer():
        value = int(value)
    if isinstance(value, bool) or not isinstance(value, int) or not low <= value <= high:
        raise AssistantError(f"{key}: expected a whole number from {low} to {high}, got {value!r}")
    return value


def _batch_lines(handle):
    """``(number, text or None, problem or None)`` per line of a binary file; a line that is
    not UTF-8 or longer than :data:`MAX_LINE_BYTES` gives a problem instead of text."""
    number = 0
    while True:
        raw = handle.readline(MAX_LINE_BYTES + 1)
        if not raw:
            return
        number += 1
        if len(raw) > MAX_LINE_BYTES and not raw.endswith(b"\n"):
            skipped = len(raw)
            while raw and not raw.endswith(b"\n"):  # skip the rest of the long line
                if skipped > MAX_SKIPPED_BYTES:  # no line end in sight: not a file of requests
                    raise AssistantError(f"line {number} goes on for over {MAX_SKIPPED_BYTES // 2**20} MiB "
                                         "without a line end; give a text file with one request per line")
                raw = handle.readline(MAX_LINE_BYTES)
                skipped += len(raw)
            yield number, None, f"longer than {MAX_LINE_BYTES} bytes; give one request per line"
            continue
        if number == 1 and raw.startswith(b"\xef\xbb\xbf"):
            raw = raw[3:]
        try:
            yield number, raw.decode("utf-8"), None
        except UnicodeDecodeError as error:
            yield number, None, f"not UTF-8 text (byte {raw[error.start]:#04x} at column {error.start + 1}); save the file as UTF-8"


def run_batch(
    path: str,
    handle: Callable[[Any], dict],
    *,
    json_requests: bool,
) -> int:
    """Answer one request per line of ``path`` with one JSON object per line, in order.

    With ``json_requests`` each line is parsed as a JSON object first (finite numbers only).
    A request that fails gives ``{"error": ..., "line": n}`` on its line and the batch goes on
    — whatever went wrong, even a fault of the product (then the error says to report it).
    Blank lines are skipped.
    """
    try:
        if path != "-":
            check_readable_file(path, "file with one request per line", pipes=True)  # <(command) is fine
        handle_file = sys.stdin.buffer if path == "-" else open(path, "rb")
    except OSError as error:
        raise AssistantError(f"cannot read batch file {path}: {error.strerror or error}") from error
    with handle_file:
        for number, line, problem in _batch_lines(handle_file):
            if problem is None:
                line = line.strip()
                if not line:
                    continue
            try:
                if problem is not None:
                    raise AssistantError(problem)
                request = parse_request(line) if json_requests else check_command_text(line)
                answer = handle(request)
            except (AssistantError, ValueError, KeyError, TypeError, OverflowError,
                    argparse.ArgumentTypeError) as error:
                answer = {"error": f"line {number}: {error}", "line": number}
            except (KeyboardInterrupt, BrokenPipeError, MemoryError):
                raise
            except Exception as error:  # a fault of ours must not cost the other lines their answers
                answer = {"error": f"line {number}: internal error ({type(error).__name__}: {error}); "
                                   "please report it with this line", "line": number}
            emit_json(answer)
    return 0


def require_text_or_batch(text: str | None, batch: str | None, what: str) -> None:
    """Refuse both or neither of a TEXT argument and ``--batch FILE``."""
    if text and batch:
        raise AssistantError("give either TEXT or --batch FILE, not both")
    if not text and not batch:
        raise AssistantError(f"nothing to {what}: give the command as TEXT or use --batch FILE")


def parse_pose(text: str) -> tuple[float, float, float]:
    """Parse ``X,Y,HEADING`` (metres, metres, radians) for argparse."""
    parts = [p for p in text.replace(" ", "").split(",") if p]
    if len(parts) != 3:
        raise argparse.ArgumentTypeError(
            f"expected X,Y,HEADING (metres, metres, radians), got {text!r}"
        )
    try:
        x, y, heading = (float(p) for p in parts)
    except ValueError:
        raise argparse.ArgumentTypeError(f"pose values must be numbers, got {text!r}") from None
    if not all(math.isfinite(v) for v in (x, y, heading)):
        raise argparse.ArgumentTypeError(f"pose values must be finite, got {text!r}")
    return x, y, heading


def finite_float(text: str) -> float:
    """A finite number for argparse (``inf`` and ``nan`` are refused)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number, got {text!r}") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"expected a finite number, got {text!r}")
    return value


def whole_number(low: int = 1, high: int = 10**6):
    """An argparse type for a whole number from ``low`` to ``high`` (a count of rounds, trials,
    folds, frames …): ``--limit 0`` or ``--rounds -1`` is refused with the range, not run."""
    def parse(text: str) -> int:
        try:
            value = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected a whole number, got {text!r}") from None
        if not low <= value <= high:
            raise argparse.ArgumentTypeError(f"expected a whole number from {low} to {high}, got {value}")
        return value

    return parse


#: largest seed accepted (numpy's generators take 0 … 2**32 - 1)
MAX_SEED = 2**32 - 1


def seed_int(text: str) -> int:
    """A random seed for argparse: a whole number from 0 to :data:`MAX_SEED`."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"a seed is a whole number, got {text!r}") from None
    if not 0 <= value <= MAX_SEED:
        raise argparse.ArgumentTypeError(f"a seed is from 0 to {MAX_SEED}, got {value}")
    return value


def out_file(suffix: str):
    """An argparse type for a file to write: refuses a folder (``DIR/``) and another suffix."""
    def parse(text: str) -> str:
        if not text.strip() or text.endswith(("/", os.sep)) or os.path.isdir(text):
            raise argparse.ArgumentTypeError(f"{text!r} is a folder; give a file name such as "
                                             f"{os.path.join(text.rstrip('/') or '.', 'out' + suffix)}")
        if not text.lower().endswith(suffix):
            raise argparse.ArgumentTypeError(f"{text!r}: give a file name ending in {suffix}")
        try:
            check_writable_target(text)
        except AssistantError as error:
            raise argparse.ArgumentTypeError(str(error)) from None
        return text

    return parse


#: a value that starts with "-" and is made of numbers and commas (``-1.8,0.75,3.14``)
_NEGATIVE_VALUES = re.compile(r"^-[0-9.][0-9.,eE+\- ]*$")


def join_negative_values(argv: list[str]) -> list[str]:
    """``--pose -1.8,0.75,3.14`` → ``--pose=-1.8,0.75,3.14``: argparse takes a value that starts
    with "-" and is not one plain number for an option; this lets users write it as they would."""
    out: list[str] = []
    for item in argv:
        if (out and out[-1].startswith("--") and "=" not in out[-1] and _NEGATIVE_VALUES.match(item)
                and "," in item):
            out[-1] = f"{out[-1]}={item}"
        else:
            out.append(item)
    return out


def miss_probability(text: str) -> float:
    """Parse a probability in [0, 1) for argparse (a detector's miss rate)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a probability from 0 to below 1, got {text!r}") from None
    if not 0.0 <= value < 1.0:
        raise argparse.ArgumentTypeError(f"a miss rate must be at least 0 and below 1, got {value}")
    return value


def robot_spec(text: str) -> str:
    """Check a robot spec for argparse (``sim``, ``sim:WORLD[:SCENE]``, ``replay:PATH``,
    ``p3dx:PORT``): an unknown kind is refused with the kinds the factory knows."""
    from assistant.robot import parse_robot_spec

    try:
        return str(parse_robot_spec(text))
    except AssistantError as error:
        raise argparse.ArgumentTypeError(str(error)) from None


def add_robot_option(parser: argparse.ArgumentParser, default: str = "sim", help_: str | None = None) -> None:
    """``--robot SPEC``: any spec :func:`~assistant.robot.make_robot` knows, checked when parsed."""
    from assistant.robot import robot_schemes

    parser.add_argument("--robot", type=robot_spec, default=default, metavar="SPEC",
                        help=help_ or f"which robot acts: {', '.join(robot_schemes())} — sim (default; "
                                      "sim:WORLD[:SCENE] names the home), replay:PATH, p3dx:PORT")


def add_json_flag(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--json", action="store_true", help="print one JSON object on stdout")


def progress_for(args: argparse.Namespace):
    """The progress hook of one command (:class:`assistant.eval.progress.Progress`), by the one
    rule of :func:`assistant.progress.hook_for`: a tqdm bar per stage when stderr is a terminal;
    quiet with ``--json`` (an evaluation's included) or when stderr is not a terminal."""
    from assistant.progress import hook_for, installed_hook

    # the command line's own hook (it closes it when the command ends), else the rule applied here
    return installed_hook() or hook_for(bool(getattr(args, "json", False)))


def percent(value: float | None, digits: int = 1, sign: str = "%") -> str:
    """``value`` (a share, 0–1) as a percentage text; ``-`` for ``None``."""
    return "-" if value is None else f"{100 * value:.{digits}f}{sign}"


def print_table(rows: Iterable[Iterable[Any]], header: Iterable[str], stream=None) -> None:
    """Print a plain-text table with aligned columns."""
    stream = stream or sys.stdout
    header = [str(h) for h in header]
    body = [[_cell(c) for c in row] for row in rows]
    widths = [max(len(h), *(len(r[i]) for r in body)) if body else len(h) for i, h in enumerate(header)]
    stream.write("  ".join(h.ljust(w) for h, w in zip(header, widths)).rstrip() + "\n")
    stream.write("  ".join("-" * w for w in widths) + "\n")
    for row in body:
        stream.write("  ".join(c.ljust(w) for c, w in zip(row, widths)).rstrip() + "\n")


def _cell(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.3f}"
    return str(value)

"""Helpers shared by the command modules: JSON output, batch requests, pose arguments."""

from __future__ import annotations

import argparse
import json
import math
import sys
from collections.abc import Callable, Iterable
from typing import Any

from assistant.errors import AssistantError


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


def run_batch(
    path: str,
    handle: Callable[[Any], dict],
    *,
    json_requests: bool,
) -> int:
    """Answer one request per line of ``path`` with one JSON object per line, in order.

    With ``json_requests`` each line is parsed as a JSON object first. A request that fails
    gives ``{"error": ..., "line": n}`` on its line and the batch goes on. Blank lines are skipped.
    """
    try:
        handle_file = sys.stdin if path == "-" else open(path, encoding="utf-8-sig")
    except OSError as error:
        raise AssistantError(f"cannot read batch file {path}: {error.strerror}") from error
    with handle_file:
        for number, raw in enumerate(handle_file, start=1):
            line = raw.strip()
            if not line:
                continue
            try:
                request = json.loads(line) if json_requests else line
                if json_requests and not isinstance(request, dict):
                    raise AssistantError("expected a JSON object")
                emit_json(handle(request))
            except json.JSONDecodeError as error:
                emit_json({"error": f"line {number}: not JSON: {error.msg}", "line": number})
            except (AssistantError, ValueError, KeyError, TypeError, argparse.ArgumentTypeError) as error:
                emit_json({"error": f"line {number}: {error}", "line": number})
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


def add_robot_option(parser: argparse.ArgumentParser, default: str = "sim") -> None:
    from assistant.robot import robot_schemes

    parser.add_argument("--robot", type=robot_spec, default=default, metavar="SPEC",
                        help=f"which robot acts: {', '.join(robot_schemes())} — sim (default; "
                             "sim:WORLD[:SCENE] names the home), replay:PATH, p3dx:PORT")


def add_json_flag(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--json", action="store_true", help="print one JSON object on stdout")


def stderr_progress(what: str, done: int | None = None, total: int | None = None) -> None:
    """A progress hook (:class:`assistant.eval.progress.Progress`) that writes one line per call
    to stderr: ``what``, then ``done/total`` when the stage is counted."""
    count = "" if done is None else f" ({done}/{total})" if total is not None else f" ({done})"
    sys.stderr.write(f"{what}{count}\n")
    sys.stderr.flush()


def quiet_progress(what: str, done: int | None = None, total: int | None = None) -> None:
    """A progress hook that says nothing (``--json`` runs)."""


def progress_for(args: argparse.Namespace):
    """The progress hook of one command: quiet with ``--json`` (its stdout is read by programs
    and its stderr often shown beside it), one line per step on stderr otherwise."""
    return quiet_progress if getattr(args, "json", False) else stderr_progress


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

"""Regenerate ``sample_scans/``: small sessions recorded by the product itself in the simulator.

Each session is one ``assistant record`` command (listed in :data:`SESSIONS` and in
``sample_scans/README.md``); the simulator's fixed seed and ``SOURCE_DATE_EPOCH`` make every
file the same byte for byte on every run.

    .venv/bin/python tools/make_sample_scans.py            # all sessions
    .venv/bin/python tools/make_sample_scans.py apartment_fetch.mcap
"""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from assistant.cli import main  # noqa: E402

OUT = ROOT / "sample_scans"
#: the recordings' start time, fixed (2025-12-01 00:00 UTC) so a regenerated file is identical
EPOCH = "1764547200"
FETCH = "go into the living room, the laptop is on the dinner table"
HK_FETCH = "go into the office, the mug is on the table in front of the couch"

#: file name → the arguments of ``assistant record`` after ``--robot``
SESSIONS: dict[str, list[str]] = {
    "apartment_fetch.mcap": ["sim:apartment", "--fetch", FETCH],
    "hk-studio_fetch.mcap": ["sim:hk-studio", "--fetch", HK_FETCH],
    **{f"{home}_look_around.mcap": [f"sim:{home}", "--step-deg", "45"]
       for home in ("apartment", "hk-studio", "one-bedroom-house", "two-bedrooms-house", "training-home")},
}


def make(name: str) -> int:
    spec, *options = SESSIONS[name]
    return main(["record", "--robot", spec, *options, "--overwrite", "--json", str(OUT / name)])


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("names", nargs="*", metavar="NAME", help=f"sessions to make (default: all): {', '.join(SESSIONS)}")
    args = parser.parse_args()
    unknown = sorted(set(args.names) - set(SESSIONS))
    if unknown:
        parser.error(f"unknown session(s) {', '.join(unknown)}; known: {', '.join(SESSIONS)}")
    os.environ["SOURCE_DATE_EPOCH"] = EPOCH
    OUT.mkdir(exist_ok=True)
    sys.exit(max([make(name) for name in args.names or SESSIONS] or [0]))

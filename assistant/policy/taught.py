"""The demonstrations a user teaches: kept in the user's data folder, checked, listable, removable.

The repository's ``corpus/demonstrations/`` is the shipped corpus; it is never written by
``assistant teach``. A person's demonstrations go to ``DATA/demonstrations/<rdt>/`` (DATA:
:func:`assistant.fileio.user_data_dir`), files readable by their owner only, named
``<world>-<scene>-keyboard-NN.json`` with the next free NN chosen under the folder's lock, so
several ``teach`` runs at once each keep their own file.

Before a demonstration is used it is compared with the others of its RDT (shipped and taught):
where the robot ends relative to the place it was taught about (the target, else the reference,
else where it started; in that thing's own frame when it has a front, else only the distance).
One that ends more than :data:`OUTLIER_M` metres (or four times the others' spread, if larger)
from where the others end would move the learned place by metres: it is held back in
``DATA/demonstrations-held/`` and used only once the person confirms it (``assistant teach
--accept NAME``) — or forgets it (``--forget NAME``).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from assistant.errors import AssistantError, UnknownNameError
from assistant.fileio import PRIVATE_FILE_MODE, atomic_write_text, file_lock, private_dir, user_data_dir
from assistant.policy.demonstration import Demonstration, load_demonstrations

#: a demonstration ending further than this from where the others end is held back (metres)
OUTLIER_M = 1.5
#: fewer other demonstrations than this: nothing to compare with, the demonstration is used
MIN_OTHERS = 2
_NAME = re.compile(r"^[A-Za-z0-9_.-]+(/[A-Za-z0-9_.-]+)?$")


def taught_directory() -> Path:
    """``DATA/demonstrations``: the demonstrations the user taught and confirmed."""
    return user_data_dir() / "demonstrations"


def held_directory() -> Path:
    """``DATA/demonstrations-held``: outliers waiting for the person's confirmation."""
    return user_data_dir() / "demonstrations-held"


@dataclass(frozen=True)
class OutlierCheck:
    """How far a demonstration ends from where the others of its RDT end (metres)."""

    distance_m: float | None  # None: too few others to compare with
    others: int
    limit_m: float

    @property
    def outlier(self) -> bool:
        return self.distance_m is not None and self.distance_m > self.limit_m

    def describe(self, rdt: str) -> str:
        if self.distance_m is None:
            return f"no other demonstrations of {rdt} to compare with"
        return (f"it ends {self.distance_m:.1f} m from where the {self.others} other demonstrations "
                f"of {rdt} end (limit {self.limit_m:.1f} m)")


def end_point(demo: Demonstration) -> np.ndarray:
    """Where ``demo`` ends relative to what it was about (see the module docstring): a 2-vector
    in the anchor's frame when it has a front, else ``[distance, 0]``."""
    end = np.array([demo.last_pose.x, demo.last_pose.y])
    ident = demo.target_id or demo.reference_id
    anchor = None
    if ident is not None:
        try:
            anchor = demo.entity(ident)
        except KeyError:
            anchor = None
    if anchor is not None:
        origin = anchor.polygon_array().mean(axis=0)
        heading = anchor.orientation
    else:
        origin = np.array([demo.first_pose.x, demo.first_pose.y])
        heading = demo.first_pose.theta
    offset = end - origin
    if heading is None:
        return np.array([float(np.hypot(*offset)), 0.0])
    c, s = math.cos(-heading), math.sin(-heading)
    return np.array([c * offset[0] - s * offset[1], s * offset[0] + c * offset[1]])


def check_outlier(demo: Demonstration, others: list[Demonstration]) -> OutlierCheck:
    """Compare ``demo``'s end with the ends of ``others`` of the same RDT."""
    same = [d for d in others if d.rdt == demo.rdt]
    if len(same) < MIN_OTHERS:
        return OutlierCheck(None, len(same), OUTLIER_M)
    points = np.array([end_point(d) for d in same])
    centre = np.median(points, axis=0)
    spread = float(np.median(np.linalg.norm(points - centre, axis=1)))
    limit = max(OUTLIER_M, 4.0 * spread)
    return OutlierCheck(float(np.linalg.norm(end_point(demo) - centre)), len(same), limit)


def next_free_path(folder: Path, world: str, scene: str) -> Path:
    """The next demonstration file in ``folder`` whose name is in use neither there nor in the
    same RDT's folder of the other kind (taught or held back), so that one name never means two
    demonstrations (a held one and a confirmed one had both been "…-keyboard-01")."""
    rdt = folder.name
    folders = {folder, taught_directory() / rdt, held_directory() / rdt}
    n = 1
    while any((f / f"{world}-{scene}-keyboard-{n:02d}.json").exists() for f in folders):
        n += 1
    return folder / f"{world}-{scene}-keyboard-{n:02d}.json"


def save_taught(demo: Demonstration, shipped: Path, accept_outlier: bool = False) -> tuple[Path, OutlierCheck]:
    """Save a person's demonstration in the user's folder (held back when it is an outlier and
    ``accept_outlier`` is False); return the path and the check."""
    others = load_demonstrations(shipped, demo.rdt) if shipped.is_dir() else []
    if taught_directory().is_dir():
        others += load_demonstrations(taught_directory(), demo.rdt)
    check = check_outlier(demo, others)
    root = held_directory() if check.outlier and not accept_outlier else taught_directory()
    folder = private_dir(root / demo.rdt)
    with file_lock(folder / ".names"):
        path = next_free_path(folder, demo.world, demo.scene)
        atomic_write_text(path, demo.to_json(), mode=PRIVATE_FILE_MODE)
    return path, check


@dataclass(frozen=True)
class TaughtFile:
    name: str  # "<rdt>/<stem>"
    path: Path
    held: bool


def list_taught() -> list[TaughtFile]:
    """Every demonstration the user taught (confirmed ones first, then held ones), by name."""
    out = []
    for root, held in ((taught_directory(), False), (held_directory(), True)):
        if root.is_dir():
            for path in sorted(root.glob("*/*.json")):
                out.append(TaughtFile(f"{path.parent.name}/{path.stem}", path, held))
    return out


#: the prefix that names the held-back one of two demonstrations of the same name
HELD_PREFIX = "held:"


def find_taught(name: str, held: bool | None = None) -> TaughtFile:
    """The taught demonstration called ``name`` (``RDT/STEM`` or a unique ``STEM``; ``held:``
    before it, or ``held``, picks the one held back when a confirmed one has the same name)."""
    if (name or "").startswith(HELD_PREFIX):
        name, held = name[len(HELD_PREFIX):], True
    if not _NAME.match(name or ""):
        raise AssistantError(f"{name!r} is not a demonstration name; `assistant teach --list` shows them")
    files = list_taught()
    found = [f for f in files if (f.name == name or f.path.stem == name) and (held is None or f.held == held)]
    if len(found) == 1:
        return found[0]
    exact = [f for f in found if f.name == name]
    if len(exact) == 2 and {f.held for f in exact} == {True, False}:
        raise AssistantError(f"{name!r} names one demonstration in use and one held back (saved by an earlier "
                             f"version under the same name): give {name} for the one in use, {HELD_PREFIX}{name} "
                             "for the held one")
    if len(found) > 1:
        raise AssistantError(f"{name!r} names {len(found)} demonstrations ("
                             + ", ".join(f.name for f in found) + "); give RDT/NAME")
    raise UnknownNameError("taught demonstration", name, [f.name for f in files])


def forget_taught(name: str) -> TaughtFile:
    """Delete one taught (or held) demonstration."""
    item = find_taught(name)
    with file_lock(item.path.parent / ".names"):
        item.path.unlink(missing_ok=True)
    return item


def accept_held(name: str) -> Path:
    """Confirm a held-back demonstration: move it among the ones used for training."""
    try:
        item = find_taught(name, held=True)
    except UnknownNameError:
        item = find_taught(name)  # one in use of that name: said so below
    if not item.held:
        raise AssistantError(f"{item.name} is already in use; nothing to accept")
    demo = Demonstration.load(item.path)
    folder = private_dir(taught_directory() / demo.rdt)
    with file_lock(folder / ".names"):
        path = next_free_path(folder, demo.world, demo.scene)
        atomic_write_text(path, demo.to_json(), mode=PRIVATE_FILE_MODE)
    item.path.unlink(missing_ok=True)
    return path

"""Robot behaviour policies learned from demonstrations (dissertation 5.5).

* :class:`Demonstration` — an RDT node, the robot's trajectory and the environment model, as a
  JSON file (:func:`load_demonstrations`, :func:`environment_from_world`).
* :class:`KeyboardSession`, :func:`drive_by_keys` — driving the simulated robot by keys.
* :func:`teacher_goal`, :func:`sample_start` — the scripted teacher's written rules.
* :class:`PolicyModel` — the linear SRV score model (5-12 … 5-16) and the coarse-to-fine
  move-to search (5.5.4); :class:`PolicyLibrary` — every RDT's model, trained and cached.

Names are loaded on first use, so ``assistant eval`` and ``assistant teach`` start fast.
"""

from __future__ import annotations

import importlib

_EXPORTS = {
    "RDT": "rdt", "TABLE_5_1": "rdt", "TABLE_RDTS": "rdt", "parse_rdt": "rdt",
    "Demonstration": "demonstration", "EnvironmentEntity": "demonstration", "Frame": "demonstration",
    "environment_from_world": "demonstration", "environment_grid": "demonstration",
    "load_demonstrations": "demonstration",
    "FreeSpace": "freespace",
    "KEY_COMMANDS": "keyboard", "KeyboardSession": "keyboard", "drive_by_keys": "keyboard",
    "normalise_key": "keyboard",
    "NoInstanceError": "teacher", "TeacherGoal": "teacher", "approach": "teacher",
    "sample_start": "teacher", "teacher_goal": "teacher",
    "MoveToResult": "model", "NotFittedError": "model", "PolicyModel": "model",
    "rotation_memberships": "model", "srv_vectors": "model",
    "ModelChoice": "library", "PolicyLibrary": "library",
}

__all__ = sorted(_EXPORTS)


def __getattr__(name: str):
    module = _EXPORTS.get(name)
    if module is None:
        raise AttributeError(f"module 'assistant.policy' has no attribute {name!r}")
    value = getattr(importlib.import_module(f"assistant.policy.{module}"), name)
    globals()[name] = value
    return value


def __dir__():
    return __all__

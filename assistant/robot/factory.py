"""``make_robot(spec)``: the one place that turns a robot spec into a :class:`Robot`.

Every caller (the command line, the dialogue, the application layer, the evaluations, the
notebooks) builds its robot here, so a new adapter is usable everywhere at once. A spec is
``SCHEME`` or ``SCHEME:ARGUMENT``:

* ``sim`` / ``sim:WORLD`` / ``sim:WORLD:SCENE`` — the built-in simulator (world and scene
  default to the ``world`` and ``scene`` keyword arguments, then to the apartment's original
  scene);
* ``replay:PATH`` — a recorded session played back;
* ``p3dx:PORT`` — a Pioneer P3-DX on a serial port, with its Kinect.

Adapters live in higher layers (the simulator) or in optional sub-packages (hardware), so this
module names them by import path and imports one only when it is asked for: the robot layer
stays free of imports from above it, and a machine without the serial or camera libraries can
still run the simulator. An adapter registers with :func:`register_adapter`.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from dataclasses import dataclass

from assistant.errors import AssistantError, UnknownNameError
from assistant.robot.interface import Robot

__all__ = ["RobotSpec", "make_robot", "parse_robot_spec", "register_adapter", "robot_schemes"]

#: scheme → "module:function"; the function takes (argument, **options) and returns an
#: unconnected Robot. Filled below for the product's own adapters.
_ADAPTERS: dict[str, str] = {}


@dataclass(frozen=True)
class RobotSpec:
    """A parsed robot spec: ``scheme`` ("sim", "replay", "p3dx") and its ``argument`` (or "")."""

    scheme: str
    argument: str = ""

    def __str__(self) -> str:
        return f"{self.scheme}:{self.argument}" if self.argument else self.scheme


def register_adapter(scheme: str, target: str) -> None:
    """Make ``SCHEME:…`` specs build robots with ``target`` ("package.module:function")."""
    if ":" not in target:
        raise ValueError(f"adapter target must be 'module:function', got {target!r}")
    _ADAPTERS[scheme] = target


def robot_schemes() -> list[str]:
    """The schemes :func:`make_robot` accepts, sorted."""
    return sorted(_ADAPTERS)


def parse_robot_spec(spec: str | RobotSpec) -> RobotSpec:
    """``"p3dx:/dev/ttyUSB0"`` → ``RobotSpec("p3dx", "/dev/ttyUSB0")``; unknown schemes list the known."""
    if isinstance(spec, RobotSpec):
        return spec
    text = str(spec).strip()
    if not text:
        raise AssistantError(f"empty robot spec; use one of: {', '.join(_examples())}")
    scheme, _, argument = text.partition(":")
    scheme = scheme.strip().lower()
    if scheme not in _ADAPTERS:
        raise UnknownNameError("robot kind", scheme, _ADAPTERS)
    return RobotSpec(scheme, argument.strip())


def make_robot(spec: str | RobotSpec = "sim", **options) -> Robot:
    """A new, unconnected robot for ``spec`` (see the module docstring).

    ``options`` go to the adapter (the simulator takes ``world``, ``scene``, ``start``,
    ``seed``, ``odometry_noise``…); an option an adapter does not take raises ``TypeError``
    from that adapter. Use the robot in a ``with`` block so it is stopped and closed on every
    way out.
    """
    parsed = parse_robot_spec(spec)
    build = _load(parsed.scheme)
    return build(parsed.argument, **options)


def _load(scheme: str) -> Callable[..., Robot]:
    module_name, _, function = _ADAPTERS[scheme].partition(":")
    try:
        module = importlib.import_module(module_name)
    except ImportError as error:
        raise AssistantError(
            f"the {scheme!r} robot adapter cannot be loaded ({error}); "
            "run `make setup` (or `assistant doctor`) to install what it needs") from error
    return getattr(module, function)


def _examples() -> list[str]:
    return ["sim:apartment", "replay:PATH", "p3dx:/dev/ttyUSB0"]


register_adapter("sim", "assistant.sim.robot:sim_robot_from_spec")
register_adapter("replay", "assistant.robot.replay:replay_robot_from_spec")
register_adapter("p3dx", "assistant.robot.p3dx:p3dx_robot_from_spec")

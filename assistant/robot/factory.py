"""``make_robot(spec)``: the one place that turns a robot spec into a :class:`Robot`.

Every caller (the command line, the dialogue, the application layer, the evaluations, the
notebooks) builds its robot here, so a new adapter is usable everywhere at once. A spec is
``SCHEME`` or ``SCHEME:ARGUMENT``:

* ``sim`` / ``sim:WORLD`` / ``sim:WORLD:SCENE`` — the built-in simulator (world and scene
  default to the ``world`` and ``scene`` keyword arguments, then to the apartment's original
  scene);
* ``replay:PATH`` — a recorded session played back;
* ``p3dx:PORT`` — a Pioneer P3-DX on a serial port, with its Kinect.

A use case runs in a home and passes every robot the same **home options** (:data:`HOME_OPTIONS`:
``world``, ``scene``, ``start``, ``seed``, ``noise``); each adapter declares which of them it takes
when it registers (the simulator all, a real P3-DX ``world`` and ``start`` — its odometry starts
where the home's plan says it stands —, a recording none: it brings its own home), and
:func:`make_robot` passes it only those. Other options are the adapter's own and go to it as given.

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

__all__ = ["HOME_OPTIONS", "RobotSpec", "make_robot", "parse_robot_spec", "register_adapter", "robot_schemes"]

#: options a use case gives any robot: the home it runs in, the scene, where the robot starts,
#: the random seed and whether odometry is noisy (see the module docstring)
HOME_OPTIONS = frozenset({"world", "scene", "start", "seed", "noise"})

#: scheme → "module:function"; the function takes (argument, **options) and returns an
#: unconnected Robot. Filled below for the product's own adapters.
_ADAPTERS: dict[str, str] = {}
#: scheme → the home options its adapter takes
_TAKES: dict[str, frozenset[str]] = {}


@dataclass(frozen=True)
class RobotSpec:
    """A parsed robot spec: ``scheme`` ("sim", "replay", "p3dx") and its ``argument`` (or "")."""

    scheme: str
    argument: str = ""

    def __str__(self) -> str:
        return f"{self.scheme}:{self.argument}" if self.argument else self.scheme


def register_adapter(scheme: str, target: str, takes=()) -> None:
    """Make ``SCHEME:…`` specs build robots with ``target`` ("package.module:function"), which is
    given the :data:`HOME_OPTIONS` named in ``takes`` (and every option that is not one)."""
    if ":" not in target:
        raise ValueError(f"adapter target must be 'module:function', got {target!r}")
    if unknown := set(takes) - HOME_OPTIONS:
        raise ValueError(f"not home options: {sorted(unknown)}; the home options are {sorted(HOME_OPTIONS)}")
    _ADAPTERS[scheme] = target
    _TAKES[scheme] = frozenset(takes)


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

    ``options``: the :data:`HOME_OPTIONS` (each adapter gets those it takes; the others are
    dropped, so a use case passes the same ones to any robot) and the adapter's own (the
    simulator's ``odometry_noise``, a P3-DX's ``params``…; one an adapter does not take raises
    ``TypeError`` from that adapter). Use the robot in a ``with`` block so it is stopped and
    closed on every way out.
    """
    parsed = parse_robot_spec(spec)
    build = _load(parsed.scheme)
    takes = _TAKES[parsed.scheme]
    given = {k: v for k, v in options.items() if k not in HOME_OPTIONS or k in takes}
    return build(parsed.argument, **given)


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


register_adapter("sim", "assistant.sim.robot:sim_robot_from_spec", takes=HOME_OPTIONS)
register_adapter("replay", "assistant.robot.replay:replay_robot_from_spec")  # a recording has its own home
register_adapter("p3dx", "assistant.robot.p3dx:p3dx_robot_from_spec", takes=("world", "start"))

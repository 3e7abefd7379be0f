"""The teaching use case: a person drives the robot by keys and a demonstration of an RDT node
is recorded (dissertation 5.5.2), with any robot the factory knows."""

from __future__ import annotations

from assistant.app.result import Result, Status
from assistant.app.robots import DEFAULT_ROBOT, open_robot

__all__ = ["teach"]


def teach(rdt: str, world: str, scene: str = "original", *, robot: str = DEFAULT_ROBOT, start=None,
          reference: str | None = None, target: str | None = None, out=None, stdin=None,
          interactive: bool | None = None, echo=None, accept_outlier: bool = False) -> Result:
    """Record a demonstration of ``rdt`` in ``world`` (a name or world file)/``scene`` driven from ``start`` (x, y,
    heading; default the world's start) by keys (see
    :func:`~assistant.policy.teaching.run_teaching`). A ``teach`` :class:`Result`: ``success``
    with the demonstration saved to ``out`` (default the user's data folder; one that ends far
    from the others of its RDT is held back unless ``accept_outlier``), or ``stopped`` when the
    person aborted; ``data`` are the ``assistant teach --json`` fields, ``task`` the session's
    outcome."""
    from assistant.geometry import Pose2D
    from assistant.policy.teaching import run_teaching
    from assistant.world import load_world

    w = load_world(world)
    scene = w.scene(scene).name
    start_pose = Pose2D(*start) if start is not None else w.start
    bot = open_robot(robot, w, scene, noise=False, start=start_pose)
    outcome = run_teaching(rdt, world, scene, start, reference, target, out, stdin, interactive, echo,
                           accept_outlier=accept_outlier, robot=bot)
    if outcome.saved is None:
        return Result("teach", Status.STOPPED, f"aborted after {outcome.presses} key presses; nothing saved",
                      outcome.to_dict(), task=outcome)
    held = " (held back until accepted)" if getattr(outcome, "held", False) else ""
    return Result("teach", Status.SUCCESS, f"saved {outcome.saved}{held}", outcome.to_dict(), task=outcome)

"""``assistant teach``: a person drives the simulated robot by keys and a demonstration is
recorded (dissertation 5.5.2).

In a terminal the session is a full-screen ``curses`` view (arrow keys or w/a/s/d, x or space
to stop, q to finish and save, Esc to abort). When standard input is not a terminal, keys are
read one per line (``w``, ``up``, ``forward``, ``a 4`` for four presses, ``q``, ``esc``), so a
script or a pipe can drive it; the end of input finishes and saves like ``q``.
"""

from __future__ import annotations

import math
import re
import sys
from dataclasses import dataclass
from pathlib import Path


from assistant.errors import AssistantError
from assistant.fileio import check_writable_target, text_lines
from assistant.geometry import Pose2D, angle_difference
from assistant.policy.demonstration import Demonstration, environment_from_world
from assistant.policy.freespace import FreeSpace
from assistant.policy.keyboard import KEY_COMMANDS, KeyboardSession, normalise_key
from assistant.policy.rdt import RDT
from assistant.policy.taught import OutlierCheck, save_taught
from assistant.policy.teacher import NoInstanceError, teacher_goal

#: the most presses one line may ask for (``w 40``); more is refused, not run for hours
MAX_KEY_REPEAT = 200
HELP = "keys: w/↑ forward  s/↓ back  a/← left  d/→ right  x/space stop  q finish+save  Esc abort"


@dataclass
class TeachOutcome:
    saved: Path | None
    demonstration: Demonstration | None
    presses: int
    ignored: list[str]
    check: OutlierCheck | None = None
    held: bool = False  # saved, but held back until the person confirms it

    def to_dict(self) -> dict:
        d = self.demonstration
        return {"saved": None if self.saved is None else str(self.saved), "presses": self.presses,
                "held": self.held, "name": None if self.saved is None else f"{self.saved.parent.name}/{self.saved.stem}",
                "check": None if self.check is None or d is None else self.check.describe(d.rdt),
                "ignored": self.ignored, "rdt": d.rdt if d else None,
                "frames": len(d.frames) if d else 0,
                "final_pose": None if d is None else [round(d.last_pose.x, 3), round(d.last_pose.y, 3),
                                                      round(d.last_pose.theta, 4)],
                "reference_id": d.reference_id if d else None, "target_id": d.target_id if d else None}


class Teaching:
    """One teaching session: the world, the robot, the RDT's reference and target.

    ``robot``: an unconnected robot to drive (default: the simulator in ``world``/``scene`` at
    ``start``, made by :func:`~assistant.robot.make_robot`); the session connects and closes it.
    """

    def __init__(self, rdt: str, world: str, scene: str = "original", start=None,
                 reference: str | None = None, target: str | None = None, seed: int = 0, robot=None):
        from assistant.robot import make_robot
        from assistant.world import load_world

        self.rdt = RDT.parse(rdt)
        self.world = load_world(world)
        self.scene = self.world.scene(scene).name
        self.environment = environment_from_world(self.world, self.scene)
        ids = {e.id for e in self.environment}
        for role, ident in (("reference", reference), ("target", target)):
            if ident is not None and ident not in ids:
                from assistant.errors import UnknownNameError

                raise UnknownNameError(f"{role} (furniture, room:NAME or wall:I:ROOM)", ident, sorted(ids))
        start_pose = Pose2D(*start) if start is not None else self.world.start
        self.robot = robot if robot is not None else make_robot("sim", world=self.world, scene=self.scene,
                                                                start=start_pose, seed=seed)
        self.robot.connect()
        self.session = KeyboardSession(self.robot)
        self.reference_id, self.target_id = reference, target
        self.suggested: Pose2D | None = None
        if (reference is None and self.rdt.has_reference_entity) or (target is None and self.rdt.has_target):
            try:
                goal = teacher_goal(self.rdt, self.environment, start_pose, FreeSpace(self.environment))
            except NoInstanceError as error:
                raise AssistantError(f"cannot tell which {self.rdt.reference}/{self.rdt.target} "
                                     f"{self.rdt.name} means here ({error}); give --reference and --target") from error
            self.reference_id = reference or goal.reference_id
            self.target_id = target or goal.target_id
        self.presses = 0
        self.ignored: list[str] = []
        self.accept_outlier = False  # save an outlier among the used demonstrations at once

    # ---------------------------------------------------------------- what the teacher sees
    def status_lines(self) -> list[str]:
        p = self.session.pose
        lines = [f"teaching {self.rdt.name} in {self.world.name} ({self.scene})",
                 f"reference: {self.reference_id or '(the robot)'}   target: {self.target_id or '(none)'}",
                 f"pose x={p.x:.2f} m  y={p.y:.2f} m  heading={math.degrees(p.theta):.0f}°   "
                 f"t={self.session.frames[-1].t:.1f} s   presses={self.presses}"
                 + ("   BUMPED" if self.robot.bumped else ""),
                 "near:"]
        for dist, word, item in self.nearby():
            lines.append(f"  {item.id:18s} {dist:4.1f} m {word}")
        lines.append(HELP)
        return lines

    def nearby(self, count: int = 6):
        p = self.session.pose
        out = []
        for item in self.environment:
            if item.kind != "short_term":
                continue
            c = item.polygon_array().mean(axis=0)
            dist = math.hypot(c[0] - p.x, c[1] - p.y)
            rel = math.degrees(angle_difference(math.atan2(c[1] - p.y, c[0] - p.x), p.theta))
            word = ("ahead" if abs(rel) <= 45 else "behind" if abs(rel) >= 135
                    else "on the left" if rel > 0 else "on the right")
            out.append((dist, word, item))
        out.sort(key=lambda t: t[0])
        return out[:count]

    # ---------------------------------------------------------------- keys
    def press(self, key: str, times: int = 1) -> None:
        self.session.press(key, times)
        self.presses += times

    def finish(self, out: str | Path | None, teacher: str = "keyboard") -> TeachOutcome:
        """Save the demonstration: to ``out`` when given, else among the user's taught ones
        (:func:`assistant.policy.taught.save_taught`; an outlier is held back)."""
        from assistant.policy.library import DEFAULT_DIRECTORY

        self.session.settle(0.5)
        demo = self.session.demonstration(self.rdt.name, self.world.name, self.scene, self.environment,
                                          self.reference_id, self.target_id, None, teacher)
        self.robot.close()
        if out:
            return TeachOutcome(demo.save(out), demo, self.presses, self.ignored)
        path, check = save_taught(demo, DEFAULT_DIRECTORY, self.accept_outlier)
        return TeachOutcome(path, demo, self.presses, self.ignored, check,
                            held=check.outlier and not self.accept_outlier)

    def abort(self) -> TeachOutcome:
        self.robot.close()
        return TeachOutcome(None, None, self.presses, self.ignored)

    def run_lines(self, lines, out=None, echo=None) -> TeachOutcome:
        """Keys one per line (``w``, ``up``, ``a 3``…); ``q`` ("done") or the end saves, ``esc``
        ("cancel", "never mind") aborts; a demonstration in which the robot was not driven is not
        saved."""
        for number, raw in enumerate(lines, 1):
            text = raw.strip()
            if not text or text.startswith("#"):
                continue
            word, _, count = text.partition(" ")
            key = normalise_key(word)
            try:
                times = int(count) if count.strip() else 1
            except ValueError:
                times = -1
            if key is None and len(text.split()) > 1 and re.match(r"(never ?mind|stop teaching|forget it|cancel)\b",
                                                                  text.lower()):
                key, times = "esc", 1  # "never mind", "cancel that": the teaching stops, nothing saved
            if key is None or times < 1:
                self.ignored.append(text)
                if echo:
                    echo(f"line {number}: {text!r} is not a key — you are teaching me a place now; {HELP} "
                         "(or \"done\" to save, \"cancel\" to stop)")
                continue
            if times > MAX_KEY_REPEAT:
                self.ignored.append(text)
                if echo:
                    echo(f"line {number}: at most {MAX_KEY_REPEAT} presses per line, got {times}; "
                         "give several lines")
                continue
            if key == "q":
                return self.finish(out) if self.presses else self.abort()
            if key == "esc":
                return self.abort()
            self.press(key, times)
        return self.finish(out) if self.presses else self.abort()  # not driven: nothing to save

    def run_curses(self, out=None) -> TeachOutcome:
        import curses

        def loop(screen) -> TeachOutcome:
            curses.curs_set(0)
            screen.keypad(True)
            codes = {curses.KEY_UP: "w", curses.KEY_DOWN: "s", curses.KEY_LEFT: "a", curses.KEY_RIGHT: "d",
                     27: "esc", ord(" "): "x"}
            while True:
                screen.erase()
                for i, line in enumerate(self.status_lines()):
                    try:
                        screen.addstr(i, 0, line[: max(1, curses.COLS - 1)])
                    except curses.error:
                        pass
                screen.refresh()
                ch = screen.getch()
                key = codes.get(ch) or (normalise_key(chr(ch)) if 0 <= ch < 256 else None)
                if key == "q":
                    return self.finish(out)
                if key == "esc":
                    return self.abort()
                if key in KEY_COMMANDS:
                    self.press(key)

        return curses.wrapper(loop)


def check_out_path(out: str | Path | None) -> None:
    """Refuse an ``--out`` that is a folder (``DIR/``), not .json, or in a folder that cannot hold it."""
    if out is None:
        return
    text = str(out)
    if not text.strip() or text.endswith(("/", "\\")) or Path(text).is_dir():
        raise AssistantError(f"--out {text!r} is a folder; give a file name such as {text.rstrip('/') or '.'}/demo.json")
    if Path(text).suffix.lower() != ".json":
        raise AssistantError(f"--out {text!r}: a demonstration is a .json file; give a name ending in .json")
    check_writable_target(text, "demonstration")


def run_teaching(rdt: str, world: str, scene: str = "original", start=None, reference=None, target=None,
                 out=None, stdin=None, interactive: bool | None = None, echo=None,
                 accept_outlier: bool = False, robot=None) -> TeachOutcome:
    """One teaching session driven by keys: a curses view in a terminal, else one key per line
    of ``stdin``. ``robot``: see :class:`Teaching`; ``accept_outlier``: save a demonstration
    that ends far from what was learned before without asking."""
    check_out_path(out)
    stdin = stdin or sys.stdin
    teaching = Teaching(rdt, world, scene, start, reference, target, robot=robot)
    teaching.accept_outlier = accept_outlier
    if interactive is None:
        interactive = stdin.isatty() and sys.stdout.isatty()
    if interactive:
        return teaching.run_curses(out)
    return teaching.run_lines(text_lines(stdin), out, echo)

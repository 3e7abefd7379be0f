"""Driving the simulated robot by keys, as the dissertation's teacher did (5.5.2), and
recording what happened as a :class:`~assistant.policy.demonstration.Demonstration`.

Each key press sets the base's velocity command and lets ``KEY_TICK_S`` of simulated time
pass (a key held down repeats); the base's own acceleration limits smooth the motion, as
they do for a person at a keyboard.

=========  ============  =======================================
key        also          command
=========  ============  =======================================
``w``      up arrow      forward 0.3 m/s
``s``      down arrow    backward 0.15 m/s
``a``      left arrow    turn left 0.7 rad/s
``d``      right arrow   turn right 0.7 rad/s
``x``      space         stop
``q``                    finish and save
Esc                      abort without saving
=========  ============  =======================================
"""

from __future__ import annotations

import math

import numpy as np

from assistant.geometry import Pose2D, angle_difference
from assistant.policy.demonstration import Demonstration, Frame

KEY_TICK_S = 0.25
FORWARD_M_S = 0.3
BACKWARD_M_S = 0.15
TURN_RAD_S = 0.7
KEY_COMMANDS: dict[str, tuple[float, float]] = {
    "w": (FORWARD_M_S, 0.0),
    "s": (-BACKWARD_M_S, 0.0),
    "a": (0.0, TURN_RAD_S),
    "d": (0.0, -TURN_RAD_S),
    "x": (0.0, 0.0),
}
#: other spellings accepted (one per line on a pipe, or what curses reports)
KEY_ALIASES = {"up": "w", "forward": "w", "down": "s", "back": "s", "backward": "s",
               "left": "a", "right": "d", "stop": "x", "space": "x", " ": "x",
               "quit": "q", "finish": "q", "save": "q", "done": "q", "finished": "q",
               "esc": "esc", "escape": "esc", "abort": "esc", "cancel": "esc"}


def normalise_key(text: str) -> str | None:
    """``"w"``, ``"up"``, ``"forward"`` … → one of w, s, a, d, x, q, esc; None if unknown."""
    key = text.strip().lower() if text.strip() else text
    key = KEY_ALIASES.get(key, key)
    return key if key in KEY_COMMANDS or key in ("q", "esc") else None


class KeyboardSession:
    """A simulated robot under keyboard control, recording a frame after every key.

    ``robot`` is a :class:`~assistant.sim.SimRobot`; the recorded pose is its true pose (what
    the teacher sees on the simulator's map)."""

    def __init__(self, robot, tick_s: float = KEY_TICK_S):
        self.robot = robot
        self.tick_s = float(tick_s)
        self.t0 = robot.time_s
        self.frames: list[Frame] = [Frame(0.0, robot.ground_truth_pose, None)]
        self.bumps = 0

    @property
    def pose(self) -> Pose2D:
        return self.robot.ground_truth_pose

    def press(self, key: str, times: int = 1) -> Pose2D:
        """Apply a movement key (w, s, a, d, x) ``times`` times; returns the pose."""
        linear, angular = KEY_COMMANDS[key]
        for _ in range(times):
            self.robot.send_velocity(linear, angular)
            self.robot.advance(self.tick_s)
            if self.robot.bumped:
                self.bumps += 1
            self.frames.append(Frame(self.robot.time_s - self.t0, self.pose, key))
        return self.pose

    def settle(self, seconds: float = 1.5) -> Pose2D:
        """Stop and let the base come to rest (recorded as ``x`` presses)."""
        self.press("x", max(1, int(round(seconds / self.tick_s))))
        return self.pose

    def demonstration(self, rdt: str, world: str, scene: str, environment, reference_id, target_id,
                      goal: Pose2D | None, teacher: str) -> Demonstration:
        return Demonstration(rdt, world, scene, reference_id, target_id, tuple(self.frames),
                             tuple(environment), goal, teacher)


def drive_by_keys(session: KeyboardSession, waypoints, goal_heading: float | None,
                  position_tolerance_m: float = 0.08, heading_tolerance_rad: float = 0.08,
                  max_presses: int = 4000) -> bool:
    """The scripted teacher's hands: press keys to pass ``waypoints`` ((N, 2) metres) and end
    facing ``goal_heading``. Turn keys while the heading is off by more than 0.2 rad (0.3 on
    long legs), forward otherwise; near a waypoint, stop and tap. Returns whether the last
    waypoint and heading were reached."""
    pts = np.asarray(waypoints, dtype=float).reshape(-1, 2)
    presses = 0
    for i, wp in enumerate(pts):
        last = i == len(pts) - 1
        tol = position_tolerance_m if last else 0.2
        while presses < max_presses:
            p = session.pose
            dx, dy = wp[0] - p.x, wp[1] - p.y
            dist = math.hypot(dx, dy)
            if dist <= tol:
                break
            err = angle_difference(math.atan2(dy, dx), p.theta)
            linear = session.robot.odometry().linear_m_s
            if abs(err) > (0.2 if dist < 1.0 else 0.3):
                if abs(linear) > 0.05:
                    session.press("x")
                else:
                    session.press("a" if err > 0 else "d")
            elif last and dist < 0.05 + linear * linear / (2 * 0.3):
                # close: let it roll to a stop, then tap forward
                session.press("x")
            else:
                session.press("w")
            presses += 1
            if session.robot.bumped:
                session.press("s", 2)
                session.settle(0.5)
                presses += 3
        session.settle(0.75) if last else None
    if goal_heading is not None:
        while presses < max_presses:
            err = angle_difference(goal_heading, session.pose.theta)
            if abs(err) <= heading_tolerance_rad:
                break
            if abs(session.robot.odometry().angular_rad_s) > 0.3 and abs(err) < 0.4:
                session.press("x")
            else:
                session.press("a" if err > 0 else "d")
            presses += 1
    session.settle(1.0)
    p = session.pose
    ok = math.hypot(pts[-1][0] - p.x, pts[-1][1] - p.y) <= 2.5 * position_tolerance_m
    if goal_heading is not None:
        ok = ok and abs(angle_difference(goal_heading, p.theta)) <= 2 * heading_tolerance_rad
    return ok

"""How far a place is from the robot, along the floor: "how far is the bedroom?", "is the couch
far?", "which is closer, the bed or the couch?".

The distance is the length of the robot's own route (:func:`~assistant.executor.planning.plan_path`)
over the floor plan it is told — walls, doors, openings — not through walls; furniture is not
in that map (the robot knows the rooms, not where the furniture stands), so the figure is what a
person would walk, give or take going round a table. It is said the way people say it: "about
4 metres", never "3.87 m".
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

#: "how far …" and "which is closer …" questions (normalised text); ``what`` is the place asked
#: about ("the bedroom", "my mug", "it"), or, for a comparison, "the couch or the bed"
HOW_FAR = (
    r"^(?:(?:and|so|ok|okay|um|uh|then|but) )*how far (?:is it|would it be|do (?:i|you|we) have to (?:go|walk|drive)|"
    r"(?:will|would) (?:i|you|we) have to (?:go|walk)) (?:to|till|until|from here to) (?:get to )?(?P<what>.+?)"
    r"(?: from here)?$",
    r"^(?:(?:and|so|ok|okay|um|uh|then|but|roughly|about) )*how far (?:away )?(?:is|are|s|was) (?!you\b)(?P<what>.+?)"
    r"(?: (?:from )?(?:here|me|you|us|where (?:you are|i am|we are))| away| from where i am now)?$",
    r"^(?:(?:and|so|ok|okay|um|uh|then|but) )*how far (?:away )?(?:are you|is the robot) from (?P<what>.+?)(?: now)?$",
    r"^(?:(?:and|so|ok|okay|um|uh|then|but) )*how (?:many (?:metres|meters|steps|feet|yards)|long a walk) (?:is it )?"
    r"(?:to|till|from here to|away is|is) (?P<what>.+?)(?: from here)?$",
    r"^(?:(?:and|so|ok|okay|um|uh|then|but) )*(?:is|are) (?P<what>(?:the|my|our|that|it|they|this) ?[a-z ]*?) "
    r"(?:very |too |a long way |quite )?(?:far|far away|a long way away|a long way|close by|nearby)"
    r"(?: from here| away| from you| from me)?$",
    r"^(?:(?:and|so|ok|okay|um|uh|then|but) )*(?:which|what)(?: one)? (?:is|s) (?P<compare>closer|nearer|nearest|closest|"
    r"further|farther|further away|farther away)(?: to (?:you|me|here|us))?,? (?P<what>.+? or .+?)$",
)
_HOW_FAR = tuple(re.compile(p) for p in HOW_FAR)
#: the words a comparison asks for the nearer of two places with
NEARER = ("closer", "nearer", "nearest", "closest")


@dataclass(frozen=True)
class HowFarQuestion:
    """What a distance question asks: the places (one, or two to compare), whether the nearer
    (``nearer`` True) or the further of two is wanted, and the place measured from."""

    places: tuple[str, ...]
    nearer: bool = True
    origin: str | None = None  # "how far is the couch from the bed?": the bed (None: the robot)


def how_far_question(norm: str) -> HowFarQuestion | None:
    """The place(s) a normalised "how far" question asks about, or None when it is not one."""
    for pattern in _HOW_FAR:
        m = pattern.search(norm)
        if m is None:
            continue
        what = m.group("what").strip()
        if "compare" in pattern.groupindex:
            first, _, second = what.partition(" or ")
            places = tuple(p.strip() for p in (first, second) if p.strip())
            return HowFarQuestion(places, m.group("compare") in NEARER) if len(places) == 2 else None
        place, _, origin = what.partition(" from ")
        if origin and place and not re.fullmatch(r"(?:here|me|you|us|where (?:you are|i am|we are))", origin):
            return HowFarQuestion((place,), origin=origin)
        return HowFarQuestion((what,))
    return None


def floor_distance_m(occupancy, start_xy, goal_xy) -> tuple[float, bool]:
    """(metres the robot would drive from ``start_xy`` to ``goal_xy`` over ``occupancy``, True),
    or (the straight-line metres, False) when its planner finds no way there."""
    from assistant.executor.planning import NoPathError, plan_path

    try:
        path = plan_path(occupancy, start_xy, goal_xy, max_snap_m=2.0)
    except NoPathError:
        return math.dist(start_xy[:2], goal_xy[:2]), False
    return path.length_m + path.snap_distance_m, True


def spoken_distance(metres: float) -> str:
    """A distance as people say it: "less than a metre", "about a metre", "about 4 metres"."""
    if metres < 0.75:
        return "less than a metre"
    if metres < 1.5:
        return "about a metre"
    return f"about {round(metres)} metres"

"""Errands of several steps: "go to the living room, then go to the bedroom".

One plan has one room: the grounders read "go to the office, after that go to the bedroom and stop
at the bed" as a single destination and the robot did only one of the two. A request whose parts
(split at "then", "after that", "afterwards", "and then", a full stop or a semicolon) each send
the robot to a room (named, or the one room with the furniture named), not all to the same room,
is read as that many steps; the chat carries them out in turn (``DialogueManager``). A route told in one
go ("go out the door, turn left, then go into the kitchen") has parts that name no room: it
stays one command, as the grounders read it.
"""

from __future__ import annotations

import re
from collections.abc import Callable

__all__ = ["split_steps", "step_place", "STEP_BREAK"]

#: where one step of an errand ends and the next begins
STEP_BREAK = re.compile(r"\s*,?\s*\b(?:and then|then|after that|afterwards|after this|and after that)\b\s*,?\s*"
                        r"|\s*[.;!]+\s+", re.IGNORECASE)
#: words that number a step, dropped from its text ("First, go to …", "Finally take …", "step 2 …")
STEP_NUMBER = re.compile(r"^(?:first(?:ly)?|second(?:ly)?|third(?:ly)?|next|finally|lastly|last|now|"
                         r"step (?:\d+|one|two|three|four|five)|\d+[.):])[,:]?\s+", re.IGNORECASE)


def split_steps(text: str, room_of: Callable[[str], str | None]) -> list[str]:
    """The steps of a request (see the module), or ``[text]`` when it is one. ``room_of(part)``
    gives the room a part sends the robot to, or None. A part that only names the room ("then
    the bedroom") becomes "go to the bedroom"."""
    parts = [STEP_NUMBER.sub("", p.strip(" ,")) for p in STEP_BREAK.split(text.strip().rstrip(".!"))
             if p and p.strip(" ,")]
    if len(parts) < 2:
        return [text]
    rooms = [room_of(p) for p in parts]
    if any(r is None for r in rooms) or all(a == b for a, b in zip(rooms, rooms[1:])):
        return [text]
    return [f"go {p}" if p.lower().startswith(("to ", "into ", "through ")) else p if _has_verb(p)
            else f"go to the {room}" for p, room in zip(parts, rooms)]


def step_place(step: str) -> str:
    """What a step goes to, as said after "After that, …": "go to the bed" → "the bed"."""
    rest = re.sub(r"^(?:please )?(?:go|come|head|walk|drive|move|get)(?: back| over| on| right| straight)*"
                  r"(?: to| into| in to| towards| toward| through)? ", "", step.strip(), flags=re.IGNORECASE)
    return rest if rest.lower().startswith(("the ", "my ", "your ")) else step


_VERBS = ("go", "come", "head", "walk", "drive", "move", "get", "take", "bring", "find", "look", "check",
          "stop", "wait", "turn", "enter", "visit", "return", "back", "into", "through", "to")


def _has_verb(part: str) -> bool:
    words = part.lower().split()
    return any(w in _VERBS for w in words[:4])


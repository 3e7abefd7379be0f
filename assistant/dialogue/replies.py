"""The dialogue's final replies to a finished task: a fetch or a search ended in an
application-layer :class:`~assistant.app.Result`; these turn it into the robot's sentence,
and keep the object memory in step with what the robot saw."""

from __future__ import annotations

import math
import re
import time
from dataclasses import dataclass

from assistant.app import Status
from assistant.dialogue.memory import TOLD_NOT_SEEN
from assistant.dialogue.services import furniture_phrase
from assistant.dialogue.turns import Turn, join_words
from assistant.grounding.vocabulary import furniture_category
from assistant.grounding.objects import NOT_OBJECTS

__all__ = ["ReplyContext", "SeenFurniture", "fetch_reply", "near", "place_text", "search_reply"]


@dataclass
class ReplyContext:
    """What a reply is composed with: the home (``world``, ``scene``), the object ``memory``
    and the session's ``services`` (describer, search mode)."""

    world: object
    scene: str
    memory: object
    services: object


def search_reply(ctx: ReplyContext, name: str, result, summary: dict, start: float) -> Turn:
    """The final turn of a search (a ``where`` :class:`~assistant.app.Result`): where the object
    is, composed from what the robot perceived, or the honest "I looked in … and did not find
    …" (and memory forgets a place the object was not seen at)."""
    searched = result.task
    rooms = list(getattr(searched, "rooms_searched", []) or [])
    data = {"object": name, "found": result.success, "status": result.status.value,
            "rooms_searched": rooms, "seen": summary["seen"], "source": "search",
            "search_seconds": round(float(getattr(searched, "wall_seconds", 0.0) or 0.0), 2)}
    description = result.message
    if result.success:
        reply = f"Found {it_them(name)}: {description[0].lower() + description[1:]}"
        return Turn(name, "where", reply, "search", "success", data, time.perf_counter() - start)
    if result.status is Status.TIMEOUT:
        where = join_words(["the " + r for r in rooms]) if rooms else "nowhere"
        reply = f"I searched {where} but ran out of time before I found your {name}."
    else:
        reply = description
    related = related_seen(name, summary["seen"])
    entry = ctx.memory.recall(ctx.world.name, related) if related else None
    if entry is not None:  # "glasses" asked, a glasses case seen: say so
        place = " ".join(p for p in (entry.phrase, f"in the {entry.room}" if entry.room else "") if p)
        reply += f" I did see your {related}{' ' + place if place else ''} — is that what you mean?"
        data["related"] = related
    if ctx.memory.recall(ctx.world.name, name) is not None and name not in summary["seen"]:
        ctx.memory.forget(ctx.world.name, name)
    return Turn(name, "where", reply, "search", "failed", data, time.perf_counter() - start)


def related_seen(name: str, seen) -> str | None:
    """A thing among ``seen`` whose name holds the one asked for, or is held in it ("glasses"
    asked, "glasses case" seen; "phone" and "cell phone"), or None."""
    words = name.split()
    for other in seen:
        mine = other.split()
        if other != name and (set(words) <= set(mine) or set(mine) <= set(words)):
            return other
    return None


#: words asking for a thing to be carried to the person ("bring me", "fetch", "get me")
CARRY_WORDS = r"\b(bring|fetch|grab|carry|hand)\b|\bget me\b"


def fetch_reply(ctx: ReplyContext, text: str, result, obj: str | None, start: float, summary: dict | None = None,
                before=None, said: str = "") -> tuple[Turn, dict | None]:
    """The final turn of a fetch (a ``fetch`` :class:`~assistant.app.Result`) and the question
    it leaves pending (None, or an offer to search). ``summary``: what the task saw (memory's
    summary); ``before``: the memory's entry for the object before the fetch; ``said``: the
    person's own words that asked for it (the command when empty), which decide whether "I have
    no arm" is said."""
    pending = None
    obj = obj or result.object
    summary = summary or {"seen": [], "moved": [], "places": {}}
    executor = result.data.get("executor") or {}
    message = executor.get("message", "")
    furniture = executor.get("target_furniture") or {}
    item = next((f for f in ctx.world.scene(ctx.scene).furniture if f.id == furniture.get("id")), None)
    data = {"command": text, "failure": result.failure, "final_pose": result.data.get("final_pose"),
            "target_furniture": furniture or None, "executor_message": message,
            "seen": summary["seen"]}
    if result.failure and result.failure != "not_visible":
        # the executor's message names the plan's node ("node room-center-table: no table seen in
        # the hallway"): the person gets the reason, not the node
        reason = re.sub(r"^node [a-z-]+: ", "", message or result.failure.replace("_", " "))
        reply = f"Sorry, I couldn't do it: {reason}."
        return Turn(text, "command", reply, "fetch", "failed", data, time.perf_counter() - start), pending
    details = getattr(result.task, "details", None) or {}
    if details.get("motion"):  # "turn around": said what it did
        return Turn(text, "command", f"Done — I've {message}.", "fetch", "success", data,
                    time.perf_counter() - start), pending
    if item is not None:
        phrase = furniture_phrase(ctx.services.describer, ctx.world, ctx.scene, item)
        where = f"{phrase} in the {item.room}"
    elif furniture.get("centre") is not None and furniture.get("name"):
        # sensed perception: the detector's own furniture instance, not a world-file item
        centre = furniture["centre"]
        found = ctx.world.floorplan.room_at(float(centre[0]), float(centre[1]))
        room = getattr(found, "name", found)
        item = SeenFurniture(str(furniture.get("id")), str(furniture["name"]), room)
        phrase = f"on the {item.word}"
        where = f"{phrase} in the {room}" if room else phrase
    else:
        phrase, where = None, "here"
    place = summary["places"].get(obj) if obj else None
    if obj and result.object_seen:
        if place is not None:  # described from the robot's own view of the furniture
            where = place_text(place) or where
        else:  # the detector did not report it on the way (a stand-in, or a miss): the target place
            ctx.memory.remember(ctx.world.name, obj, item.room if item else None, item.id if item else None,
                                 item.word if item else None, phrase, source="fetch")
        moved = obj in summary["moved"] or (
            before is not None and place is None and before.furniture != (item.id if item else None))
        carry = (f" I can't carry {it_them(obj)} to you — I have no arm — but I'm right by {it_them(obj)}."
                 if re.search(CARRY_WORDS, (said or text).lower()) else "")  # "take me to it": nothing to carry
        reply = f"Here {'they are' if it_them(obj) == 'them' else 'it is'}: I can see your {obj} {where}." + carry + (
            " It wasn't where I saw it last; I've updated my memory." if moved else "")
        data["remembered"] = True
        return Turn(text, "command", reply, "fetch", "success", data, time.perf_counter() - start), pending
    if obj:
        here = f"I'm at the {item.word if item else 'place you described'}, but I can't see your {obj} there."
        if place is not None:  # seen somewhere else on the way
            reply = f"{here} I did see it {place_text(place)} on my way — I've noted that."
            data["seen_elsewhere"] = place
            return Turn(text, "command", reply, "fetch", "failed", data, time.perf_counter() - start), pending
        if before is not None and near(before, item, furniture):
            ctx.memory.forget(ctx.world.name, obj)
            data["forgot"] = True
            here += " It isn't where I saw it last, so I've forgotten that place."
        elif (before is None or before.told) and item is not None and names_furniture(said or text) \
                and obj.split()[-1] not in NOT_OBJECTS:  # never a word of a place ("the table next to …")
            # "my hearing aid is on the bed": kept as the person said it, with the looking done,
            # so that "where is my hearing aid?" answers with it (a place told before and looked
            # at now too: it had answered "You told me … It's in this room")
            ctx.memory.remember(ctx.world.name, obj, item.room, item.id, item.word, phrase, source=TOLD_NOT_SEEN)
            data["remembered"] = TOLD_NOT_SEEN
        if ctx.services.search_mode == "sensed":
            pending = {"kind": "confirm", "search": obj, "object": obj}
            here += f" Shall I look for {it_them(obj)}?"
        return Turn(text, "command", here, "fetch", "failed", data, time.perf_counter() - start), pending
    if item is not None and item.room and not names_furniture(text):  # "go to the living room": the room
        return Turn(text, "command", f"Done — I'm in the {item.room}.", "fetch", "success", data,
                    time.perf_counter() - start), pending
    if item is not None:
        where = re.sub(r"^(on|at|by) ", "", phrase or f"the {item.word}") + f" in the {item.room}"
    elif details.get("arrived"):  # a room with nothing to face ("go to the hallway")
        return Turn(text, "command", f"I'm here, in the {details['arrived']}.", "fetch", "success", data,
                    time.perf_counter() - start), pending
    on_it = _things_on(summary, item, furniture)
    if on_it:  # "check the coffee table": what lies there
        data["on_it"] = on_it
        seen_there = join_words([f"your {n}" for n in on_it])
        return Turn(text, "command", f"I'm there, facing {where}. On it I can see {seen_there}.", "fetch", "success",
                    data, time.perf_counter() - start), pending
    return Turn(text, "command", f"I'm there, facing {where}.", "fetch", "success", data,
                time.perf_counter() - start), pending


def names_furniture(command: str) -> bool:
    """Whether a command names a piece of furniture (else the robot chose what to face)."""
    return any(furniture_category(w) is not None for w in re.findall(r"[a-z]+", command.lower()))


def place_text(place: dict) -> str | None:
    """"on the table by the chair in the bedroom" from a memory entry's dict."""
    phrase = place.get("phrase") or (f"on the {place['furniture_word']}" if place.get("furniture_word") else None)
    room = place.get("room")
    if phrase and room:
        return f"{phrase} in the {room}"
    return phrase or (f"in the {room}" if room else None)


def near(before, item, furniture: dict, distance_m: float = 1.0) -> bool:
    """Whether a remembered sighting lies on (or by) the furniture the fetch went to."""
    if item is not None and before.furniture == item.id:
        return True
    centre = furniture.get("centre") if furniture else None
    if centre is None and item is not None and hasattr(item, "x"):
        centre = (item.x, item.y)
    if centre is None or before.x_m is None:
        return False
    return ((before.x_m - float(centre[0])) ** 2 + (before.y_m - float(centre[1])) ** 2) ** 0.5 <= distance_m


@dataclass
class SeenFurniture:
    """Furniture the detector reported (id, word, room) when it is not a world-file item."""

    id: str
    word: str
    room: str | None


def it_them(obj: str) -> str:
    """"them" for the keys, "it" for the wallet or the mail (the generation layer's grammar)."""
    from assistant.generation import it_them as pronoun

    return pronoun(obj)


def _things_on(summary: dict, item, furniture: dict) -> list[str]:
    """The things the task saw lying on the piece of furniture it went to (the world's ``item``, or
    the detector's ``furniture`` with its centre): by the piece's id, or within 0.9 m of its centre."""
    centre = (item.x, item.y) if item is not None else tuple((furniture.get("centre") or [None, None])[:2])
    ids = {i for i in ((item.id if item is not None else None), furniture.get("id")) if i is not None}
    out = []
    for name, place in sorted(summary.get("places", {}).items()):
        x, y = place.get("x_m"), place.get("y_m")
        if place.get("furniture") in ids or (x is not None and centre[0] is not None
                                             and math.dist((x, y), centre) < 0.9):
            out.append(name)
    return out

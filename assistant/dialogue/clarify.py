"""Understanding the answer to "which one?" in context, and the robot's progress sentences."""

from __future__ import annotations

import re

from assistant.dialogue.intents import ordinal_choice

#: furniture words the robot can be told an unknown word stands for
FURNITURE_CHOICES = ("table", "chair", "couch", "bed")


def choose_option(norm: str, options: list[dict], parse) -> int | None:
    """Index of the option an answer picks, or None. ``options``: ``{"phrase": "on the table in
    front of the couch", …}`` in the order they were offered; ``parse()`` gives the answer's
    grounded plan (called only when no ordinal was said). Tried in order: an ordinal ("the
    second", "the last one"); the reference of a grounded node ("the one with the chairs" →
    ``chair-beside-table`` → the single option naming a chair; when several do, the direction);
    the single option sharing most content words with the answer."""
    i = ordinal_choice(norm)
    if i is not None and -len(options) <= i < len(options):
        return i % len(options)
    phrases = [o["phrase"].lower() for o in options]
    plan = parse()
    refs = [str(n).split("-")[0] for n in plan.nodes]
    rdts = [str(n) for n in plan.nodes]
    for ref in refs:
        if ref in ("room", "move", "robot"):
            continue
        hits = [k for k, ph in enumerate(phrases) if re.search(rf"\b{ref}s?\b", ph)]
        if len(hits) == 1:
            return hits[0]
        if len(hits) > 1:  # same reference: the direction decides
            for rdt in rdts:
                direction = rdt.split("-")[1] if "-" in rdt else ""
                words = {"front": "in front of", "back": "behind", "left": "left of", "right": "right of",
                         "beside": "by"}.get(direction, direction)
                sub = [k for k in hits if words and words in phrases[k]]
                if len(sub) == 1:
                    return sub[0]
    content = {w for w in norm.split() if w not in _STOP and len(w) > 2}
    scores = [len(content & set(re.findall(r"[a-z]+", ph))) for ph in phrases]
    best = max(scores) if scores else 0
    if best > 0 and scores.count(best) == 1:
        return scores.index(best)
    return None


def progress_sentence(name: str, data: dict, words: dict) -> str | None:
    """What the robot says for one executor event (None: nothing worth saying)."""
    if name == "entered":
        room = data.get("room")
        result = data.get("result")
        ok = getattr(result, "ok", None)
        if ok is None:
            status = getattr(getattr(result, "status", None), "value", "success")
            ok = status == "success"
        return f"I'm in the {room}." if ok else f"I can't get into the {room} — trying another way."
    if name == "node":
        report = data.get("report")
        if report is None:
            return None
        ref = words.get(report.reference or "", None) or (str(report.rdt).split("-")[0] if report.rdt else None)
        if report.status == "success":
            target = words.get(report.target or "", None)
            if ref in FURNITURE_CHOICES:
                return f"I see the {ref}."
            return f"I see the {target}." if target else None
        if ref in FURNITURE_CHOICES:
            return f"I can't find {article(ref)} {ref} here — looking around."
        return "I'm not sure where that is — looking around."
    if name == "better_view":
        return "Moving to the middle of the room for a better look."
    return None


def article(word: str) -> str:
    return "an" if word[:1] in "aeiou" else "a"


_STOP = {"the", "one", "with", "that", "this", "near", "next", "and", "its", "it", "is", "on", "of", "to",
         "by", "in", "at", "a", "an", "table", "tables", "chair", "couch", "bed", "please", "which"}

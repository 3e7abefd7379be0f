"""``assistant eval dialogue``: scripted conversations, each with its expected outcome.

Conversations live in ``corpus/dialogues/*.yaml`` (or ``--corpus PATH``, files or folders)::

    conversations:
      - name: where-from-memory
        world: apartment            # default apartment
        scene: original             # default original
        search: oracle              # optional: how an unseen object is found (default --search)
        memory:                     # sightings the robot starts with (optional; at the furniture's centre)
          - {object: mug, furniture: hexagontable_1, minutes_ago: 3}   # earlier_session: true → "earlier today"
        turns:
          - say: where is my mug
            expect: {intent: where, action: answer, reply_has: ["3 minutes ago", "bedroom"]}
          - say: yes
            expect: {action: fetch, outcome: started}
          - wait: true              # wait for the fetch to end (the simulator runs)
            expect: {outcome: success, memory: {mug: bedroom}}

``expect`` keys: ``intent``, ``action``, ``outcome``, ``reply_has`` / ``reply_lacks`` (substrings,
case-insensitive), ``data`` (key → value the turn's data must hold), ``memory`` (object → room,
or null for forgotten). A conversation *ends as expected* when every turn meets its
expectations, no turn raised inside the manager (intent ``error``) and no wait ran out
(``--timeout``). Fetches run in the simulator with the real parser, policies and executor
(``--perception oracle`` by default, to separate dialogue from perception errors).
"""

from __future__ import annotations

import time
from collections.abc import Callable
from pathlib import Path

from assistant.eval.progress import Progress, no_progress
from assistant.fileio import read_yaml

EXPECT_KEYS = {"intent", "action", "outcome", "reply_has", "reply_lacks", "data", "memory"}
TURN_KEYS = {"say", "wait", "expect", "sleep"}
CONVERSATION_KEYS = {"name", "world", "scene", "memory", "turns", "covers", "search"}


def default_corpus() -> Path:
    return Path(__file__).resolve().parents[2] / "corpus" / "dialogues"


def load_conversations(paths=None) -> list[dict]:
    """Read and check the conversation files; a bad one raises DataFileError naming the key."""
    import yaml

    from assistant.errors import AssistantError, DataFileError

    files: list[Path] = []
    for p in (paths or [default_corpus()]):
        p = Path(p)
        if p.is_dir():
            files.extend(sorted(p.glob("*.yaml")))
        elif p.exists():
            files.append(p)
        else:
            raise AssistantError(f"{p}: no such file or folder")
    out = []
    for f in files:
        try:
            data = read_yaml(f.read_text(encoding="utf-8"))
        except yaml.YAMLError as error:
            raise DataFileError(f, "", f"not valid YAML ({error})") from None
        if not isinstance(data, dict) or not isinstance(data.get("conversations"), list):
            raise DataFileError(f, "conversations", "expected a list of conversations")
        for i, conv in enumerate(data["conversations"]):
            where = f"conversations[{i}]"
            if not isinstance(conv, dict) or not conv.get("name") or not isinstance(conv.get("turns"), list):
                raise DataFileError(f, where, "needs a name and a list of turns")
            extra = set(conv) - CONVERSATION_KEYS
            if extra:
                raise DataFileError(f, f"{where}.{sorted(extra)[0]}", f"unknown key; use {sorted(CONVERSATION_KEYS)}")
            for j, turn in enumerate(conv["turns"]):
                if not isinstance(turn, dict) or not (set(turn) & {"say", "wait", "sleep"}):
                    raise DataFileError(f, f"{where}.turns[{j}]", "needs 'say' or 'wait'")
                extra = (set(turn) - TURN_KEYS) | (set(turn.get("expect") or {}) - EXPECT_KEYS)
                if extra:
                    raise DataFileError(f, f"{where}.turns[{j}].{sorted(extra)[0]}", "unknown key")
            out.append(conv | {"file": f.name})
    return out


def check(turn, expect: dict, memory, world: str) -> list[str]:
    """Problems of one turn against its expectations (empty when it is as expected)."""
    problems = []
    if turn is None:
        return ["no turn (the fetch did not end in time)"]
    if turn.intent == "error":
        problems.append(f"crashed: {turn.reply}")
    for key in ("intent", "action", "outcome"):
        want = expect.get(key)
        if isinstance(want, bool):  # YAML reads a bare yes / no as a boolean
            want = "yes" if want else "no"
        if key in expect and getattr(turn, key) != want:
            problems.append(f"{key} {getattr(turn, key)!r} != {want!r}")
    reply = turn.reply.lower()
    for s in _list(expect.get("reply_has")):
        if str(s).lower() not in reply:
            problems.append(f"reply lacks {s!r}: {turn.reply!r}")
    for s in _list(expect.get("reply_lacks")):
        if str(s).lower() in reply:
            problems.append(f"reply has {s!r}: {turn.reply!r}")
    for k, v in (expect.get("data") or {}).items():
        if turn.data.get(k) != v:
            problems.append(f"data[{k!r}] {turn.data.get(k)!r} != {v!r}")
    for obj, room in (expect.get("memory") or {}).items():
        seen = memory.recall(world, obj)
        got = None if seen is None else seen.room
        if got != room:
            problems.append(f"memory of {obj}: {got!r} != {room!r}")
    return problems


def _list(v) -> list:
    return [] if v is None else v if isinstance(v, list) else [v]


#: called after every turn with (conversation name, what was said or "(wait)", the turn or None)
TurnHook = Callable[[str, str, object], None]


def run_conversation(conv: dict, services, timeout: float = 180.0,
                     on_turn: TurnHook | None = None) -> dict:
    """Play one conversation with a fresh manager and memory; its record (``ok``, problems…).
    ``on_turn`` sees every turn as it ends."""
    import tempfile

    from assistant.dialogue.manager import DialogueManager
    from assistant.dialogue.memory import ObjectMemory
    from assistant.dialogue.services import furniture_phrase
    from assistant.world import load_world

    world = load_world(conv.get("world", "apartment"))
    scene = conv.get("scene", "original")
    with tempfile.TemporaryDirectory() as folder:
        memory = ObjectMemory(Path(folder) / "memory.json")
        now = time.time()
        items = {f.id: f for f in world.scene(scene).furniture}
        for m in conv.get("memory") or []:
            item = items[m["furniture"]]
            seen_s = now - 60.0 * float(m.get("minutes_ago", 1))
            memory.remember(world.name, m["object"], item.room, item.id, item.word,
                            furniture_phrase(services.describer, world, scene, item),
                            time_s=seen_s, source="seeded", x_m=item.x, y_m=item.y)
            if not m.get("earlier_session", False):
                # seen in this conversation's session: the session began before the sighting
                memory.session_start_s = min(memory.session_start_s, seen_s - 1.0)
        manager = DialogueManager(world, scene, services, memory)
        mode = services.search_mode
        services.search_mode = conv.get("search", mode)
        problems, turns, hang, crash = [], [], False, False
        latencies = []
        for j, step in enumerate(conv["turns"]):
            if "sleep" in step:
                time.sleep(float(step["sleep"]))
            if "say" in step:
                said = step["say"]
                if isinstance(said, bool):  # YAML reads a bare yes / no as a boolean
                    said = "yes" if said else "no"
                turn = manager.handle(str(said))
                latencies.append(turn.seconds)
            elif step.get("wait"):
                turn = manager.wait(timeout)
                hang = hang or (turn is None and manager.fetch_started)
            else:
                continue
            crash = crash or (turn is not None and turn.intent == "error")
            found = check(turn, step.get("expect") or {}, memory, world.name)
            problems += [f"turn {j + 1} ({step.get('say', 'wait')!r}): {p}" for p in found]
            turns.append(None if turn is None else turn.to_dict())
            if on_turn is not None:
                on_turn(conv["name"], step.get("say", "(wait)"), turn)
        manager.close(timeout=30.0)
        services.search_mode = mode
    return {"name": conv["name"], "file": conv["file"], "ok": not problems, "problems": problems,
            "crashed": crash, "hung": hang, "turns": turns, "covers": conv.get("covers", []),
            "reply_seconds": latencies}


def evaluate_dialogue(corpus=None, *, perception: str = "oracle", search: str = "sensed",
                      timeout: float = 180.0, only: str | None = None,
                      on_turn: TurnHook | None = None, progress: Progress = no_progress) -> dict:
    """Play every conversation of ``corpus`` (files or folders; default the repository's) whose
    name contains ``only``, with fetches in the simulator (``perception``) and unseen objects
    found by ``search``; a fetch longer than ``timeout`` seconds counts as a hang. Returns the
    JSON report: the summary figures (per topic, failures) and every conversation's record."""
    import statistics

    from assistant.dialogue.services import Services
    from assistant.world import load_world

    conversations = load_conversations(corpus)
    if only:
        conversations = [c for c in conversations if only in c["name"]]
    services = Services(perception=perception, search=search)
    start = time.perf_counter()
    progress("loading the parser, describer and policies")
    services.warm_up(load_world(conversations[0].get("world", "apartment")) if conversations else None,
                     background=False)
    records = []
    for number, conv in enumerate(conversations):
        progress("conversations", number, len(conversations))
        records.append(run_conversation(conv, services, timeout, on_turn))
    n = len(records)
    ok = sum(r["ok"] for r in records)
    latencies = [s for r in records for s in r["reply_seconds"]]
    summary = {
        "conversations": n, "as_expected": ok, "share_as_expected": round(ok / n, 4) if n else None,
        "crashed": sum(r["crashed"] for r in records), "hung": sum(r["hung"] for r in records),
        "median_reply_ms": round(1000 * statistics.median(latencies), 2) if latencies else None,
        "perception": perception, "wall_seconds": round(time.perf_counter() - start, 1),
        "by_topic": by_topic(records),
        "failures": [{"name": r["name"], "file": r["file"], "problems": r["problems"]} for r in records if not r["ok"]],
    }
    return summary | {"records": records}


def by_topic(records: list[dict]) -> dict:
    """topic → conversations covering it and how many of them ended as expected."""
    covers: dict[str, list[int]] = {}
    for r in records:
        for c in r["covers"]:
            covers.setdefault(c, [0, 0])
            covers[c][0] += 1
            covers[c][1] += r["ok"]
    return {k: {"conversations": v[0], "as_expected": v[1]} for k, v in sorted(covers.items())}

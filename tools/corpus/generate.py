"""Generate the product's own annotated spatial-language corpus (``corpus/``).

Run from the repository root::

    .venv/bin/python tools/corpus/generate.py            # writes corpus/descriptions.xml + chunk_groundings.csv
    .venv/bin/python tools/corpus/generate.py --check-csisl ../shared/realdata/csisl

Descriptions are composed from phrase banks (:mod:`phrases`) and the facts of the four study
homes (:mod:`homes`) into families (dynamic / static / mixed × no / goal / path landmark, plus
the shorter and longer kinds real speakers produce: ``partial-route`` / ``partial-furniture`` /
``partial-static`` without an object phrase, and ``twostep-goal``, the room said first as a
sentence of its own — see :func:`compose_any`), then hedges, fillers and disfluencies are
inserted at fixed rates. ``--scale`` multiplies every family count (default :data:`SCALE`). Hand-written descriptions
(``handwritten.txt``) are added as they are. Everything is seeded, so the output is the same
on every run. Each chunk is grounded (target room, target object, reference, direction,
target) by the rules of :mod:`notation` unless the phrase states its grounding explicitly.
"""

from __future__ import annotations

import argparse
import random
import re
import sys
from collections import Counter
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import homes as H  # noqa: E402
import noise  # noqa: E402
import phrases as P  # noqa: E402
from notation import Node, csv_rows, ground_tree, parse, to_xml, write_csv_text  # noqa: E402

REPO = HERE.parents[1]
SEED = 20141014
#: descriptions per (home, object) and family; the apartment (the CSISL house) gets more
FAMILY_COUNTS = {
    "dynamic-none": 4, "dynamic-goal": 5, "dynamic-path": 4,
    "static-none": 3, "static-goal": 5, "static-path": 4,
    "mixed-goal": 4, "mixed-path": 3,
    # kinds "partial" and "twostep": the generation layer does not learn whole descriptions from
    # them (it reads kinds static/mixed); the grounder and the chunker use every chunk
    "partial-route": 2, "partial-furniture": 2, "partial-static": 1, "twostep-goal": 2,
}
WORLD_WEIGHT = {"apartment": 1.5}
#: all counts ×SCALE: 1.5 (≈1600 descriptions) read the real CSISL descriptions 0.45 points
#: better than 1.0 (mean of 3 seeds), 2.5 no better than 1.5; training stays well under 60 s
SCALE = 1.5
#: furniture phrases that notice the furniture ("there's a table", "you'll see a table"): real
#: speakers often say where first, nested in the furniture phrase
NOTICE = ("[FURTP there/EX", "[FURTP you/PRP 'll/MD see/VB")


# ------------------------------------------------------------------ slot expansion

_SLOT = re.compile(r"\{([a-z_]+)(?::([a-z ]+))?\}")


def expand(text: str, rng: random.Random, ctx: dict) -> str:
    """Fill ``{slot}`` / ``{slot:arg}`` placeholders (repeatedly, slots may contain slots)."""
    for _ in range(8):
        m = _SLOT.search(text)
        if not m:
            return text
        name, arg = m.group(1), m.group(2)
        if name in ctx:
            val = ctx[name]
            val = rng.choice(val) if isinstance(val, list) else val
        else:
            bank = P.SLOTS[name]
            val = P.pick(rng, bank)
            if arg:
                val = val.replace("{D}", arg)
        text = text[:m.start()] + val + text[m.end():]
    raise ValueError(f"slot expansion did not finish: {text}")


def a_form(np: str) -> str:
    """``the/DT table/FUR`` → ``a/DT table/FUR`` (an indefinite first mention)."""
    return re.sub(r"^the/DT ", "a/DT ", np)


# ------------------------------------------------------------------ families


def _side(text: str, side: str) -> str:
    return text.replace("{S}", side).replace(":S}", ":" + side + "}")


def route_options(world: str, obj: str, fact: dict) -> list[list[str]]:
    """Outside-room route chunk sequences that lead from the start into the object's room."""
    side = fact["side"]
    out: list[list[str]] = []
    if side in ("left", "right"):
        for r, w in P.SIDE_ROUTES:
            out.extend([[_side(r, side)]] * w)
        out.extend([[r] for r in P.SPECIAL_ROUTES.get((world, fact["room"]), [])] * 2)
    elif side == "ahead":
        out.extend([[r] for r in H.AHEAD_ROUTES[(world, fact["room"])]])
    out.extend(fact.get("routes", []) * (3 if side == "far" else 1))
    return out


def static_room_options(world: str, fact: dict) -> list[str]:
    side = fact["side"]
    if side in ("left", "right"):
        return [_side(r, side) for r, w in P.STATIC_ROOM_SIDE for _ in range(w)]
    return list(P.STATIC_ROOM_NAMED)


def compose(family: str, world: str, obj: str, fact: dict, rng: random.Random) -> list[str]:
    """The top-level segments (chunk strings and O words) of one description."""
    ctx = {"obj": P.OBJECT_NP[obj], "roomnp": H.ROOM_NP[fact["room"]]}
    kind, landmark = family.split("-")
    segs: list[str] = []

    def furn():
        np = rng.choice(fact["furniture"])
        if rng.random() < 0.12 and "/JJ" not in np and np.startswith("the/DT "):
            np = "the/DT " + P.pick(rng, P.FURN_ADJ) + " " + np[len("the/DT "):]
        return np

    def furrp():
        if not fact["furrp"]:
            return ""
        f = rng.choice(fact["furrp"])
        if rng.random() < 0.1:
            f = "[FURRP " + P.pick(rng, P.FURRP_REL) + " " + f[len("[FURRP "):]
        return f

    def where():
        return rng.choice(fact["where"])

    def where_move():
        """A true move towards the object's place: "in the middle of the room" → "go to the middle …"."""
        cands = [w for w in fact["where"] if w.startswith(("[IRMRP in/IN the/DT", "[IRMRP at/IN the/DT"))]
        if not cands:
            return None
        w = rng.choice(cands).split(" ", 3)[3]
        return "[IRMRP " + P.pick(rng, P.SLOTS["go"]) + " " + rng.choice(["to/TO the/DT", "over/IN to/TO the/DT", "all/DT the/DT way/NN to/TO the/DT",
                                                                    "almost/RB all/DT the/DT way/NN to/TO the/DT"]) + " " + w

    if kind in ("dynamic", "mixed"):
        route = rng.choice(route_options(world, obj, fact))
        for i, r in enumerate(route):
            if i:
                segs.append(rng.choice(["and/CC", "and/CC then/RB", "then/RB", ""]))
            segs.append(r)
    if kind == "dynamic":
        moves = list(rng.choice(fact["dynamic"]))
        if rng.random() < 0.15:
            moves.insert(0, P.pick(rng, P.STEP_MOVES))
        if rng.random() < 0.22:
            moves.insert(0, P.pick(rng, P.ENTER_MOVES))
        if rng.random() < 0.25:
            wm = where_move()
            if wm:
                moves = [wm] if rng.random() < 0.5 else moves[:1] + [wm]
        if landmark == "path" and fact["path"] and rng.random() < 0.6:
            moves.insert(rng.randrange(len(moves) + 1), rng.choice(fact["path"]))
        for m in moves:
            segs.append(rng.choice(["and/CC", "and/CC", "", "and/CC then/RB", "then/RB"]))
            segs.append(m)
        segs.append(rng.choice(["and/CC", "and/CC", ""]))
        if landmark == "none":
            segs.append(P.pick(rng, P.OBTP_END_NONE).replace("{where}", where()))
        elif landmark == "goal" and rng.random() < 0.75:   # "[FURTP go to the table] and [OBTP it's on it]"
            f = P.pick(rng, P.FURTP_GOAL_FIRST).replace("{furn}", furn()).replace("{furna}", a_form(furn()))
            if f.startswith(NOTICE) and rng.random() < 0.5:   # "[FURTP [IRMRP on the left wall] there's a table]"
                f = "[FURTP " + where() + " " + f[len("[FURTP "):]
            elif rng.random() < 0.45:
                f = f[:-1] + " " + where() + "]"
            elif rng.random() < 0.15:
                f = f[:-1] + " " + P.pick(rng, P.OBRP) + "]"
            if rng.random() < 0.08:      # the object said inside the furniture phrase
                segs.append(f[:-1] + " " + P.pick(rng, P.OBTP_IN_FURTP) + "]")
            else:
                segs.append(f)
                segs.append(rng.choice(["and/CC", "and/CC", ""]))
                segs.append(P.pick(rng, P.OBTP_AFTER_FURTP))
        elif landmark == "goal" and rng.random() < 0.2:
            segs.append(P.pick(rng, P.OBTP_FURN_FIRST).replace("{furn}", furn()))
        elif landmark == "goal":
            inner = f"[FURTP on/ON {furn()} {rng.choice(['', '', where()])}]"
            if rng.random() < 0.3:
                inner = f"[FURTP on/ON top/NN of/IN {furn()}]"
            segs.append(P.pick(rng, P.OBTP_END_FURN).replace("{furtp}", inner))
        else:  # path: the furniture is a landmark on the way, then the object
            if fact["furrp"] and rng.random() < 0.7:
                f = P.pick(rng, P.FURTP_PATH).replace("{furn}", furn()).replace("{furna}", a_form(furn()))
                if f.startswith(NOTICE) and rng.random() < 0.4:   # "[FURTP [FURRP behind the couch] there's a table]"
                    f = "[FURTP {furrp} " + f[len("[FURTP "):].replace(" {furrp}", "")
                f = f.replace("{furrp}", furrp())
                segs[-1:] = [rng.choice(["and/CC", ""]), f, "and/CC"]
                segs.append(P.pick(rng, P.OBTP_AFTER_FURTP))
            else:
                w = where() if rng.random() < 0.4 else ""
                inner = f"[FURTP on/ON {furn()} {w} {furrp()}]"
                segs.append(P.pick(rng, P.OBTP_END_FURN).replace("{furtp}", inner))
    elif kind == "static":
        room = rng.choice(static_room_options(world, fact))
        opener = P.pick(rng, P.OBTP_STATIC_OPEN)
        parts = [room]
        if landmark == "none":
            parts.append(where())
            second = where()
            if rng.random() < 0.25 and second != parts[-1]:
                parts.append(second)
        elif landmark == "goal":
            if rng.random() < 0.25:
                parts.append(where())
            w = where() if rng.random() < 0.45 else ""
            parts.append(f"[FURTP {P.pick(rng, P.ON_FURN).replace('{furn}', furn())} {w}]")
        elif rng.random() < 0.2 and fact["furrp"]:      # "[OBTP the statue is … [FURRP next to the bed] [FURTP on the nightstand]]"
            parts.append(furrp())
            parts.append(f"[FURTP {P.pick(rng, P.ON_FURN).replace('{furn}', furn())}]")
        else:
            w = where() if rng.random() < 0.5 else ""
            parts.append(f"[FURTP {P.pick(rng, P.ON_FURN).replace('{furn}', furn())} {w} {furrp()}]")
        if rng.random() < 0.12 and len(parts) > 1:   # room last: "on the table ... in the bedroom"
            parts = parts[1:] + parts[:1]
        elif rng.random() < 0.08 and len(parts) > 1 and parts[-1].startswith("[FURTP"):
            parts = parts[1:-1] + [parts[-1][:-1] + " " + parts[0] + "]"]   # "[FURTP on the table [ORMTP in the bedroom]]"
        if rng.random() < 0.15 and len(parts) > 1 and parts[-1].startswith("[FURTP"):
            segs.append(f"[OBTP {opener} {' '.join(parts[:-1])}]")    # furniture said after the object
            segs.append(rng.choice(["", "", "and/CC", "uh/IGN"]))
            segs.append(parts[-1])
        elif rng.random() < 0.15 and len(parts) > 1:      # "... is in the bedroom and on the table"
            segs.append(f"[OBTP {opener} {parts[0]} and/CC {' '.join(parts[1:])}]")
        else:
            segs.append(f"[OBTP {opener} {' '.join(parts)}]")
    elif kind == "mixed":
        segs.append(rng.choice(["and/CC", "and/CC", ""]))
        if landmark == "goal":
            inner = f"[FURTP {P.pick(rng, P.ON_FURN).replace('{furn}', furn())}]"
            if rng.random() < 0.5:
                inner = inner[:-1] + " " + where() + "]"
            segs.append(P.pick(rng, P.OBTP_MIXED).replace("{furtp}", inner))
        else:
            inner = f"[FURTP {P.pick(rng, P.ON_FURN).replace('{furn}', furn())} {furrp()}]"
            if rng.random() < 0.6 and fact["furrp"]:
                f = P.pick(rng, P.FURTP_LOOK).replace("{furn}", furn()).replace("{furna}", a_form(furn()))
                segs[-1:] = ["and/CC", f.replace("{furrp}", furrp()), rng.choice(["and/CC", ""])]
                segs.append(P.pick(rng, P.OBTP_AFTER_FURTP))
            else:
                segs.append(P.pick(rng, P.OBTP_MIXED).replace("{furtp}", inner))
    if rng.random() < 0.14:      # a small thing the speaker notices beside the target
        i = max((k for k, sg in enumerate(segs) if sg.startswith("[OBTP")), default=None)
        if i is not None:
            sg = segs[i]
            if sg.endswith("]]") and "[FURTP" in sg and rng.random() < 0.5:
                segs[i] = sg[:-2] + " " + P.pick(rng, P.OBRP) + "]]"      # inside the FURTP
            else:
                segs[i] = sg[:-1] + " " + P.pick(rng, P.OBRP) + "]"
    return [expand(s, rng, ctx) for s in segs if s]


def compose_any(family: str, world: str, obj: str, fact: dict, rng: random.Random) -> list[str] | None:
    """:func:`compose` plus the shorter and longer kinds real speakers produce:

    ``partial-route``      the route only, no object (the speaker stops after the moves)
    ``partial-furniture``  the route and the furniture, no object phrase
    ``partial-static``     room and furniture phrases without the object sentence
    ``twostep-goal``       "[OBTP the mug is in the room on the left] [moves] [OBTP it's on the table]"
    and, now and then, a closing second object sentence ("… [OBTP pick it up]").
    """
    kind, landmark = family.split("-")
    if kind == "partial":
        if landmark == "static":
            segs = compose("static-goal", world, obj, fact, rng)
            inner = [s for s in segs if s.startswith("[OBTP")]
            if not inner:
                return None
            # drop the opener: "[OBTP the mug is [ORMTP …] [FURTP …]]" → "[ORMTP …] [FURTP …]"
            tree = parse(inner[0])
            ob = tree.children()[0]
            kids = [c for c in ob.items if isinstance(c, Node)]
            if not kids:
                return None
            parts = [c.bracketed() for c in kids]
            if rng.random() < 0.3 and parts[0].startswith("[ORMTP in/IN "):   # "in [ORMTP the room …]"
                parts[0] = "in/IN [ORMTP " + parts[0][len("[ORMTP in/IN "):]
            return parts
        base = "dynamic-goal" if landmark == "furniture" else rng.choice(["dynamic-none", "dynamic-goal", "mixed-goal"])
        for _ in range(6):
            segs = compose(base, world, obj, fact, rng)
            cut = next((i for i, s in enumerate(segs) if s.startswith("[OBTP")), len(segs))
            segs = segs[:cut]
            while segs and not segs[-1].startswith("["):
                segs.pop()
            if landmark == "furniture" and not (segs and segs[-1].startswith("[FURTP")):
                continue
            if landmark == "route":
                while segs and segs[-1].startswith("[FURTP"):
                    segs.pop()
                    while segs and not segs[-1].startswith("["):
                        segs.pop()
            if segs:
                return segs
        return None
    if kind == "twostep":
        if fact["side"] not in ("left", "right"):
            return None
        room = rng.choice(static_room_options(world, fact))
        segs = [P.pick(rng, P.OBTP_ROOM_FIRST).replace("{room}", room)]
        moves = list(rng.choice(fact["dynamic"]))
        if rng.random() < 0.3:
            moves.insert(0, P.pick(rng, P.ENTER_MOVES))
        for m in moves[: rng.choice([0, 1, 1, 2, 3])]:
            segs.append(rng.choice(["and/CC", "", "then/RB", "and/CC then/RB"]))
            segs.append(m)
        furn = rng.choice(fact["furniture"])
        furtp = f"[FURTP on/ON {furn}]" if rng.random() < 0.7 else f"[FURTP on/ON {furn} {rng.choice(fact['where'])}]"
        if rng.random() < 0.25 and fact["furrp"]:
            f = P.pick(rng, P.FURTP_PATH).replace("{furn}", furn).replace("{furna}", a_form(furn))
            segs += [rng.choice(["and/CC", ""]), f.replace("{furrp}", rng.choice(fact["furrp"]))]
            furtp = "[FURTP on/ON that/DT table/FUR]" if "table" in furn else "[FURTP on/ON it/PRP]"
        segs.append(rng.choice(["and/CC", "and/CC", ""]))
        segs.append(P.pick(rng, P.OBTP_SECOND).replace("{furtp}", furtp))
        return [expand(s, rng, {"obj": P.OBJECT_NP[obj], "roomnp": H.ROOM_NP[fact["room"]]}) for s in segs if s]
    segs = compose(family, world, obj, fact, rng)
    if kind == "dynamic" and rng.random() < 0.06:      # "[OBTP look down] and [OBTP you'll see the mug]"
        i = max((k for k, sg in enumerate(segs) if sg.startswith("[OBTP")), default=None)
        if i is not None and "[FURTP" not in segs[i]:
            segs[i:i] = [P.pick(rng, P.OBTP_LOOK), "and/CC"]
    if rng.random() < 0.05:
        segs += [rng.choice(["and/CC", "", "and/CC then/RB"]),
                 expand(P.pick(rng, P.OBTP_CLOSING), rng, {"obj": P.OBJECT_NP[obj]})]
    return [s for s in segs if s]


# ------------------------------------------------------------------ assembling the corpus


def build(rng: random.Random, scale: float = SCALE) -> list[dict]:
    """All descriptions as dicts: tree (Node), attrs, ctx (``scale`` × the family counts)."""
    out: list[dict] = []
    seen: set[str] = set()

    def add(tree: Node, attrs: dict, ctx: dict) -> bool:
        key = tree.text().lower()
        if key in seen:
            return False
        seen.add(key)
        ground_tree(tree, ctx)
        out.append({"tree": tree, "attrs": attrs, "ctx": ctx})
        return True

    for world, home in H.HOMES.items():
        for obj, fact in home["objects"].items():
            ctx = {"room": fact["room"], "object": obj}
            for family, n in FAMILY_COUNTS.items():
                kind, landmark = family.split("-")
                if landmark == "path" and not (fact["furrp"] or fact["path"]):
                    continue
                want = round(scale * n * WORLD_WEIGHT.get(world, 1.0))
                made = tries = 0
                while made < want and tries < 60:
                    tries += 1
                    segs = compose_any(family, world, obj, fact, rng)
                    if segs is None:
                        continue
                    segs = noise.top_level(segs, rng, kind)
                    tree = parse(" ".join(segs))
                    noise.in_tree(tree, rng)
                    attrs = {"id": "", "world": world, "object": obj, "room": fact["room"],
                             "family": family, "kind": kind, "landmark": landmark}
                    if add(tree, attrs, ctx):
                        made += 1
    for hw in read_handwritten(HERE / "handwritten.txt") + read_handwritten(HERE / "spoken.txt"):
        add(hw["tree"], hw["attrs"], hw["ctx"])
    for i, d in enumerate(out, 1):
        d["attrs"]["id"] = f"d{i:04d}"
    return out


def read_handwritten(path: Path) -> list[dict]:
    """Hand-written descriptions: ``world | object | kind-landmark | notation`` per line, or
    ``world | object @ room | kind-landmark | notation`` for an object the home facts do not
    place (``keys @ bedroom``)."""
    out = []
    for lineno, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        line = line.strip()
        if not line or line.startswith("#"):
            continue
        try:
            world, obj, family, text = (p.strip() for p in line.split("|", 3))
        except ValueError:
            raise SystemExit(f"{path}:{lineno}: need 'world | object | family | notation'")
        if "@" in obj:
            obj, room = (p.strip() for p in obj.split("@", 1))
        else:
            room = H.HOMES[world]["objects"][obj]["room"]
        tree = parse(text)
        kind, landmark = family.split("-")
        out.append({"tree": tree, "ctx": {"room": room, "object": obj},
                    "attrs": {"id": "", "world": world, "object": obj, "room": room,
                              "family": family, "kind": kind, "landmark": landmark,
                              "source": "handwritten"}})
    return out


def write(descs: list[dict], out_dir: Path) -> None:
    out_dir.mkdir(parents=True, exist_ok=True)
    xml = ["<ALL>"]
    rows: list[list[str]] = []
    for i, d in enumerate(descs, 1):
        xml.append(to_xml(d["tree"], d["attrs"]))
        rows.extend(csv_rows(i, d["tree"]))
    xml.append("</ALL>")
    _atomic(out_dir / "descriptions.xml", "\n".join(xml) + "\n")
    _atomic(out_dir / "chunk_groundings.csv", write_csv_text(rows))


def _atomic(path: Path, text: str) -> None:
    tmp = path.with_suffix(path.suffix + ".tmp")
    tmp.write_text(text, encoding="utf-8")
    tmp.replace(path)


def csisl_sentences(csisl_dir: Path) -> set[str]:
    """Lower-cased word strings of the CSISL descriptions (for the no-copy check)."""
    import xml.etree.ElementTree as ET
    out = set()
    for name in ("csisl_templates149_annotated.xml", "csisl_real_descriptions_annotated.xml"):
        p = csisl_dir / name
        if not p.exists():
            continue
        raw = p.read_bytes().decode("utf-8-sig")
        raw = re.sub(r"<\?xml[^>]*\?>", "", raw)
        for s in ET.fromstring(raw).iter("S"):
            words = [(e.text or "").strip().lower() for e in s.iter() if len(e) == 0 and e is not s]
            out.add(" ".join(w for w in words if w))
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=REPO / "corpus")
    ap.add_argument("--seed", type=int, default=SEED)
    ap.add_argument("--scale", type=float, default=SCALE,
                    help=f"multiply every family count (default {SCALE}; the committed corpus uses it)")
    ap.add_argument("--check-csisl", type=Path, default=None,
                    help="directory of the CSISL files: report (and drop) exact copies")
    args = ap.parse_args(argv)
    rng = random.Random(args.seed)
    descs = build(rng, args.scale)
    if args.check_csisl:
        real = csisl_sentences(args.check_csisl)
        copies = [d for d in descs if d["tree"].text().lower() in real]
        print(f"exact matches with CSISL descriptions: {len(copies)}")
        for d in copies:
            print("   dropped:", d["tree"].text())
        descs = [d for d in descs if d["tree"].text().lower() not in real]
        for i, d in enumerate(descs, 1):
            d["attrs"]["id"] = f"d{i:04d}"
    write(descs, args.out)
    words = sum(len(d["tree"].words()) for d in descs)
    chunks = sum(1 for d in descs for _ in d["tree"].walk())
    print(f"{len(descs)} descriptions, {words} words, {chunks} chunks -> {args.out}")
    for key in ("family", "kind", "landmark", "world", "object"):
        counts = Counter(d["attrs"][key] for d in descs)
        print(f"  by {key}: " + ", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    print(f"  hand-written: {sum(1 for d in descs if d['attrs'].get('source') == 'handwritten')}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())

"""Hedges, fillers, disfluencies and perspective phrases, inserted at fixed rates.

Rates follow what speakers in the study homes would plausibly say (the CSISL recordings show
fillers in roughly a quarter of the descriptions, hedges and self-corrections in a few percent);
the words and their annotation follow the CSISL conventions: fillers are ``IGN`` and stay outside
chunks between phrases, the addressee is ``WHO``, a self-correction or an uncertain aside is a
``CONF`` chunk nested where it was said, a viewpoint clause ("as you walk in", "from the door")
is a ``PERS`` chunk.
"""

from __future__ import annotations

import random
import re

from notation import Node, Word, parse

START_FILLERS = [("um/IGN", 5), ("uh/IGN", 5), ("okay/IGN", 3), ("ok/IGN", 2), ("alright/IGN", 2),
                 ("so/IN", 2), ("robot/WHO", 4), ("okay/IGN robot/WHO", 2), ("um/IGN robot/WHO", 1),
                 ("well/RB", 1), ("okay/IGN so/IN", 1), ("uh/IGN okay/IGN", 1), ("please/IGN", 1),
                 ("robot/WHO please/IGN", 1), ("hey/IGN robot/WHO", 1), ("robot/WHO um/IGN", 1),
                 ("uh/IGN robot/WHO", 1), ("okay/IGN so/IN robot/WHO", 1), ("um/IGN so/IN", 1), ("oh/IGN", 1),
                 ("ah/IGN okay/IGN", 1), ("umm/IGN", 1), ("uhh/IGN", 1),
                 # a robot with a name: the addressee is WHO wherever it is said
                 ("brian/WHO", 6), ("ok/IGN brian/WHO", 2), ("uh/IGN brian/WHO", 2), ("um/IGN brian/WHO", 1),
                 ("alright/IGN brian/WHO", 1), ("okay/IGN so/IN brian/WHO", 1), ("brian/WHO please/IGN", 1)]
IMPERATIVE_LEADS = [("you/PRP need/VBP to/TO", 3), ("you/PRP want/VBP to/TO", 2), ("it/PRP needs/VBZ to/TO", 1),
                    ("he/PRP needs/VBZ to/TO", 1), ("i/PRP need/VBP you/PRP to/TO", 2), ("you/PRP 're/VBP gon/VBR na/VBR", 1),
                    ("you/PRP should/MD", 1), ("you/PRP have/VBP to/TO", 1), ("i/PRP want/VBP you/PRP to/TO", 1),
                    ("first/RB", 1), ("just/RB", 2), ("so/IN first/RB", 1), ("he/PRP should/MD", 1),
                    ("he/PRP 's/VBZ gon/VBR na/VBR", 1), ("tell/VB him/PRP to/TO", 1), ("i/PRP 'd/MD like/VB you/PRP to/TO", 1),
                    ("can/MD you/PRP", 1), ("could/MD you/PRP please/IGN", 1),
                    ("brian/WHO needs/VBZ to/TO", 2), ("brian/WHO should/MD", 1), ("brian/WHO you/PRP need/VBP to/TO", 1),
                    ("he/PRP needs/VBZ to/TO", 1), ("you/PRP wan/VBR na/VBR", 1), ("the/DT robot/WHO should/MD", 1)]
HEDGES = [("i/PRP think/VBP", 5), ("i/PRP believe/VBP", 3), ("i/PRP guess/VBP", 1),
          ("if/IN i/PRP remember/VBP", 1), ("i/PRP 'm/VBP pretty/RB sure/JJ", 1),
          ("i/PRP 'm/VBP not/RB sure/JJ but/CC", 1)]
MID_FILLERS = [("uh/IGN", 5), ("um/IGN", 5), ("umm/IGN", 1), ("uhh/IGN", 1), ("okay/IGN", 1), ("and/CC uh/IGN", 2)]
END_WORDS = [("please/IGN", 3), ("okay/IGN", 1), ("i/PRP think/VBP", 2), ("i/PRP believe/VBP", 1)]
PERS_TOP = [("[PERS from/IN the/DT door/STR]", 3), ("[PERS as/IN you/PRP walk/VB in/IN]", 3),
            ("[PERS when/WRB you/PRP walk/VB in/IN]", 2), ("[PERS once/WRB you/PRP 're/VBP inside/IN]", 1),
            ("[PERS looking/VBG in/IN from/IN the/DT doorway/STR]", 1),
            ("[PERS if/IN you/PRP 're/VBP standing/VBG at/IN the/DT door/STR]", 1),
            ("[PERS from/IN where/WRB you/PRP are/VBP]", 1), ("[PERS as/IN you/PRP come/VBP in/IN]", 1),
            ("[PERS from/IN where/WRB i/PRP am/VBP standing/VBG]", 1)]
PERS_NESTED = [("[PERS as/IN you/PRP walk/VB in/IN]", 3), ("[PERS from/IN the/DT door/STR]", 2),
               ("[PERS when/WRB you/PRP come/VBP in/IN]", 2), ("[PERS as/IN you/PRP enter/VB]", 1),
               ("[PERS when/WRB you/PRP 're/VBP facing/VBG the/DT room/RM]", 1),
               ("[PERS from/IN my/PRP side/NN]", 1)]
CONF_ASIDES = [("[CONF i/PRP think/VBP]", 5), ("[CONF i/PRP believe/VBP]", 3), ("[CONF i/PRP guess/VBP]", 1),
               ("[CONF um/IGN]", 2), ("[CONF uh/IGN]", 2), ("[CONF i/PRP 'm/VBP not/RB sure/JJ]", 1),
               ("[CONF if/IN i/PRP remember/VBP correctly/RB]", 1)]
CORRECTIONS = [("no/DT", 3), ("sorry/IGN", 2), ("no/DT sorry/IGN", 2), ("i/PRP mean/VBP", 2), ("uh/IGN no/DT", 1),
               ("or/CC", 1), ("wait/VB", 1)]


def _pick(rng, bank):
    texts, weights = zip(*bank)
    return rng.choices(texts, weights=weights, k=1)[0]


def top_level(segs: list[str], rng: random.Random, kind: str) -> list[str]:
    """Fillers and hedges between the top-level segments of a description."""
    segs = list(segs)
    if rng.random() < 0.025:
        obtp = next((i for i, s in enumerate(segs) if s.startswith("[OBTP")), None)
        if obtp is not None:
            segs.insert(obtp, _pick(rng, PERS_TOP))
    if rng.random() < 0.14 and len(segs) > 1:
        segs.insert(rng.randrange(1, len(segs)), _pick(rng, MID_FILLERS))
    if rng.random() < 0.13 and re.match(r"^(\[ORMTP )*[a-z]+/VB ", segs[0]):
        segs.insert(0, _pick(rng, IMPERATIVE_LEADS))
    r = rng.random()
    if r < 0.03:
        segs.insert(0, _pick(rng, HEDGES))
    elif r < 0.05:
        segs.insert(0, "[CONF " + _pick(rng, HEDGES) + "]")
    if rng.random() < 0.40:
        segs.insert(0, _pick(rng, START_FILLERS))
    if rng.random() < 0.05:
        segs.append(_pick(rng, END_WORDS))
    return segs


def _chunks(node: Node):
    for c in node.children():
        yield c
        yield from _chunks(c)


def in_tree(root: Node, rng: random.Random) -> None:
    """Disfluencies inside chunks: a filler after a determiner, a repeated word, a corrected
    direction, an uncertain aside, a nested viewpoint clause."""
    chunks = list(_chunks(root))
    if not chunks:
        return
    if rng.random() < 0.06:                       # "the uh table", "the uh the table"
        c = rng.choice(chunks)
        idx = [i for i, it in enumerate(c.items) if isinstance(it, Word) and it.tag == "DT"]
        if idx:
            i = rng.choice(idx)
            add = [Word(rng.choice(["uh", "um", "uh"]), "IGN")]
            if rng.random() < 0.4:
                add.append(Word(c.items[i].text, "DT"))
            c.items[i + 1:i + 1] = add
    if rng.random() < 0.04:                       # "to the the left", "you you"
        c = rng.choice(chunks)
        idx = [i for i, it in enumerate(c.items) if isinstance(it, Word) and it.tag in ("DT", "PRP", "TO", "IN")]
        if idx:
            i = rng.choice(idx)
            c.items.insert(i, Word(c.items[i].text, c.items[i].tag))
    if rng.random() < 0.04:                       # "turn [CONF left no] right"
        cands = [(c, i) for c in chunks if c.label in ("ORMRP", "IRMRP")
                 for i, it in enumerate(c.items) if isinstance(it, Word) and it.tag == "DIR"]
        if cands:
            c, i = rng.choice(cands)
            wrong = "left" if c.items[i].text == "right" else "right"
            conf = parse(f"[CONF {wrong}/DIR {_pick(rng, CORRECTIONS)}]").items[0]
            c.items.insert(i, conf)
    if rng.random() < 0.04:                       # "[ORMRP on your left [CONF i think]]"
        cands = [c for c in chunks if c.label in ("ORMRP", "IRMRP", "FURTP", "FURRP")]
        if cands:
            c = rng.choice(cands)
            c.items.append(parse(_pick(rng, CONF_ASIDES)).items[0])
    if rng.random() < 0.06:                       # "[IRMRP on the right wall [IRMRP once you've entered the room]]"
        cands = [c for c in chunks if c.label == "IRMRP" and c.own_words() and c.own_words()[0].tag in ("ON", "IN", "TO", "RB")
                 and not c.children()]
        if cands:
            from phrases import IRMRP_NESTED, pick
            rng.choice(cands).items.append(parse(pick(rng, IRMRP_NESTED)).items[0])
    if rng.random() < 0.07:                       # "[IRMRP on the left [PERS as you walk in]]"
        cands = [c for c in chunks if c.label == "IRMRP" and any(
            isinstance(it, Word) and it.tag == "DIR" for it in c.items) and not any(
            isinstance(it, Word) and it.text in ("turn", "take", "make") for it in c.items)]
        if cands:
            rng.choice(cands).items.append(parse(_pick(rng, PERS_NESTED)).items[0])

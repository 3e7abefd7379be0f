"""Phrase banks of the corpus generator, in the bracket notation of :mod:`notation`.

Written for this project from the annotation conventions of the CSISL corpus (which tag each
kind of word gets, where chunk boundaries fall) — not copied from it. A bank is a list of
strings or ``(string, weight)`` pairs. ``{slot}`` placeholders are filled by
:func:`generate.expand`: ``{go}`` a motion verb, ``{fwd}`` an adverb of straight motion,
``{turn:D}`` a turn towards direction D, ``{onside:D}`` "on the D"-style phrase, ``{obj}`` the
target object's noun phrase, ``{roomnp}`` the target room's noun phrase.
"""

from __future__ import annotations

import random


def pick(rng: random.Random, bank):
    """One entry of a bank (weighted when entries are ``(text, weight)`` pairs)."""
    if bank and isinstance(bank[0], tuple):
        texts, weights = zip(*bank)
        return rng.choices(texts, weights=weights, k=1)[0]
    return rng.choice(bank)


SLOTS = {
    "go": [("go/VB", 8), ("walk/VB", 4), ("move/VB", 2), ("head/VB", 1), ("come/VB", 1), ("continue/VB", 1)],
    "fwd": [("forward/RB", 7), ("straight/RB", 6), ("straight/RB down/RB the/DT hall/NN", 1), ("ahead/RB", 1),
            ("straight/RB forward/RB", 1), ("forward/RB a/DT little/RB", 1)],
    "turn": [("turn/VB {D}/DIR", 8), ("take/VB a/DT {D}/DIR", 4), ("make/VB a/DT {D}/DIR", 2),
             ("turn/VB to/TO the/DT {D}/DIR", 2), ("turn/VB to/TO your/PRP {D}/DIR", 2),
             ("hang/VB a/DT {D}/DIR", 1), ("take/VB a/DT {D}/DIR turn/NN", 1), ("go/VB {D}/DIR", 1),
             ("turn/VB to/TO his/PRP {D}/DIR", 1), ("make/VB a/DT {D}/DIR turn/NN", 1), ("turn/VB slightly/RB {D}/DIR", 1)],
    "onside": [("on/ON the/DT {D}/DIR", 5), ("on/ON your/PRP {D}/DIR", 4), ("to/TO the/DT {D}/DIR", 4),
               ("to/TO your/PRP {D}/DIR", 3), ("on/ON the/DT {D}/DIR side/NN", 1),
               ("on/ON your/PRP {D}/DIR hand/NN side/NN", 1), ("on/ON his/PRP {D}/DIR", 1), ("to/TO his/PRP {D}/DIR", 1)],
}

#: one-step routes into a room whose door is on side {S} of the start (weights)
SIDE_ROUTES = [
    ("[ORMTP {go} {fwd} and/CC [ORMRP {turn:S}]]", 12),
    ("[ORMTP {go} {fwd} and/CC then/RB [ORMRP {turn:S}]]", 3),
    ("[ORMTP [ORMRP {turn:S}]]", 3),
    ("[ORMTP {turn:S}]", 1),
    ("[ORMTP {turn:S} through/IN the/DT door/STR]", 1),
    ("[ORMTP {go} into/IN the/DT room/RM [ORMRP {onside:S}]]", 4),
    ("[ORMTP {go} into/IN {roomnp} [ORMRP {onside:S}]]", 2),
    ("[ORMTP enter/VB the/DT room/RM [ORMRP {onside:S}]]", 2),
    ("[ORMTP enter/VB {roomnp} [ORMRP {onside:S}]]", 1),
    ("[ORMTP {go} {fwd} and/CC [ORMRP {turn:S}] into/IN the/DT room/RM]", 2),
    ("[ORMTP {go} {fwd} and/CC [ORMRP {turn:S} into/IN] {roomnp}]", 2),
    ("[ORMTP {go} through/IN the/DT door/STR [ORMRP {onside:S}]]", 2),
    ("[ORMTP {go} through/IN the/DT entryway/STR [ORMRP {onside:S}]]", 1),
    ("[ORMTP {go} into/IN the/DT entrance/STR [ORMRP {onside:S}]]", 1),
    ("[ORMTP [ORMRP {turn:S}] through/IN the/DT door/STR]", 2),
    ("[ORMTP go/VB down/RB the/DT hallway/NN and/CC [ORMRP {turn:S} into/IN] {roomnp}]", 1),
    ("[ORMTP {go} to/TO the/DT room/RM [ORMRP {onside:S}]]", 1),
    ("{go} to/TO [ORMTP {roomnp} [ORMRP {onside:S}]]", 1),
    ("[ORMTP come/VB into/IN the/DT room/RM [ORMRP {onside:S}]]", 1),
    ("{go} {fwd} and/CC [ORMTP [ORMRP {turn:S}]]", 1),
    ("{go} {fwd} [ORMTP [ORMRP {turn:S} into/IN] the/DT room/RM]", 1),
    ("{go} {fwd} and/CC then/RB [ORMTP [ORMRP {turn:S}]]", 1),
    ("{go} {fwd} and/CC go/VB into/IN [ORMTP the/DT room/RM [ORMRP {onside:S}]]", 2),
    ("{go} to/TO [ORMTP the/DT room/RM [ORMRP {onside:S}]]", 2),
    ("{go} into/IN [ORMTP the/DT room/RM [ORMRP {onside:S}]]", 1),
    ("{go} {fwd} and/CC [ORMTP enter/VB the/DT room/RM [ORMRP {onside:S}]]", 1),
    ("[ORMTP [ORMRP {turn:S} into/IN] {roomnp}]", 1),
    ("{go} {fwd} until/IN you/PRP [ORMTP [ORMRP reach/VBP the/DT door/STR on/ON the/DT {S}/DIR]]", 1),
    ("[ORMTP {go} {fwd} [ORMRP {turn:S}]]", 1),
    ("[ORMTP {go} {fwd} and/CC [ORMRP go/VB into/IN the/DT room/RM {onside:S}]]", 1),
    ("[ORMTP {go} {fwd} a/DT few/JJ steps/NNS and/CC [ORMRP {turn:S}]]", 1),
    ("[ORMTP {go} {fwd} about/IN three/CD steps/NNS and/CC [ORMRP {turn:S}]]", 1),
    ("[ORMTP [ORMRP {turn:S} into/IN] the/DT room/RM]", 1),
    ("[ORMTP [ORMRP {turn:S} into/IN] the/DT first/JJ room/RM]", 1),
    ("[ORMTP [ORMRP {turn:S}] and/CC go/VB into/IN the/DT room/RM]", 1),
    ("[ORMTP {go} {fwd} until/IN you/PRP reach/VBP the/DT door/STR [ORMRP {onside:S}]]", 1),
    ("[ORMTP {go} into/IN the/DT {S}/DIR room/RM]", 1),
    ("[ORMTP go/VB through/IN the/DT {S}/DIR door/STR]", 1),
    ("[ORMTP {go} down/RB the/DT hall/NN and/CC [ORMRP {turn:S}]]", 1),
    ("[ORMTP {go} down/RB the/DT hallway/NN a/DT bit/NN and/CC [ORMRP {turn:S}]]", 1),
]

#: routes that only fit one home
SPECIAL_ROUTES = {
    ("one-bedroom-house", "office"): [
        "[ORMTP [ORMRP take/VB an/DT immediate/JJ left/DIR]]",
        "[ORMTP go/VB into/IN the/DT first/JJ door/STR [ORMRP on/ON your/PRP left/DIR]]",
        "[ORMTP [ORMRP turn/VB left/DIR] right/RB away/RB into/IN the/DT office/RM]",
    ],
    ("one-bedroom-house", "living room"): [
        "[ORMTP [ORMRP turn/VB right/DIR into/IN] the/DT open/JJ living/NN room/RM]",
        "[ORMTP step/VB into/IN the/DT living/NN room/RM [ORMRP on/ON your/PRP right/DIR]]",
    ],
    ("hk-studio", "office"): [
        "[ORMTP {go} {fwd} and/CC [ORMRP take/VB the/DT door/STR on/ON the/DT right/DIR]]",
        "[ORMTP {go} up/RP the/DT hallway/NN to/TO the/DT door/STR [ORMRP on/ON your/PRP right/DIR]]",
    ],
    ("hk-studio", "meeting room"): [
        "[ORMTP [ORMRP turn/VB left/DIR into/IN] the/DT open/JJ area/NN]",
        "[ORMTP step/VB into/IN the/DT meeting/NN room/RM [ORMRP on/ON your/PRP left/DIR]]",
    ],
}

#: where-descriptions: the room, when its door is on side {S} of the start
STATIC_ROOM_SIDE = [
    ("[ORMTP in/IN the/DT room/RM [ORMRP {onside:S}]]", 6),
    ("[ORMTP in/IN {roomnp} [ORMRP {onside:S}]]", 5),
    ("[ORMTP in/IN {roomnp}]", 3),
    ("[ORMTP in/IN the/DT {S}/DIR room/RM]", 1),
    ("[ORMTP in/IN the/DT room/RM]", 1),
]
STATIC_ROOM_NAMED = ["[ORMTP in/IN {roomnp}]", "[ORMTP in/IN {roomnp}]", "[ORMTP inside/IN {roomnp}]",
                     "[ORMTP over/IN in/IN {roomnp}]"]

OBJECT_NP = {
    "fork": [("the/DT fork/NN", 8), ("a/DT fork/NN", 1), ("the/DT silver/JJ fork/NN", 1), ("my/PRP fork/NN", 1)],
    "glasses case": [("the/DT glasses/NNS case/NN", 8), ("the/DT eyeglasses/NNS case/NN", 1),
                     ("my/PRP glasses/NNS case/NN", 1), ("the/DT case/NN for/IN my/PRP glasses/NNS", 1),
                     ("the/DT eyeglass/NN case/NN", 1), ("the/DT black/JJ glasses/NNS case/NN", 1)],
    "laptop": [("the/DT laptop/NN", 8), ("the/DT laptop/NN computer/NN", 1), ("my/PRP laptop/NN", 1),
               ("the/DT computer/NN", 1), ("the/DT black/JJ laptop/NN", 1)],
    "monitor": [("the/DT monitor/NN", 8), ("the/DT computer/NN monitor/NN", 1), ("the/DT screen/NN", 1),
                ("the/DT little/JJ monitor/NN", 1), ("the/DT black/JJ monitor/NN", 1)],
    "mug": [("the/DT mug/NN", 8), ("the/DT coffee/NN mug/NN", 2), ("the/DT cup/NN", 1), ("my/PRP mug/NN", 1),
            ("the/DT yellow/JJ mug/NN", 1), ("the/DT white/JJ mug/NN", 1)],
    "statue": [("the/DT statue/NN", 8), ("the/DT little/JJ statue/NN", 1), ("the/DT small/JJ statue/NN", 1),
               ("the/DT figurine/NN", 1), ("the/DT green/JJ statue/NN", 1), ("this/DT little/JJ statue/NN", 1)],
}
# slot versions (generate.expand draws from lists)
OBJECT_NP = {k: [t for t, w in v for _ in range(w)] for k, v in OBJECT_NP.items()}

#: the object phrase that ends a dynamic description without furniture
OBTP_END_NONE = [
    ("[OBTP you/PRP 'll/MD find/VB {obj}]", 5), ("[OBTP you/PRP will/MD find/VB {obj}]", 2),
    ("[OBTP there/EX is/VBZ {obj}]", 3), ("[OBTP there/EX 's/VBZ {obj}]", 2),
    ("[OBTP you/PRP 'll/MD see/VB {obj}]", 2), ("[OBTP {obj} will/MD be/VB {where}]", 4),
    ("[OBTP {obj} should/MD be/VB {where}]", 2), ("[OBTP {obj} is/VBZ {where}]", 3),
    ("[OBTP it/PRP 's/VBZ {where}]", 2), ("[OBTP it/PRP should/MD be/VB {where}]", 1),
    ("[OBTP {obj} is/VBZ right/RB there/RB]", 1), ("[OBTP you/PRP should/MD see/VB {obj}]", 1),
    ("[OBTP you/PRP 're/VBP gon/VBR na/VBR see/VB {obj}]", 1), ("[OBTP look/VB for/IN {obj}]", 1),
    ("[OBTP pick/VB up/RP {obj}]", 1), ("[OBTP {obj} is/VBZ there/RB]", 1),
    ("[OBTP that/DT 's/VBZ where/WRB {obj} is/VBZ]", 1), ("[OBTP its/PRP {where}]", 1),
    ("[OBTP bring/VB me/PRP {obj}]", 1), ("[OBTP bring/VB {obj} back/RB to/TO me/PRP]", 1),
    ("[OBTP {obj} can/MD be/VB found/VBN {where}]", 1), ("[OBTP get/VB {obj} for/IN me/PRP]", 1),
    ("[OBTP and/CC pick/VB it/PRP up/RP]", 1), ("[OBTP you/PRP 'd/MD see/VB {obj}]", 1),
]

#: the object phrase that ends a dynamic description, with the goal furniture {furtp}
OBTP_END_FURN = [
    ("[OBTP you/PRP 'll/MD find/VB {obj} {furtp}]", 5), ("[OBTP {obj} will/MD be/VB {furtp}]", 4),
    ("[OBTP {obj} is/VBZ {furtp}]", 4), ("[OBTP there/EX is/VBZ {obj} {furtp}]", 2),
    ("[OBTP it/PRP 's/VBZ {furtp}]", 2), ("[OBTP {obj} should/MD be/VB {furtp}]", 2),
    ("[OBTP {obj} is/VBZ sitting/VBG {furtp}]", 1), ("[OBTP you/PRP 'll/MD see/VB {obj} {furtp}]", 2),
    ("[OBTP you/PRP will/MD find/VB {obj} {furtp}]", 1), ("[OBTP {obj} 's/VBZ {furtp}]", 1),
    ("[OBTP grab/VB {obj} {furtp}]", 1), ("[OBTP {obj} is/VBZ right/RB there/RB {furtp}]", 1),
]

#: furniture landmark on the way (path): {furn} the table, {furna} "a table", {furrp} its reference
FURTP_PATH = [
    ("[FURTP [IRMRP go/VB forward/RB to/TO] {furn} {furrp}]", 4),
    ("[FURTP [IRMRP walk/VB straight/RB until/IN you/PRP are/VBP at/IN] {furn} {furrp}]", 2),
    ("[FURTP [IRMRP go/VB straight/RB to/TO] {furn} {furrp}]", 3),
    ("[FURTP [IRMRP walk/VB over/IN to/TO] {furn} {furrp}]", 2),
    ("[FURTP [IRMRP go/VB up/RP to/TO] {furn} {furrp}]", 1),
    ("[FURTP you/PRP 'll/MD see/VB {furna} {furrp}]", 2),
    ("[FURTP there/EX 's/VBZ {furna} {furrp}]", 1),
    ("[FURTP there/EX is/VBZ {furna} {furrp}]", 1),
    ("[FURTP [IRMRP head/VB toward/IN] {furn} {furrp}]", 1),
]
FURTP_LOOK = [
    ("[FURTP look/VB for/IN {furna} {furrp}]", 2), ("[FURTP you/PRP 'll/MD see/VB {furna} {furrp}]", 2),
    ("[FURTP find/VB {furn} {furrp}]", 1), ("[FURTP there/EX is/VBZ {furna} {furrp}]", 1),
    ("[FURTP go/VB to/TO {furn} {furrp}]", 1),
]
#: the object phrase after a furniture landmark chunk
OBTP_AFTER_FURTP = [
    ("[OBTP there/EX is/VBZ {obj}]", 3), ("[OBTP you/PRP 'll/MD find/VB {obj}]", 3),
    ("[OBTP {obj} is/VBZ [FURTP on/ON it/PRP]]", 2), ("[OBTP {obj} is/VBZ [FURTP on/ON that/DT table/FUR]]", 2),
    ("[OBTP it/PRP 's/VBZ [FURTP on/ON that/DT table/FUR]]", 1), ("[OBTP {obj} should/MD be/VB [FURTP on/ON that/DT one/CD]]", 1),
    ("[OBTP {obj} is/VBZ sitting/VBG [FURTP on/ON that/DT table/FUR]]", 1),
    ("[OBTP {obj} will/MD be/VB [FURTP on/ON top/NN of/IN it/PRP]]", 1), ("[OBTP it/PRP 's/VBZ [FURTP on/ON it/PRP]]", 1),
    ("[OBTP {obj} should/MD be/VB there/RB]", 1), ("[OBTP you/PRP should/MD see/VB {obj}]", 1),
    ("[OBTP {obj} is/VBZ on/ON there/RB]", 1),
]

#: openers of static where-descriptions (the OBTP spans the rest)
OBTP_STATIC_OPEN = [
    ("the/DT {obj_bare} is/VBZ", 0),
    ("{obj} is/VBZ", 12), ("{obj} 's/VBZ", 2), ("{obj} was/VBD", 2), ("{obj} should/MD be/VB", 3),
    ("{obj} will/MD be/VB", 2), ("{obj} is/VBZ located/VBN", 2), ("{obj} is/VBZ sitting/VBG", 1),
    ("it/PRP 's/VBZ", 2), ("it/PRP is/VBZ", 1), ("you/PRP 'll/MD find/VB {obj}", 2),
    ("you/PRP can/MD find/VB {obj}", 1), ("{obj} is/VBZ going/VBG to/TO be/VB", 1),
    ("i/PRP put/VBD {obj}", 1), ("{obj} can/MD be/VB found/VBN", 1), ("you/PRP 'd/MD find/VB {obj}", 1),
    ("{obj} is/VBZ lying/VBG", 1), ("{obj} is/VBZ also/RB", 1), ("its/PRP", 1), ("{obj} would/MD be/VB", 1), ("{obj} might/MD be/VB", 1),
]
OBTP_STATIC_OPEN = [(t, w) for t, w in OBTP_STATIC_OPEN if w]

#: "on the table" heads of a goal-landmark FURTP
ON_FURN = [("on/ON {furn}", 10), ("on/ON top/NN of/IN {furn}", 3), ("at/IN {furn}", 1), ("on/ON the/DT edge/NN of/IN {furn}", 1),
           ("sitting/VBG on/ON {furn}", 1), ("on/ON the/DT top/NN of/IN {furn}", 1)]

#: object phrases of mixed descriptions (after a route): {furtp} is the goal FURTP
OBTP_MIXED = [
    ("[OBTP {obj} is/VBZ {furtp}]", 5), ("[OBTP {obj} will/MD be/VB {furtp}]", 3),
    ("[OBTP you/PRP 'll/MD find/VB {obj} {furtp}]", 3), ("[OBTP it/PRP 's/VBZ {furtp}]", 2),
    ("[OBTP {obj} should/MD be/VB {furtp}]", 2), ("[OBTP there/EX 's/VBZ {obj} {furtp}]", 1),
    ("[OBTP {obj} is/VBZ sitting/VBG {furtp}]", 1), ("[OBTP look/VB for/IN {obj} {furtp}]", 1),
    ("[OBTP get/VB {obj} {furtp}]", 1),
]

#: small things people mention beside the target (not in the world model; grounded N/A)
OBRP = [
    ("[OBRP next/RB to/TO the/DT book/NN]", 3), ("[OBRP by/IN the/DT lamp/FUR]", 3),
    ("[OBRP next/RB to/TO a/DT plant/NN]", 2), ("[OBRP near/IN the/DT keys/NNS]", 1),
    ("[OBRP beside/IN the/DT phone/NN]", 1), ("[OBRP next/RB to/TO the/DT cell/NN phone/NN]", 1),
    ("[OBRP with/IN some/DT papers/NNS]", 1), ("[OBRP by/IN the/DT vase/NN]", 2),
    ("[OBRP next/RB to/TO the/DT wallet/NN]", 1), ("[OBRP with/IN a/DT notepad/NN]", 1),
    ("[OBRP next/RB to/TO the/DT remote/NN]", 1), ("[OBRP by/IN a/DT stack/NN of/IN books/NNS]", 1),
    ("[OBRP with/IN the/DT lamp/FUR on/ON it/PRP]", 1), ("[OBRP that/WDT has/VBZ a/DT plant/NN on/ON it/PRP]", 1),
    ("[OBRP next/RB to/TO a/DT letter/NN]", 1), ("[OBRP near/IN the/DT purse/NN]", 1),
    ("[OBRP with/IN a/DT clock/NN]", 1), ("[OBRP next/RB to/TO the/DT picture/NN frame/NN]", 1),
    ("[OBRP where/WRB there/EX 's/VBZ also/RB a/DT lamp/FUR]", 1), ("[OBRP which/WDT has/VBZ a/DT vase/NN on/ON it/PRP]", 1),
    ("[OBRP right/RB next/RB to/TO the/DT yellow/JJ book/NN]", 1), ("[OBRP by/IN this/DT green/JJ plant/NN]", 1),
]

#: harmless first moves after entering a room (they do not change where the route ends)
ENTER_MOVES = [
    ("[IRMRP go/VB in/IN]", 2), ("[IRMRP walk/VB in/IN]", 2), ("[IRMRP step/VB inside/IN]", 1),
    ("[IRMRP once/WRB you/PRP enter/VB the/DT room/RM]", 2), ("[IRMRP when/WRB you/PRP get/VB in/IN]", 1),
    ("[IRMRP as/IN soon/RB as/IN you/PRP walk/VB in/IN]", 1), ("[IRMRP once/WRB you/PRP 're/VBP inside/IN]", 1),
    ("[IRMRP go/VB through/IN the/DT door/STR]", 1), ("[IRMRP walk/VB through/IN the/DT doorway/STR]", 1),
    ("[IRMRP go/VB through/IN the/DT opening/STR]", 1), ("[IRMRP enter/VB the/DT room/RM]", 1),
    ("[IRMRP once/WRB you/PRP 've/VBP entered/VBN the/DT room/RM]", 1), ("[IRMRP take/VB a/DT step/NN in/IN]", 1),
    ("[IRMRP take/VB one/CD step/NN inside/IN]", 1), ("[IRMRP as/IN soon/RB as/IN you/PRP enter/VB]", 1),
    ("[IRMRP go/VB through/IN the/DT entrance/STR]", 1), ("[IRMRP walk/VB through/IN the/DT entryway/STR]", 1),
]

#: a few steps straight on (a plain "go forward", counted in steps)
STEP_MOVES = [
    ("[IRMRP take/VB a/DT step/NN forward/RB]", 2), ("[IRMRP take/VB two/CD steps/NNS forward/RB]", 2),
    ("[IRMRP walk/VB about/IN four/CD steps/NNS]", 1), ("[IRMRP go/VB forward/RB 2/CD steps/NNS]", 1),
    ("[IRMRP take/VB three/CD steps/NNS]", 1), ("[IRMRP go/VB about/IN five/CD steps/NNS in/IN]", 1),
    ("[IRMRP walk/VB forward/RB a/DT couple/JJ of/IN steps/NNS]", 1), ("[IRMRP take/VB a/DT few/JJ steps/NNS forward/RB]", 2),
    ("[IRMRP go/VB forward/RB about/IN 3/CD steps/NNS]", 1), ("[IRMRP move/VB forward/RB one/CD step/NN]", 1),
    ("[IRMRP go/VB a/DT little/RB further/RB]", 1), ("[IRMRP keep/VB going/VBG straight/RB]", 1),
    ("[IRMRP continue/VB straight/RB]", 1), ("[IRMRP go/VB straight/RB ahead/RB]", 2),
]

#: goal furniture said first as its own chunk, the object after it (real speakers do this a lot)
FURTP_GOAL_FIRST = [
    ("[FURTP [IRMRP go/VB to/TO] {furn}]", 3), ("[FURTP [IRMRP go/VB over/IN to/TO] {furn}]", 2),
    ("[FURTP [IRMRP walk/VB up/RP to/TO] {furn}]", 1), ("[FURTP [IRMRP head/VB towards/RB] {furn}]", 1),
    ("[FURTP [IRMRP go/VB straight/RB to/TO] {furn}]", 2), ("[FURTP look/VB at/IN {furn}]", 1),
    ("[FURTP look/VB for/IN {furna}]", 2), ("[FURTP you/PRP 'll/MD see/VB {furna}]", 2),
    ("[FURTP there/EX 's/VBZ {furna}]", 1), ("[FURTP there/EX is/VBZ {furna}]", 1),
    ("[FURTP [IRMRP walk/VB towards/RB] {furn}]", 1), ("[FURTP [IRMRP go/VB forward/RB and/CC stop/VB at/IN] {furn}]", 1),
    ("[FURTP [IRMRP keep/VB going/VBG until/IN you/PRP get/VB to/TO] {furn}]", 1),
    ("[FURTP [IRMRP continue/VB to/TO] {furn}]", 1), ("[FURTP find/VB {furn}]", 1),
]

#: object phrases that say the furniture first: "[OBTP [FURTP on the table] there's the mug]"
OBTP_FURN_FIRST = [
    ("[OBTP [FURTP on/ON {furn}] there/EX 's/VBZ {obj}]", 2), ("[OBTP [FURTP on/ON {furn}] there/EX is/VBZ {obj}]", 2),
    ("[OBTP [FURTP on/ON top/NN of/IN {furn}] you/PRP 'll/MD find/VB {obj}]", 1),
    ("[OBTP [FURTP on/ON {furn}] you/PRP 'll/MD see/VB {obj}]", 1), ("[OBTP [FURTP on/ON {furn}] is/VBZ {obj}]", 1),
    ("[OBTP [FURTP sitting/VBG on/ON {furn}] is/VBZ {obj}]", 1), ("[OBTP [FURTP on/ON top/NN of/IN {furn}] is/VBZ {obj}]", 1),
    ("[OBTP [FURTP on/ON top/NN of/IN {furn}] there/EX 's/VBZ {obj}]", 1),
]

#: colour and size words put before a furniture noun now and then
FURN_ADJ = [("brown/JJ", 3), ("white/JJ", 2), ("wooden/JJ", 2), ("small/JJ", 2), ("little/JJ", 1), ("light/JJ brown/JJ", 1),
            ("dark/JJ", 1), ("black/JJ", 1), ("big/JJ", 1), ("short/JJ", 1), ("low/JJ", 1)]
#: relative-clause openings of a furniture reference ("the table which is in front of the couch")
FURRP_REL = [("which/WDT is/VBZ", 2), ("that/WDT is/VBZ", 2), ("that/WDT 's/VBZ", 1), ("which/WDT is/VBZ right/RB", 1)]

#: the object said inside the furniture phrase: "[FURTP go to the table [OBTP the mug is on it]]"
OBTP_IN_FURTP = [
    ("[OBTP with/IN {obj} on/ON it/PRP]", 3), ("[OBTP and/CC {obj} is/VBZ on/ON it/PRP]", 2),
    ("[OBTP that/WDT has/VBZ {obj} on/ON it/PRP]", 2), ("[OBTP and/CC you/PRP 'll/MD see/VB {obj}]", 1),
    ("[OBTP {obj} is/VBZ there/RB]", 1), ("[OBTP and/CC {obj} should/MD be/VB there/RB]", 1),
]
#: a time clause nested in an inside-room phrase ("on the right wall once you've entered the room")
IRMRP_NESTED = [
    ("[IRMRP once/WRB you/PRP 've/VBP entered/VBN the/DT room/RM]", 2), ("[IRMRP as/IN soon/RB as/IN you/PRP walk/VB in/IN]", 2),
    ("[IRMRP when/WRB you/PRP enter/VB]", 1), ("[IRMRP once/WRB you/PRP 're/VBP in/IN the/DT room/RM]", 1),
    ("[IRMRP right/RB as/IN you/PRP go/VB in/IN]", 1),
]

# ------------------------------------------------------------------ shorter and longer descriptions
# (real speakers often stop after the route or the furniture, or say the room first as a
# sentence of its own and the place later; the object is then said twice)

#: the room said first as a sentence of its own (the object phrase spans the room phrase)
OBTP_ROOM_FIRST = [
    ("[OBTP {obj} is/VBZ {room}]", 8), ("[OBTP {obj} is/VBZ located/VBN {room}]", 1),
    ("[OBTP {obj} 's/VBZ {room}]", 1), ("[OBTP it/PRP 's/VBZ {room}]", 2), ("[OBTP {obj} was/VBD {room}]", 1),
    ("[OBTP {obj} should/MD be/VB {room}]", 1), ("[OBTP its/PRP {room}]", 1),
]
#: the second object sentence, after the moves inside the room: {furtp} the goal FURTP
OBTP_SECOND = [
    ("[OBTP it/PRP 's/VBZ {furtp}]", 6), ("[OBTP it/PRP is/VBZ {furtp}]", 3), ("[OBTP its/PRP {furtp}]", 2),
    ("[OBTP {obj} is/VBZ {furtp}]", 3), ("[OBTP it/PRP should/MD be/VB {furtp}]", 2),
    ("[OBTP you/PRP 'll/MD find/VB it/PRP {furtp}]", 1), ("[OBTP it/PRP will/MD be/VB {furtp}]", 1),
    ("[OBTP it/PRP 's/VBZ sitting/VBG {furtp}]", 1), ("[OBTP you/PRP should/MD find/VB it/PRP {furtp}]", 1),
]
#: a closing sentence after the object phrase (a second OBTP)
OBTP_CLOSING = [
    ("[OBTP pick/VB it/PRP up/RP]", 3), ("[OBTP bring/VB it/PRP to/TO me/PRP]", 3), ("[OBTP grab/VB it/PRP]", 1),
    ("[OBTP bring/VB it/PRP back/RB to/TO me/PRP please/IGN]", 1), ("[OBTP it/PRP 's/VBZ right/RB there/RB]", 1),
    ("[OBTP you/PRP ca/MD n't/RB miss/VB it/PRP]", 1), ("[OBTP that/DT 's/VBZ {obj}]", 1),
    ("[OBTP could/MD you/PRP bring/VB it/PRP to/TO me/PRP]", 1),
]
#: "look down" before the object: "[OBTP look down] and [OBTP you'll see the mug]"
OBTP_LOOK = [("[OBTP look/VB down/RB]", 3), ("[OBTP look/VB on/ON it/PRP]", 1), ("[OBTP look/VB at/IN the/DT top/NN]", 1)]

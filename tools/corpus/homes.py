"""Facts of the four study homes, written as annotated phrase options for the generator.

Read off ``assistant/world/data/worlds/*.yaml`` (original scenes): which room each object is in,
which furniture it lies on, what stands near that furniture, and how a person standing at the
robot's start pose would direct someone there. Each phrase is in the bracket notation of
:mod:`notation` (``word/TAG``, ``[LABEL ...]``). Directions were worked out from the start
heading: e.g. in the apartment the robot starts at (5, 0) facing -x, so the living room
(+y) is on the right and the bedroom (-y) on the left, as in the CSISL house.

Per object:
``side``       where the room's entrance lies from the start: left / right / ahead / far
``routes``     extra outside-room routes (lists of ORMTP chunks) for rooms reached in steps
``dynamic``    inside-room move sequences (lists of IRMRP chunks) that end near the object
``where``      static inside-room location phrases (IRMRP)
``furniture``  noun phrases for the furniture the object is on (goal landmark)
``furrp``      furniture reference phrases locating that furniture (FURRP)
``path``       path-landmark steps: chunks that move past / towards other furniture
"""

from __future__ import annotations

#: room noun phrases (tagged) for each room word
ROOM_NP = {
    "living room": ["the/DT living/NN room/RM"],
    "bedroom": ["the/DT bedroom/RM"],
    "office": ["the/DT office/RM"],
    "studio": ["the/DT studio/RM", "the/DT big/JJ studio/RM"],
    "meeting room": ["the/DT meeting/NN room/RM"],
}

HOMES: dict[str, dict] = {}

# ------------------------------------------------------------------ apartment (the CSISL house)
HOMES["apartment"] = {
    "start": "the hallway between the living room (right) and the bedroom (left)",
    "objects": {
        "fork": {
            "room": "living room", "side": "right",
            "furniture": ["the/DT table/FUR", "the/DT round/JJ table/FUR", "the/DT small/JJ round/JJ table/FUR",
                          "the/DT little/JJ table/FUR", "the/DT small/JJ table/FUR"],
            "furrp": ["[FURRP behind/IN the/DT couch/FUR]", "[FURRP in/IN back/NN of/IN the/DT couch/FUR]",
                      "[FURRP behind/IN the/DT sofa/FUR]", "[FURRP just/RB behind/IN the/DT couch/FUR]"],
            "where": ["[IRMRP on/ON the/DT right/DIR]", "[IRMRP to/TO the/DT right/DIR]",
                      "[IRMRP directly/RB to/TO your/PRP right/DIR]", "[IRMRP just/RB inside/IN the/DT door/STR]",
                      "[IRMRP near/IN the/DT door/STR]", "[IRMRP on/ON your/PRP right/DIR]"],
            "dynamic": [["[IRMRP turn/VB right/DIR]"],
                        ["[IRMRP take/VB a/DT right/DIR]", "[IRMRP go/VB a/DT few/JJ steps/NNS]"],
                        ["[IRMRP turn/VB to/TO your/PRP right/DIR]"]],
            "path": ["[FURRP [IRMRP walk/VB toward/IN] the/DT back/NN of/IN the/DT couch/FUR]",
                     "[FURRP [IRMRP go/VB straight/RB up/RP to/TO] the/DT back/NN of/IN the/DT sofa/FUR]"],
        },
        "glasses case": {
            "room": "living room", "side": "right",
            "furniture": ["the/DT coffee/NN table/FUR", "the/DT table/FUR", "the/DT low/JJ table/FUR",
                          "the/DT square/JJ table/FUR", "the/DT little/JJ coffee/NN table/FUR"],
            "furrp": ["[FURRP in/IN front/NN of/IN the/DT couch/FUR]", "[FURRP in/IN front/NN of/IN the/DT sofa/FUR]",
                      "[FURRP across/IN from/IN the/DT couch/FUR]"],
            "where": ["[IRMRP in/IN the/DT middle/NN of/IN the/DT room/RM]", "[IRMRP about/IN halfway/NN in/IN]",
                      "[IRMRP about/IN halfway/NN in/IN on/ON the/DT right/DIR]", "[IRMRP in/IN the/DT center/NN of/IN the/DT room/RM]"],
            "dynamic": [["[IRMRP go/VB forward/RB]", "[IRMRP turn/VB right/DIR]"],
                        ["[IRMRP walk/VB about/IN halfway/NN in/IN]", "[IRMRP turn/VB right/DIR]"],
                        ["[IRMRP go/VB straight/RB to/TO the/DT middle/NN of/IN the/DT room/RM]"]],
            "path": ["[FURRP [IRMRP go/VB around/IN] the/DT couch/FUR]",
                     "[FURRP [IRMRP walk/VB past/JJ] the/DT sofa/FUR]"],
        },
        "laptop": {
            "room": "living room", "side": "right",
            "furniture": ["the/DT dinner/NN table/FUR", "the/DT dining/JJ table/FUR", "the/DT big/JJ table/FUR",
                          "the/DT long/JJ table/FUR", "the/DT table/FUR", "the/DT large/JJ table/FUR"],
            "furrp": ["[FURRP with/IN the/DT chairs/FUR]", "[FURRP between/IN the/DT two/CD chairs/FUR]",
                      "[FURRP with/IN the/DT blue/JJ chairs/FUR]", "[FURRP between/IN the/DT blue/JJ chairs/FUR]",
                      "[FURRP with/IN two/CD chairs/FUR]"],
            "where": ["[IRMRP at/IN the/DT back/NN]", "[IRMRP at/IN the/DT far/JJ end/NN of/IN the/DT room/RM]",
                      "[IRMRP against/IN the/DT back/NN wall/STR]", "[IRMRP all/DT the/DT way/NN at/IN the/DT back/NN]",
                      "[IRMRP along/IN the/DT far/JJ wall/STR]", "[IRMRP in/IN the/DT back/NN of/IN the/DT room/RM]",
                      "[IRMRP against/IN the/DT wall/STR]"],
            "dynamic": [["[IRMRP walk/VB straight/RB until/IN you/PRP hit/VBD the/DT wall/STR]"],
                        ["[IRMRP go/VB all/DT the/DT way/NN to/TO the/DT back/NN]"],
                        ["[IRMRP keep/VB going/VBG straight/RB until/IN you/PRP reach/VBP the/DT back/NN wall/STR]"],
                        ["[IRMRP walk/VB straight/RB until/IN you/PRP are/VBP at/IN the/DT back/NN]"],
                        ["[IRMRP go/VB straight/RB until/IN you/PRP are/VBP at/IN the/DT wall/STR]"]],
            "path": ["[FURRP [IRMRP walk/VB past/JJ] the/DT couch/FUR]",
                     "[FURRP [IRMRP go/VB straight/RB past/JJ] the/DT coffee/NN table/FUR]"],
        },
        "statue": {
            "room": "bedroom", "side": "left",
            "furniture": ["the/DT nightstand/FUR", "the/DT night/NN stand/FUR", "the/DT small/JJ table/FUR",
                          "the/DT round/JJ table/FUR", "the/DT bedside/NN table/FUR"],
            "furrp": ["[FURRP to/TO the/DT right/DIR of/IN the/DT bed/FUR]", "[FURRP next/RB to/TO the/DT bed/FUR]",
                      "[FURRP by/IN the/DT head/NN of/IN the/DT bed/FUR]", "[FURRP beside/IN the/DT bed/FUR]"],
            "where": ["[IRMRP ahead/RB to/TO your/PRP left/DIR]", "[IRMRP ahead/RB to/TO the/DT left/DIR]",
                      "[IRMRP on/ON your/PRP left/DIR]", "[IRMRP just/RB to/TO the/DT left/DIR]",
                      "[IRMRP near/IN the/DT door/STR]"],
            "dynamic": [["[IRMRP go/VB forward/RB a/DT little/RB]", "[IRMRP look/VB to/TO your/PRP left/DIR]"],
                        ["[IRMRP step/VB in/IN]", "[IRMRP turn/VB left/DIR]"]],
            "path": ["[FURRP [IRMRP go/VB toward/IN] the/DT head/NN of/IN the/DT bed/FUR]"],
        },
        "monitor": {
            "room": "bedroom", "side": "left",
            "furniture": ["the/DT nightstand/FUR", "the/DT table/FUR", "the/DT coffee/NN table/FUR",
                          "the/DT small/JJ table/FUR", "the/DT night/NN stand/FUR"],
            "furrp": ["[FURRP to/TO the/DT left/DIR of/IN the/DT bed/FUR]", "[FURRP on/ON the/DT other/JJ side/NN of/IN the/DT bed/FUR]",
                      "[FURRP on/ON the/DT far/JJ side/NN of/IN the/DT bed/FUR]", "[FURRP next/RB to/TO the/DT bed/FUR]"],
            "where": ["[IRMRP on/ON the/DT left/DIR wall/STR]", "[IRMRP against/IN the/DT left/DIR wall/STR]",
                      "[IRMRP in/IN the/DT left/DIR corner/NN]", "[IRMRP on/ON the/DT far/JJ left/DIR]",
                      "[IRMRP against/IN the/DT left/DIR side/NN wall/STR]"],
            "dynamic": [["[IRMRP walk/VB straight/RB about/IN halfway/NN in/IN]", "[IRMRP turn/VB left/DIR]",
                         "[IRMRP go/VB forward/RB until/IN you/PRP hit/VBD the/DT wall/STR]", "[IRMRP left/DIR again/RB]"],
                        ["[IRMRP walk/VB straight/RB about/IN halfway/NN in/IN]", "[IRMRP turn/VB left/DIR]",
                         "[IRMRP go/VB forward/RB until/IN you/PRP hit/VBD the/DT wall/STR]", "[IRMRP then/RB left/DIR again/RB]"],
                        ["[IRMRP go/VB about/IN halfway/NN in/IN]", "[IRMRP then/RB left/DIR]",
                         "[IRMRP go/VB forward/RB until/IN you/PRP hit/VBD wall/STR]", "[IRMRP then/RB left/DIR again/RB]"],
                        ["[IRMRP go/VB in/IN past/JJ the/DT end/NN of/IN the/DT bed/FUR]", "[IRMRP turn/VB left/DIR]",
                         "[IRMRP go/VB to/TO the/DT wall/STR]", "[IRMRP turn/VB left/DIR again/RB]"]],
            "path": ["[FURRP [IRMRP walk/VB around/IN] the/DT foot/NN of/IN the/DT bed/FUR]",
                     "[FURRP [IRMRP go/VB past/JJ] the/DT bed/FUR]"],
        },
        "mug": {
            "room": "bedroom", "side": "left",
            "furniture": ["the/DT table/FUR", "the/DT hexagon/NN table/FUR", "the/DT wooden/JJ table/FUR",
                          "the/DT six/CD sided/VBN table/FUR", "the/DT brown/JJ table/FUR"],
            "furrp": ["[FURRP with/IN the/DT chairs/FUR]", "[FURRP between/IN the/DT two/CD chairs/FUR]",
                      "[FURRP by/IN the/DT chairs/FUR]", "[FURRP with/IN the/DT wooden/JJ chairs/FUR]",
                      "[FURRP between/IN the/DT wood/NN chairs/FUR]",
                      "[FURRP with/IN two/CD chairs/FUR]"],
            "where": ["[IRMRP on/ON the/DT far/JJ right/DIR]", "[IRMRP at/IN the/DT far/JJ right/DIR wall/STR]",
                      "[IRMRP against/IN the/DT right/DIR wall/STR]", "[IRMRP at/IN the/DT far/JJ right/DIR end/NN]",
                      "[IRMRP to/TO the/DT far/JJ right/DIR]", "[IRMRP against/IN the/DT wall/STR]"],
            "dynamic": [["[IRMRP move/VB about/IN halfway/NN in/IN]", "[IRMRP turn/VB right/DIR]", "[IRMRP go/VB forward/RB]"],
                        ["[IRMRP walk/VB in/IN a/DT few/JJ steps/NNS]", "[IRMRP turn/VB right/DIR]",
                         "[IRMRP go/VB straight/RB until/IN you/PRP reach/VBP the/DT wall/STR]"]],
            "path": ["[FURRP [IRMRP walk/VB past/JJ] the/DT foot/NN of/IN the/DT bed/FUR]"],
        },
    },
}

# ------------------------------------------------------------------ hk-studio
HOMES["hk-studio"] = {
    "start": "a short hallway: the meeting room opens on the left, the office door is on the right, "
             "the studio door is at the end",
    "objects": {
        "laptop": {
            "room": "meeting room", "side": "left",
            "furniture": ["the/DT big/JJ table/FUR", "the/DT meeting/NN table/FUR", "the/DT dinner/NN table/FUR",
                          "the/DT long/JJ table/FUR", "the/DT table/FUR"],
            "furrp": ["[FURRP between/IN the/DT two/CD chairs/FUR]", "[FURRP with/IN the/DT blue/JJ chairs/FUR]",
                      "[FURRP between/IN the/DT chairs/FUR]", "[FURRP with/IN the/DT two/CD chairs/FUR]"],
            "where": ["[IRMRP in/IN the/DT middle/NN of/IN the/DT room/RM]", "[IRMRP in/IN the/DT center/NN]",
                      "[IRMRP straight/RB ahead/RB]", "[IRMRP right/RB in/IN the/DT middle/NN]"],
            "dynamic": [["[IRMRP go/VB straight/RB about/IN halfway/NN in/IN]"],
                        ["[IRMRP walk/VB forward/RB to/TO the/DT middle/NN of/IN the/DT room/RM]"]],
            "path": [],
        },
        "mug": {
            "room": "office", "side": "right",
            "furniture": ["the/DT coffee/NN table/FUR", "the/DT low/JJ table/FUR", "the/DT small/JJ table/FUR",
                          "the/DT table/FUR"],
            "furrp": ["[FURRP in/IN front/NN of/IN the/DT couch/FUR]", "[FURRP in/IN front/NN of/IN the/DT sofa/FUR]",
                      "[FURRP next/RB to/TO the/DT couch/FUR]"],
            "where": ["[IRMRP on/ON your/PRP right/DIR]", "[IRMRP to/TO the/DT right/DIR]",
                      "[IRMRP about/IN halfway/NN in/IN on/ON the/DT right/DIR]"],
            "dynamic": [["[IRMRP turn/VB right/DIR]", "[IRMRP go/VB forward/RB]"],
                        ["[IRMRP take/VB a/DT right/DIR]", "[IRMRP walk/VB a/DT few/JJ steps/NNS]"]],
            "path": ["[FURRP [IRMRP go/VB toward/IN] the/DT couch/FUR]"],
        },
        "glasses case": {
            "room": "office", "side": "right",
            "furniture": ["the/DT desk/FUR", "the/DT big/JJ desk/FUR", "the/DT white/JJ desk/FUR"],
            "furrp": ["[FURRP by/IN the/DT blue/JJ chair/FUR]", "[FURRP in/IN front/NN of/IN the/DT chair/FUR]",
                      "[FURRP with/IN the/DT chair/FUR]"],
            "where": ["[IRMRP at/IN the/DT far/JJ end/NN of/IN the/DT room/RM]", "[IRMRP in/IN the/DT far/JJ right/DIR corner/NN]",
                      "[IRMRP against/IN the/DT right/DIR wall/STR]", "[IRMRP all/DT the/DT way/NN at/IN the/DT end/NN]",
                      "[IRMRP at/IN the/DT back/NN]", "[IRMRP against/IN the/DT wall/STR]"],
            "dynamic": [["[IRMRP walk/VB all/DT the/DT way/NN to/TO the/DT end/NN of/IN the/DT room/RM]", "[IRMRP turn/VB right/DIR]"],
                        ["[IRMRP go/VB straight/RB until/IN you/PRP reach/VBP the/DT far/JJ wall/STR]", "[IRMRP turn/VB right/DIR]"]],
            "path": ["[FURRP [IRMRP walk/VB past/JJ] the/DT couch/FUR]",
                     "[FURRP [IRMRP go/VB past/JJ] the/DT coffee/NN table/FUR]"],
        },
        "fork": {
            "room": "studio", "side": "ahead",
            "furniture": ["the/DT desk/FUR", "the/DT first/JJ desk/FUR", "the/DT small/JJ desk/FUR"],
            "furrp": ["[FURRP in/IN front/NN of/IN the/DT wooden/JJ chair/FUR]", "[FURRP by/IN the/DT chair/FUR]",
                      "[FURRP with/IN the/DT wooden/JJ chair/FUR]"],
            "where": ["[IRMRP on/ON your/PRP left/DIR]", "[IRMRP to/TO the/DT left/DIR]",
                      "[IRMRP just/RB inside/IN the/DT door/STR on/ON the/DT left/DIR]", "[IRMRP right/DIR by/IN the/DT door/STR]",
                      "[IRMRP immediately/RB to/TO your/PRP left/DIR]"],
            "dynamic": [["[IRMRP turn/VB left/DIR]"], ["[IRMRP take/VB a/DT left/DIR]", "[IRMRP go/VB a/DT few/JJ steps/NNS]"],
                        ["[IRMRP make/VB an/DT immediate/JJ left/DIR]"]],
            "path": [],
        },
        "statue": {
            "room": "studio", "side": "ahead",
            "furniture": ["the/DT desk/FUR", "the/DT other/JJ desk/FUR", "the/DT desk/FUR"],
            "furrp": ["[FURRP in/IN front/NN of/IN the/DT chair/FUR]", "[FURRP by/IN the/DT wooden/JJ chair/FUR]",
                      "[FURRP with/IN the/DT chair/FUR]"],
            "where": ["[IRMRP in/IN the/DT far/JJ left/DIR corner/NN]", "[IRMRP in/IN the/DT back/NN left/DIR corner/NN]",
                      "[IRMRP at/IN the/DT back/NN]", "[IRMRP against/IN the/DT left/DIR wall/STR]",
                      "[IRMRP at/IN the/DT far/JJ end/NN on/ON the/DT left/DIR]"],
            "dynamic": [["[IRMRP go/VB straight/RB until/IN you/PRP hit/VBD the/DT back/NN wall/STR]", "[IRMRP turn/VB left/DIR]"],
                        ["[IRMRP walk/VB all/DT the/DT way/NN to/TO the/DT back/NN]", "[IRMRP then/RB left/DIR]"]],
            "path": ["[FURRP [IRMRP walk/VB past/JJ] the/DT first/JJ desk/FUR]"],
        },
        "monitor": {
            "room": "studio", "side": "ahead",
            "furniture": ["the/DT table/FUR", "the/DT hexagon/NN table/FUR", "the/DT small/JJ table/FUR",
                          "the/DT wooden/JJ table/FUR"],
            "furrp": ["[FURRP next/RB to/TO the/DT chair/FUR]", "[FURRP by/IN the/DT chair/FUR]",
                      "[FURRP to/TO the/DT right/DIR of/IN the/DT chair/FUR]", "[FURRP with/IN a/DT chair/FUR]"],
            "where": ["[IRMRP on/ON the/DT far/JJ right/DIR]", "[IRMRP against/IN the/DT right/DIR wall/STR]",
                      "[IRMRP on/ON the/DT right/DIR side/NN of/IN the/DT room/RM]", "[IRMRP over/IN on/ON the/DT right/DIR]"],
            "dynamic": [["[IRMRP turn/VB right/DIR]", "[IRMRP go/VB straight/RB until/IN you/PRP reach/VBP the/DT wall/STR]"],
                        ["[IRMRP walk/VB about/IN halfway/NN in/IN]", "[IRMRP turn/VB right/DIR]", "[IRMRP go/VB forward/RB]"]],
            "path": [],
        },
    },
}

# ------------------------------------------------------------------ one-bedroom-house
HOMES["one-bedroom-house"] = {
    "start": "the hallway: the office door right on the left, the living room open on the right, "
             "the meeting room door at the end; the bedroom opens off the living room",
    "objects": {
        "laptop": {
            "room": "office", "side": "left",
            "furniture": ["the/DT desk/FUR", "the/DT big/JJ desk/FUR", "the/DT wooden/JJ desk/FUR"],
            "furrp": ["[FURRP next/RB to/TO the/DT round/JJ table/FUR]", "[FURRP near/IN the/DT little/JJ table/FUR]"],
            "where": ["[IRMRP straight/RB ahead/RB]", "[IRMRP against/IN the/DT far/JJ wall/STR]",
                      "[IRMRP at/IN the/DT back/NN of/IN the/DT room/RM]", "[IRMRP along/IN the/DT back/NN wall/STR]"],
            "dynamic": [["[IRMRP go/VB straight/RB until/IN you/PRP reach/VBP the/DT far/JJ wall/STR]"],
                        ["[IRMRP walk/VB straight/RB in/IN]"]],
            "path": [],
        },
        "mug": {
            "room": "living room", "side": "right",
            "furniture": ["the/DT coffee/NN table/FUR", "the/DT low/JJ table/FUR", "the/DT table/FUR"],
            "furrp": ["[FURRP next/RB to/TO the/DT couch/FUR]", "[FURRP by/IN the/DT couch/FUR]",
                      "[FURRP beside/IN the/DT sofa/FUR]", "[FURRP at/IN the/DT end/NN of/IN the/DT couch/FUR]"],
            "where": ["[IRMRP in/IN the/DT far/JJ right/DIR corner/NN]", "[IRMRP against/IN the/DT right/DIR wall/STR]",
                      "[IRMRP on/ON the/DT far/JJ right/DIR]"],
            "dynamic": [["[IRMRP go/VB straight/RB across/IN the/DT room/RM]", "[IRMRP turn/VB right/DIR]"],
                        ["[IRMRP walk/VB forward/RB until/IN you/PRP get/VB to/TO the/DT wall/STR]"]],
            "path": ["[FURRP [IRMRP walk/VB toward/IN] the/DT couch/FUR]"],
        },
        "glasses case": {
            "room": "living room", "side": "right",
            "furniture": ["the/DT round/JJ table/FUR", "the/DT small/JJ table/FUR", "the/DT table/FUR",
                          "the/DT little/JJ round/JJ table/FUR"],
            "furrp": ["[FURRP in/IN front/NN of/IN the/DT couch/FUR]", "[FURRP in/IN front/NN of/IN the/DT sofa/FUR]",
                      "[FURRP near/IN the/DT blue/JJ chair/FUR]"],
            "where": ["[IRMRP ahead/RB to/TO your/PRP left/DIR]", "[IRMRP in/IN the/DT middle/NN of/IN the/DT room/RM]",
                      "[IRMRP on/ON the/DT left/DIR]"],
            "dynamic": [["[IRMRP go/VB forward/RB a/DT few/JJ steps/NNS]", "[IRMRP turn/VB left/DIR]"],
                        ["[IRMRP walk/VB in/IN a/DT little/RB bit/NN]", "[IRMRP look/VB to/TO your/PRP left/DIR]"]],
            "path": [],
        },
        "statue": {
            "room": "bedroom", "side": "far",
            "routes": [
                ["[ORMTP [ORMRP|room=living_room turn/VB right/DIR into/IN] the/DT living/NN room/RM]",
                 "[ORMTP [ORMRP turn/VB left/DIR] through/IN the/DT door/STR into/IN the/DT bedroom/RM]"],
                ["[ORMTP go/VB all/DT the/DT way/NN down/RB the/DT hallway/NN]",
                 "[ORMTP go/VB through/IN the/DT door/STR [ORMRP on/ON your/PRP right/DIR]]"],
                ["[ORMTP walk/VB to/TO the/DT end/NN of/IN the/DT hallway/NN and/CC [ORMRP take/VB the/DT door/STR on/ON the/DT right/DIR]]"],
            ],
            "furniture": ["the/DT nightstand/FUR", "the/DT night/NN stand/FUR", "the/DT small/JJ round/JJ table/FUR",
                          "the/DT bedside/NN table/FUR"],
            "furrp": ["[FURRP by/IN the/DT head/NN of/IN the/DT bed/FUR]", "[FURRP next/RB to/TO the/DT bed/FUR]",
                      "[FURRP to/TO the/DT right/DIR of/IN the/DT bed/FUR]", "[FURRP in/IN front/NN of/IN the/DT bed/FUR]"],
            "where": ["[IRMRP ahead/RB to/TO your/PRP left/DIR]", "[IRMRP on/ON the/DT left/DIR]", "[IRMRP straight/RB ahead/RB]"],
            "dynamic": [["[IRMRP go/VB straight/RB in/IN]"],
                        ["[IRMRP walk/VB forward/RB a/DT few/JJ steps/NNS]", "[IRMRP look/VB to/TO your/PRP left/DIR]"]],
            "path": ["[FURRP [IRMRP walk/VB toward/IN] the/DT bed/FUR]"],
        },
        "monitor": {
            "room": "bedroom", "side": "far",
            "routes": [
                ["[ORMTP [ORMRP|room=living_room turn/VB right/DIR into/IN] the/DT living/NN room/RM]",
                 "[ORMTP [ORMRP turn/VB left/DIR] through/IN the/DT door/STR into/IN the/DT bedroom/RM]"],
                ["[ORMTP go/VB all/DT the/DT way/NN down/RB the/DT hallway/NN]",
                 "[ORMTP go/VB through/IN the/DT door/STR [ORMRP on/ON your/PRP right/DIR]]"],
            ],
            "furniture": ["the/DT coffee/NN table/FUR", "the/DT small/JJ table/FUR", "the/DT table/FUR"],
            "furrp": ["[FURRP next/RB to/TO the/DT blue/JJ chair/FUR]", "[FURRP by/IN the/DT chair/FUR]",
                      "[FURRP with/IN the/DT blue/JJ chair/FUR]"],
            "where": ["[IRMRP on/ON your/PRP right/DIR]", "[IRMRP to/TO the/DT right/DIR]",
                      "[IRMRP just/RB inside/IN the/DT door/STR on/ON the/DT right/DIR]", "[IRMRP in/IN the/DT right/DIR corner/NN]"],
            "dynamic": [["[IRMRP turn/VB right/DIR]"], ["[IRMRP take/VB a/DT right/DIR]", "[IRMRP go/VB forward/RB a/DT little/RB]"]],
            "path": [],
        },
        "fork": {
            "room": "meeting room", "side": "ahead",
            "furniture": ["the/DT round/JJ table/FUR", "the/DT small/JJ table/FUR", "the/DT table/FUR"],
            "furrp": ["[FURRP in/IN front/NN of/IN the/DT wooden/JJ chair/FUR]", "[FURRP by/IN the/DT chairs/FUR]",
                      "[FURRP with/IN the/DT chairs/FUR]"],
            "where": ["[IRMRP in/IN the/DT back/NN left/DIR corner/NN]", "[IRMRP in/IN the/DT far/JJ left/DIR corner/NN]",
                      "[IRMRP at/IN the/DT back/NN]", "[IRMRP against/IN the/DT back/NN wall/STR]"],
            "dynamic": [["[IRMRP go/VB straight/RB to/TO the/DT back/NN]", "[IRMRP turn/VB left/DIR]"],
                        ["[IRMRP walk/VB straight/RB until/IN you/PRP hit/VBD the/DT wall/STR]", "[IRMRP turn/VB left/DIR]"]],
            "path": [],
        },
    },
}

# ------------------------------------------------------------------ two-bedrooms-house
_TB_INNER = [
    ["[ORMTP {go} straight/RB through/IN the/DT meeting/NN room/RM into/IN the/DT living/NN room/RM]",
     "[ORMTP go/VB through/IN the/DT door/STR [ORMRP|room=hallway on/ON your/PRP left/DIR]]"],
    ["[ORMTP {go} straight/RB until/IN you/PRP get/VB to/TO the/DT living/NN room/RM]",
     "[ORMTP take/VB the/DT door/STR [ORMRP|room=hallway on/ON the/DT left/DIR]]"],
]
HOMES["two-bedrooms-house"] = {
    "start": "a small hallway by the front door: the meeting room and then the living room lie straight ahead; "
             "the bedroom and the office open off an inner hall reached from the living room",
    "objects": {
        "laptop": {
            "room": "meeting room", "side": "ahead",
            "furniture": ["the/DT big/JJ table/FUR", "the/DT dinner/NN table/FUR", "the/DT dining/JJ table/FUR",
                          "the/DT long/JJ table/FUR"],
            "furrp": ["[FURRP between/IN the/DT two/CD chairs/FUR]", "[FURRP with/IN the/DT blue/JJ chairs/FUR]",
                      "[FURRP with/IN the/DT chairs/FUR]"],
            "where": ["[IRMRP on/ON your/PRP left/DIR]", "[IRMRP to/TO the/DT left/DIR]",
                      "[IRMRP on/ON the/DT left/DIR side/NN of/IN the/DT room/RM]"],
            "dynamic": [["[IRMRP walk/VB in/IN a/DT few/JJ steps/NNS]", "[IRMRP turn/VB left/DIR]"],
                        ["[IRMRP go/VB forward/RB a/DT little/RB bit/NN]", "[IRMRP look/VB to/TO your/PRP left/DIR]"]],
            "path": [],
        },
        "mug": {
            "room": "living room", "side": "far",
            "routes": [["[ORMTP {go} straight/RB through/IN the/DT meeting/NN room/RM into/IN the/DT living/NN room/RM]"],
                       ["[ORMTP {go} straight/RB ahead/RB to/TO the/DT living/NN room/RM]"],
                       ["[ORMTP {go} all/DT the/DT way/NN forward/RB past/JJ the/DT big/JJ table/FUR into/IN the/DT living/NN room/RM]"]],
            "furniture": ["the/DT hexagon/NN table/FUR", "the/DT table/FUR", "the/DT wooden/JJ table/FUR",
                          "the/DT six/CD sided/VBN table/FUR"],
            "furrp": ["[FURRP across/IN from/IN the/DT couch/FUR]", "[FURRP opposite/JJ the/DT couch/FUR]"],
            "where": ["[IRMRP against/IN the/DT right/DIR wall/STR]", "[IRMRP on/ON the/DT right/DIR]",
                      "[IRMRP on/ON the/DT right/DIR side/NN of/IN the/DT room/RM]"],
            "dynamic": [["[IRMRP go/VB about/IN halfway/NN in/IN]", "[IRMRP turn/VB right/DIR]"],
                        ["[IRMRP walk/VB in/IN a/DT couple/JJ of/IN steps/NNS]", "[IRMRP turn/VB to/TO the/DT right/DIR]"]],
            "path": [],
        },
        "glasses case": {
            "room": "living room", "side": "far",
            "routes": [["[ORMTP {go} straight/RB through/IN the/DT meeting/NN room/RM into/IN the/DT living/NN room/RM]"],
                       ["[ORMTP {go} straight/RB ahead/RB to/TO the/DT living/NN room/RM]"]],
            "furniture": ["the/DT round/JJ table/FUR", "the/DT small/JJ round/JJ table/FUR", "the/DT table/FUR",
                          "the/DT little/JJ table/FUR"],
            "furrp": ["[FURRP in/IN front/NN of/IN the/DT couch/FUR]", "[FURRP between/IN the/DT two/CD couches/FUR]",
                      "[FURRP between/IN the/DT couches/FUR]", "[FURRP in/IN front/NN of/IN the/DT sofa/FUR]"],
            "where": ["[IRMRP in/IN the/DT middle/NN of/IN the/DT room/RM]", "[IRMRP a/DT little/RB to/TO the/DT left/DIR]",
                      "[IRMRP about/IN halfway/NN in/IN on/ON the/DT left/DIR]"],
            "dynamic": [["[IRMRP go/VB about/IN halfway/NN in/IN]", "[IRMRP look/VB to/TO your/PRP left/DIR]"]],
            "path": ["[FURRP [IRMRP walk/VB toward/IN] the/DT couches/FUR]"],
        },
        "statue": {
            "room": "bedroom", "side": "far",
            "routes": [r + ["[ORMTP [ORMRP turn/VB right/DIR into/IN] the/DT bedroom/RM]"] for r in _TB_INNER]
                      + [r + ["[ORMTP go/VB into/IN the/DT room/RM [ORMRP on/ON the/DT right/DIR]]"] for r in _TB_INNER],
            "furniture": ["the/DT nightstand/FUR", "the/DT night/NN stand/FUR", "the/DT round/JJ table/FUR",
                          "the/DT bedside/NN table/FUR"],
            "furrp": ["[FURRP next/RB to/TO the/DT bed/FUR]", "[FURRP by/IN the/DT head/NN of/IN the/DT bed/FUR]",
                      "[FURRP to/TO the/DT right/DIR of/IN the/DT bed/FUR]"],
            "where": ["[IRMRP ahead/RB to/TO your/PRP left/DIR]", "[IRMRP on/ON the/DT left/DIR]",
                      "[IRMRP in/IN the/DT left/DIR corner/NN]"],
            "dynamic": [["[IRMRP go/VB in/IN a/DT few/JJ steps/NNS]", "[IRMRP turn/VB left/DIR]"]],
            "path": ["[FURRP [IRMRP walk/VB toward/IN] the/DT head/NN of/IN the/DT bed/FUR]"],
        },
        "fork": {
            "room": "office", "side": "far",
            "routes": [r + ["[ORMTP [ORMRP turn/VB left/DIR into/IN] the/DT office/RM]"] for r in _TB_INNER]
                      + [r + ["[ORMTP go/VB into/IN the/DT room/RM [ORMRP on/ON the/DT left/DIR]]"] for r in _TB_INNER],
            "furniture": ["the/DT small/JJ round/JJ table/FUR", "the/DT round/JJ table/FUR", "the/DT table/FUR"],
            "furrp": [],
            "where": ["[IRMRP on/ON your/PRP right/DIR]", "[IRMRP in/IN the/DT right/DIR corner/NN]",
                      "[IRMRP by/IN the/DT door/STR]", "[IRMRP just/RB to/TO the/DT right/DIR]"],
            "dynamic": [["[IRMRP turn/VB right/DIR]"], ["[IRMRP step/VB in/IN]", "[IRMRP look/VB to/TO your/PRP right/DIR]"]],
            "path": [],
        },
        "monitor": {
            "room": "office", "side": "far",
            "routes": [r + ["[ORMTP [ORMRP turn/VB left/DIR into/IN] the/DT office/RM]"] for r in _TB_INNER],
            "furniture": ["the/DT desk/FUR", "the/DT desk/FUR", "the/DT wooden/JJ desk/FUR"],
            "furrp": ["[FURRP in/IN front/NN of/IN the/DT blue/JJ chair/FUR]", "[FURRP by/IN the/DT chair/FUR]"],
            "where": ["[IRMRP against/IN the/DT left/DIR wall/STR]", "[IRMRP in/IN the/DT back/NN left/DIR corner/NN]",
                      "[IRMRP at/IN the/DT back/NN on/ON the/DT left/DIR]"],
            "dynamic": [["[IRMRP go/VB straight/RB to/TO the/DT back/NN]", "[IRMRP turn/VB left/DIR]"],
                        ["[IRMRP walk/VB to/TO the/DT back/NN wall/STR]", "[IRMRP then/RB left/DIR]"]],
            "path": [],
        },
    },
}

#: where the door of each room lies from the start, for generic one-step routes
AHEAD_ROUTES = {
    ("hk-studio", "studio"): [
        "[ORMTP {go} {fwd} through/IN the/DT door/STR at/IN the/DT end/NN of/IN the/DT hallway/NN]",
        "[ORMTP {go} {fwd} into/IN the/DT studio/RM]",
        "[ORMTP {go} {fwd} down/RB the/DT hallway/NN into/IN the/DT studio/RM]",
        "[ORMTP {go} through/IN the/DT door/STR straight/RB ahead/RB]",
        "[ORMTP {go} {fwd} to/TO the/DT end/NN of/IN the/DT hall/NN and/CC into/IN the/DT big/JJ room/RM]",
    ],
    ("one-bedroom-house", "meeting room"): [
        "[ORMTP {go} {fwd} down/RB the/DT hallway/NN into/IN the/DT meeting/NN room/RM]",
        "[ORMTP {go} {fwd} through/IN the/DT door/STR at/IN the/DT end/NN of/IN the/DT hallway/NN]",
        "[ORMTP {go} all/DT the/DT way/NN down/RB the/DT hall/NN to/TO the/DT meeting/NN room/RM]",
        "[ORMTP {go} through/IN the/DT door/STR straight/RB ahead/RB]",
    ],
    ("two-bedrooms-house", "meeting room"): [
        "[ORMTP {go} {fwd} into/IN the/DT meeting/NN room/RM]",
        "[ORMTP {go} {fwd} out/IN of/IN the/DT hallway/NN into/IN the/DT meeting/NN room/RM]",
        "[ORMTP {go} {fwd} into/IN the/DT first/JJ room/RM]",
        "[ORMTP {go} {fwd} into/IN the/DT room/RM ahead/RB of/IN you/PRP]",
    ],
}

"""Chat and phone shorthand written out: "pls check bedrm 4 my mug" → "please check bedroom for my
mug" (:func:`expand_shorthand`).

People type to the robot as they text: short words ("pls", "thru", "rm"), small words with
letters swapped ("teh", "wher"), "2" and "4" for "to" and "for", and prepositions as
second-language speakers put them ("near of the bed"). The chat and the command parser both read
a text through :func:`expand_shorthand` first, so "go thru the livng rm" is the same command
typed to either.
"""

from __future__ import annotations

import re

__all__ = ["SECOND_LANGUAGE", "SHORTHAND", "expand_shorthand"]

#: chat and phone shorthand → the words it stands for (a whole word, any case)
SHORTHAND = {
    "u": "you", "r": "are", "ur": "your", "pls": "please", "plz": "please", "plez": "please", "pleez": "please",
    "thx": "thanks", "thnx": "thanks", "tnx": "thanks", "ty": "thank you", "tysm": "thank you", "thanx": "thanks",
    "nvm": "never mind", "nevermind": "never mind", "wat": "what", "wot": "what", "wht": "what", "k": "ok",
    "kk": "ok", "okey": "okay", "np": "no problem", "cya": "see you", "gn": "good night", "im": "I'm", "pls.": "please", "b4": "before", "rn": "right now", "cud": "could",
    "wud": "would", "cn": "can", "abt": "about", "bc": "because", "tmrw": "tomorrow", "thru": "through",
    "bedrm": "bedroom", "livingroom": "living room", "lvngroom": "living room", "diningroom": "dining room",
    "bathrm": "bathroom", "kitchn": "kitchen", "rm": "room", "frnt": "front", "nxt": "next", "tbl": "table",
    # the small words typed in a hurry (letters swapped or left out)
    "teh": "the", "hte": "the", "wher": "where", "whre": "where", "wehre": "where", "hwere": "where",
    "waht": "what", "waht's": "what's", "cna": "can", "yuo": "you", "fnd": "find", "fidn": "find", "adn": "and",
    "taht": "that", "thier": "their", "pleae": "please", "plase": "please", "pleas": "please",
    "wich": "which", "whcih": "which", "blu": "blue", "gren": "green", "whit": "white",
    "hav": "have", "hve": "have", "ahve": "have", "sen": "seen", "yu": "you", "yor": "your",
    "chek": "check", "chk": "check", "chekc": "check", "coffe": "coffee", "cofee": "coffee", "tabel": "table",
    "tabl": "table", "bedrom": "bedroom", "couh": "couch", "cuch": "couch",
    # places typed short ("the rnd table in the innr hall", "thru the livng rm")
    "rnd": "round", "innr": "inner", "livng": "living", "lvng": "living", "bdrm": "bedroom", "offce": "office",
    "thats": "that's",
}
#: after these a "2" is "to" and a "4" is "for" ("go 2 the kitchen", "look 4 my keys"); "2 steps" stays a number
_NUMBER_WORD_NEXT = r"(?=\s+(?:the|my|your|our|his|her|it|me|him|them|there|here|a|an|bed|kitchen|bedroom|office)\b)"


#: prepositions as second-language speakers often put them → the English ones
SECOND_LANGUAGE = ((r"\bnear of\b", "near"), (r"\bnext of\b", "next to"), (r"\bbeside of\b", "beside"),
                   (r"\bbehind of\b", "behind"), (r"\bclose of\b", "close to"), (r"\binside of\b", "inside"),
                   (r"\bin front the\b", "in front of the"), (r"\bnear to\b", "near"),
                   (r"\bin the front of\b", "in front of"))


#: words people write apart that the vocabulary knows joined ("a six sided table")
WRITTEN_APART = ((r"\bsix sided\b", "six-sided"), (r"\bsix side\b", "six-sided"))


def expand_shorthand(text: str) -> str:
    """``text`` with chat shorthand written out ("pls check bedrm 4 my keys" → "please check
    bedroom for my keys"): the words of :data:`SHORTHAND`, "2"/"4" before a determiner or a
    place, the prepositions of :data:`SECOND_LANGUAGE` ("near of the bed" → "near the
    bed"), and a closing "and wait there" (the robot waits where a task ends). Everything else
    is left as typed."""
    def word(m: re.Match) -> str:
        return SHORTHAND.get(m.group(0).lower(), m.group(0))

    out = re.sub(r"(?<![\w'’])[A-Za-z][A-Za-z0-9.]*(?![\w'’])", word, text or "")
    out = re.sub(r"(?<![\w.])2" + _NUMBER_WORD_NEXT, "to", out)
    out = re.sub(r"(?<![\w.])4" + _NUMBER_WORD_NEXT, "for", out)
    for pattern, english in (*SECOND_LANGUAGE, *WRITTEN_APART):  # "go near of the bed", "six sided"
        out = re.sub(pattern, english, out, flags=re.IGNORECASE)
    # "go to the couch and wait there": the robot waits where a task ends anyway
    return re.sub(r"(?<=\w)[ ,]+and (?:wait|stay)(?: (?:there|here))?(?: (?:for me|please))*\s*([.!?]*)\s*$", r"\1",
                  out, flags=re.IGNORECASE)

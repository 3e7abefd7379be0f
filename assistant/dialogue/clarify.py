"""Understanding the answer to "which one?" in context, and the robot's progress sentences and
activity phrases."""

from __future__ import annotations

import re
from dataclasses import dataclass

from assistant.app import known_object_names
from assistant.dialogue.intents import ordinal_choice
from assistant.grounding.objects import article, is_object_word, object_phrase, plural
from assistant.grounding.vocabulary import furniture_category

#: furniture words the robot can be told an unknown word stands for
FURNITURE_CHOICES = ("table", "chair", "couch", "bed")


def choose_option(norm: str, options: list[dict], parse) -> int | None:
    """Index of the option an answer picks, or None. ``options``: ``{"phrase": "on the table in
    front of the couch", …}`` in the order they were offered; ``parse()`` gives the answer's
    grounded plan (called only when no ordinal was said). Tried in order: an ordinal ("the
    second", "the last one"); the reference of a grounded node ("the one with the chairs" →
    ``chair-beside-table`` → the single option naming a chair; when several do, the direction);
    the single option sharing most content words with the answer (its phrase and its model's
    name: "the hexagon one")."""
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
    named = [ph + " " + str(o.get("model") or "").lower() for ph, o in zip(phrases, options)]
    scores = [len(content & set(re.findall(r"[a-z]+", ph))) for ph in named]
    best = max(scores) if scores else 0
    if best > 0 and scores.count(best) == 1:
        return scores.index(best)
    return None


def options_named(norm: str, options: list[dict], parse) -> list[int]:
    """The options whose phrase names a reference of the answer's grounded plan, or else a
    furniture word of the answer ("the one near the sofa" → the options by the couch), in
    order; [] when none."""
    phrases = [o["phrase"].lower() for o in options]
    said = [w for w in map(furniture_category, norm.split()) if w is not None]
    for ref in [*(str(n).split("-")[0] for n in parse().nodes), *said]:
        if ref in ("room", "move", "robot"):
            continue
        hits = [k for k, ph in enumerate(phrases) if re.search(rf"\b{ref}s?\b", ph)]
        if hits:
            return hits
    return []


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
    if name == "search_room":
        return f"Looking in the {data.get('room')}."
    if name == "room_skipped":
        return f"I can't get into the {data.get('room')} — skipping it."
    return None


def activity_phrase(name: str, data: dict) -> str | None:
    """What the robot is doing after one executor event, for the chat's ticking status line
    ("searching the kitchen"; None: the event changes nothing). Shown, never spoken: the
    sentences the robot says are :func:`progress_sentence`'s."""
    room = data.get("room")
    if name == "search_room":
        return f"going to the {room}"
    if name == "entered":
        return f"in the {room}"
    if name == "vantage":
        return f"looking around the {room}"
    if name == "better_view":
        return "moving for a better look"
    if name == "look_again":
        return "taking another look"
    if name == "move_to":
        return "moving into place"
    return None


#: words that single out no option (a furniture word does: "the one by the table" among couches; a
#: word every option has, such as "table" among tables, adds the same to each)
_STOP = {"the", "one", "with", "that", "this", "near", "next", "and", "its", "it", "is", "on", "of", "to",
         "by", "in", "at", "a", "an", "please", "which"}


# ---------------------------------------------------------------------- furniture words
@dataclass(frozen=True)
class Mention:
    """A furniture word in a command: ``said`` as typed ("dresser", "coffee table"),
    ``category`` the word the grounding reads it as ("table"; None when it knows no such
    furniture), ``here`` whether anything in this home is called that, ``models`` the catalogue
    models of this home the words name ("coffee table"; empty for a bare category word)."""

    said: str
    category: str | None
    here: bool
    models: tuple[str, ...] = ()


def furniture_mentions(tokens, pos, world, scene: str) -> list[Mention]:
    """The furniture words of a command (tokens as the language layer split and tagged them).

    A word counts when the tagger calls it furniture (``FUR``) or the grounding vocabulary knows
    it as furniture. Two-word names are read together: a model of this home ("hexagon table",
    "blue chair") or a phrase of the vocabulary ("coffee table", "night stand").
    """
    from assistant.grounding.vocabulary import FURNITURE_WORDS, PHRASES, SYNONYMS

    items = world.scene(scene).furniture
    models = {f.model.lower() for f in items}
    words_here = {f.word for f in items} | {m.split()[-1] for m in models} | {m for m in models if " " not in m}
    words = [str(t).lower() for t in tokens]
    tags = [str(p) for p in pos]
    out: list[Mention] = []
    i = 0
    while i < len(words):
        w = words[i]
        two = f"{w} {words[i + 1]}" if i + 1 < len(words) else None
        if two is not None and (two in models or (w, words[i + 1]) in PHRASES):
            canonical = PHRASES.get((w, words[i + 1]), words[i + 1])
            category = FURNITURE_WORDS.get(canonical)
            here = two in models or canonical in words_here
            out.append(Mention(two, category, here, (two,) if two in models else ()))
            i += 2
            continue
        canonical = SYNONYMS.get(w, w)
        singular = canonical[:-1] if canonical.endswith("s") and canonical[:-1] in FURNITURE_WORDS else canonical
        if (tags[i] if i < len(tags) else "NN") == "FUR" or singular in FURNITURE_WORDS:
            category = FURNITURE_WORDS.get(singular)
            here = singular in words_here or singular in FURNITURE_CHOICES and category is not None \
                and any(f.word == category for f in items) or w in words_here
            named = tuple(m for m in models if m == singular)
            out.append(Mention(w, category, bool(here), named))
        i += 1
    return out


def unused_mentions(mentions: list[Mention], plan) -> list[Mention]:
    """Known furniture words the plan does not use (no node has their category as target or
    reference): the plan dropped part of what was said."""
    used = set()
    for n in plan.nodes:
        used.add(n.target)
        used.update(r for r, _ in n.pairs)
    return [m for m in mentions if m.here and m.category is not None and m.category not in used]


def model_choice(mentions: list[Mention], items) -> object | None:
    """The single furniture item whose model a mention names ("the hexagon table"), or None."""
    for m in mentions:
        if not m.models:
            continue
        hits = [f for f in items if f.model.lower() in m.models]
        if len(hits) == 1:
            return hits[0]
    return None


def distinct_phrases(world, scene: str, items) -> list[str]:
    """"the one by the table", "the one nearer the bedroom door" … — phrases that tell furniture
    of one kind apart when the describer's phrases do not (chairs, couches: nothing is put on
    them, so their description says little). Tried in order: the nearest other furniture's
    word, if it differs between the items; for two items, which is nearer the room's nearest
    door; else "the first one" … counted from the west (smallest x)."""
    others = [f for f in world.scene(scene).furniture if f not in items]

    def nearest(item):
        near = [f for f in others if f.room == item.room and f.word != item.word] or others
        return min(near, key=lambda f: (f.x - item.x) ** 2 + (f.y - item.y) ** 2) if near else None

    refs = [nearest(i) for i in items]
    words = [r.word if r is not None else None for r in refs]
    if None not in words and len(set(words)) == len(words):
        return [f"the one by the {w}" for w in words]
    doors = world.floorplan.doors_of(items[0].room)
    if len(items) == 2 and doors:
        cx = sum(i.x for i in items) / 2.0
        cy = sum(i.y for i in items) / 2.0
        door = min(doors, key=lambda d: (d.centre[0] - cx) ** 2 + (d.centre[1] - cy) ** 2)
        d = [(i.x - door.centre[0]) ** 2 + (i.y - door.centre[1]) ** 2 for i in items]
        if abs(d[0] - d[1]) > 0.25:
            near = 0 if d[0] < d[1] else 1
            name = door.name if "door" in door.name else f"{door.name} door"
            out = ["", ""]
            out[near] = f"the one nearer the {name}"
            out[1 - near] = f"the one further from the {name}"
            return out
    order = sorted(range(len(items)), key=lambda k: items[k].x)
    ordinal = ["first", "second", "third", "fourth", "fifth", "sixth"]
    out = [""] * len(items)
    for rank, k in enumerate(order):
        out[k] = f"the {ordinal[min(rank, 5)]} one from the west"
    return out


#: someone else's thing in a question, the apostrophe gone ("where is johns phone", "wheres
#: grandmas glasses"): groups ``owner`` (with its "s") and ``thing``; an owner never ends in "ss"
#: ("the cordless phone" is nobody's)
OWNED = (r"\b(?:where(?:s| is| are| r| was| were| did)?|seen|find|found|lost|misplaced|with) "
         r"(?:my |our |the )?(?P<owner>(?!(?:is|was|has|does|its|this|his|hers|yours|ours|theirs|whats|thats)\b)"
         r"[a-z]+[a-rt-z]s) (?P<thing>(?!(?:is|are|in|on|at|by|the|my|a|an)\b)[a-z]+(?: [a-z]+)?)$")


def owner_phrase(norm: str) -> str | None:
    """Whose thing a question asks about, as the reply says it: "John's", "Grandma's", "his",
    "her", "their"; None for the person's own ("my", or no owner said)."""
    m = re.search(OWNED, norm)
    if m is not None and not is_object_word(m.group("owner")) and not is_object_word(
            f"{m.group('owner')} {m.group('thing')}"):  # "my glasses case" is nobody's
        from assistant.world.catalogue import load_catalogue

        said = f"{m.group('owner')} {m.group('thing')}"
        if known_spelling(said, sorted(load_catalogue().object_words())) is None:  # "my glases case" neither
            return m.group("owner")[:-1].capitalize() + "'s"
    m = re.search(r"\b(his|her|their)\b (?=[a-z]+(?: [a-z]+)?$)", norm)
    return m.group(1) if m else None


def named_object(norm: str, world, plan_object: str | None = None) -> tuple[str | None, str | None]:
    """(the known object the words name, or None; the unknown noun asked about, or None):
    what "where is my …" asks for. Any noun phrase can name a thing (issue 16)."""
    known = sorted(known_object_names(world), key=len, reverse=True)
    padded = f" {norm} "
    for k in known:
        if f" {k} " in padded or f" {k}s " in padded:
            return k, None
    if plan_object:
        return plan_object, None
    # what a thing is for is not the thing: "the clicker for the telly", "the keys to the car"
    # ("the table next to the bed" is a place: "next to" is no purpose)
    norm = re.sub(r"^(.*\b(?:my|the|our|his|her|a|an) [a-z]+(?: (?!(?:next|close|closest|up|right|left|back)\b)[a-z]+)?)"
                  r" (?:for|to) (?:the|my|our|his|her) [a-z]+(?: [a-z]+)?$", r"\1", norm)
    # someone else's thing, the apostrophe gone: "wheres grandmas glasses", "where is moms phone"
    owner = re.search(OWNED, norm)
    if owner is not None:
        norm = f"the {owner.group('thing')}"
    m = re.search(r"\b(?:my|the|your|our|his|her|their|a|an|some|any) ([a-z]+(?: [a-z]+)?)$", norm) or \
        re.search(r"\b(?:my|the|your|our|his|her|their|a|an|some|any) ([a-z]+)\b", norm)
    if m:
        noun = re.sub(r"\b(is|are|now|please|again|then|gone|at|in|on|anywhere|somewhere|everywhere|around|"
                      r"lately|recently|today|yesterday|here|there|too|at all)\b", "", m.group(1)).strip()
        # read after a determiner, as said: "my hearing aid" is one compound noun
        found = object_phrase(["the", *noun.split()], ["DT", *["NN"] * len(noun.split())]) if noun else None
        meant = None
        if found is not None:  # "wheres my lapptop": the laptop; "my glasess": the glasses
            from assistant.world.catalogue import load_catalogue

            words = load_catalogue().object_words()  # every object's name and other words → its name
            meant = known_spelling(noun, known) or words.get(known_spelling(noun, sorted(words)) or "")
        if meant is not None:
            return meant, None
        if found is not None:  # any thing can be asked about (issue 16)
            said = plural(found.kind)  # a thing the catalogue does not know keeps its number: "my slippers"
            return (said if noun.split()[-1] == said.split()[-1] else found.kind), None
        return None, noun or None
    return None, None


def known_spelling(noun: str, known) -> str | None:
    """The known object name a typed noun misspells ("lapptop" → "laptop", "glases case" →
    "glasses case"), or None: the same first letter, one edit away (two from 8 letters on),
    5 letters or more (a shorter word one edit from a name is as often another word: "boot"),
    and not the plural or another longer word of a known name ("laptops"). A short word with a
    letter typed twice is one too: "mugg" is the mug, "keyys" the keys."""
    from rapidfuzz import process
    from rapidfuzz.distance import OSA

    if len(noun) < 5:
        undoubled = [noun[:i] + noun[i + 1:] for i in range(1, len(noun)) if noun[i] == noun[i - 1]]
        return next((name for name in known if name in undoubled), None)
    limit = 2 if len(noun) >= 8 else 1
    for name, _, _ in process.extract(noun, list(known), scorer=OSA.distance, score_cutoff=limit, limit=5):
        if name[0] == noun[0] and noun not in (name + "s", name + "es"):  # "wallett" is a wallet, "laptops" no
            return name
    return None


def fetch_command_text(obj: str | None, phrase: str | None, room: str | None) -> str:
    """The fetch command a clarified request stands for ("bring me the mug from the table … in
    the bedroom")."""
    place = re.sub(r"^(on|at|by) ", "", phrase or "").strip()
    parts = [f"bring me the {obj}" if obj else "go"]
    if place and obj and (phrase or "").startswith("on "):  # "on the bed": what it lies on
        parts.append(f"on {place}")
    elif place:
        parts.append(f"from {place}" if obj else f"to {place}")
    if room:
        parts.append(f"in the {room}")
    return " ".join(parts)


#: words that put a piece of furniture after them ("on the …", "next to the …", "go to the …")
PLACE_PREPOSITIONS = frozenset({"on", "onto", "by", "near", "to", "at", "beside", "behind", "under", "from", "into",
                                "towards", "toward", "of", "past", "in", "inside", "off", "around", "between", "and"})
#: words that may stand between the preposition and the furniture word
_SLOT_DETERMINERS = frozenset({"the", "a", "an", "my", "your", "our", "his", "her", "that", "this", "their"})


def in_place_slot(tokens: list[str], word: str) -> bool:
    """Whether ``word`` (lower case) stands where a piece of furniture would in the tokens:
    after a determiner (and at most two describing words) that follows a place preposition —
    "by the old wardrobe", "next to my dresser", "go to the sideboard". A word elsewhere ("my
    mom keeps her glasses …", "if she asks for …") is not a place the person named."""
    for i, token in enumerate(tokens):
        if token != word:
            continue
        j = i - 1
        while j >= 0 and i - j <= 3 and tokens[j] not in _SLOT_DETERMINERS and tokens[j] not in PLACE_PREPOSITIONS:
            j -= 1
        if j >= 1 and tokens[j] in _SLOT_DETERMINERS and tokens[j - 1] in PLACE_PREPOSITIONS:
            return True
    return False


#: prepositions after which a place word without a determiner gets "the" ("go to couch")
_ARTICLE_PREPOSITIONS = r"to|into|towards|toward|on|onto|near|beside|behind|by|of|in|inside|at|from|under"
#: verbs of going straight before a place ("go kitchen" → "go to the kitchen")
_GO_VERBS = r"go|come|walk|head|drive|move|run|roll"


def with_articles(text: str, heads: frozenset[str]) -> str:
    """``text`` with "the" put before a place said without a determiner, as people writing a
    second language or on a phone do: "go to couch" → "go to the couch", "go kitchen" → "go to
    the kitchen", "in front of blue chair" → "in front of the blue chair". A place is a word of
    ``heads`` (this home's room words, furniture and describing words) or one letter off one of
    5 letters or more, written right ("go to bedrom" → "go to the bedroom"; also after "the"). The
    chunker learned places from sentences that always had the article; without it "go to couch"
    was "I don't know the word 'couch'"."""
    def head(word: str) -> str | None:
        """The place word ``word`` is, spelt right; None if it is none."""
        w = word.lower()
        return w if w in heads else known_spelling(w, heads)

    def after_preposition(m: re.Match) -> str:
        found = head(m.group(2))
        return f"{m.group(1)} the {found}" if found else m.group(0)

    def after_verb(m: re.Match) -> str:
        found = head(m.group(2))
        return f"{m.group(1)} to the {found}" if found else m.group(0)

    def after_the(m: re.Match) -> str:
        found = head(m.group(2))
        return f"{m.group(1)} {found}" if found and found != m.group(2).lower() else m.group(0)

    out = re.sub(rf"\b({_ARTICLE_PREPOSITIONS})\s+([A-Za-z]+)\b", after_preposition, text, flags=re.IGNORECASE)
    out = re.sub(rf"\b({_GO_VERBS})\s+([A-Za-z]+)\b", after_verb, out, flags=re.IGNORECASE)
    return re.sub(r"\b(the|my|your)\s+([A-Za-z]{5,})\b", after_the, out, flags=re.IGNORECASE)

"""What the robot expects to hear: sentences and words for the recogniser's language model.

The text comes from three places, so that the recogniser knows the home and the way people
talk about it:

* the annotated corpus (``corpus/descriptions.xml``: how people describe where things are);
* the homes: the room names, furniture words and models, and the objects of every packaged
  world (and of the world in use), put into command templates ("where is my mug", "bring me
  the laptop from the bedroom", "the fork is on the table in front of the couch");
* the dialogue's control phrases (stop, cancel, repeat that, yes, no …), everyday rooms and
  furniture the homes lack (kitchen, wardrobe …), and everyday
  household objects (wallet, keys, phone …) so "where is my wallet" is heard as said, even
  though the robot does not know that object (it then says so).

Test sentences (the fetch dev set, the dialogue scripts) are **not** in the text: the speech
evaluation measures recognition on sentences the model has not seen. Their words are not
added either. Words the recogniser's dictionary lacks are dropped (and counted).
"""

from __future__ import annotations

import hashlib
import re
from dataclasses import dataclass
from pathlib import Path

#: everyday things people lose at home (the open part of "where is my X")
HOUSEHOLD_OBJECTS = (
    "wallet", "keys", "key", "phone", "glasses", "remote", "remote control", "book", "bag", "purse",
    "umbrella", "hat", "coat", "jacket", "shoes", "slippers", "watch", "ring", "pen", "pencil",
    "notebook", "tablet", "charger", "headphones", "cup", "glass", "plate", "bowl", "spoon", "knife",
    "bottle", "medicine", "pills", "newspaper", "magazine", "letter", "scissors", "tape", "blanket",
    "pillow", "towel", "toy", "ball", "camera", "lamp", "clock", "vase", "box", "basket", "hairbrush",
    "comb", "gloves", "scarf", "backpack", "passport", "ticket", "card", "money", "coins", "sweater",
    "teddy bear", "hearing aid", "walking stick", "cane", "keyboard", "mouse", "speaker", "radio",
)

#: rooms people name that the packaged homes lack ("go to the kitchen" is then heard as said,
#: and the robot can answer that this home has no kitchen)
HOUSEHOLD_ROOMS = (
    "kitchen", "bathroom", "dining room", "garage", "laundry room", "basement", "attic", "guest room",
    "study", "den", "porch", "balcony", "closet", "pantry", "family room", "lounge", "hall",
    "entrance", "corridor", "toilet", "spare room", "playroom", "nursery", "utility room",
)

#: furniture people name that the packaged homes lack (heard as said, then asked about:
#: "I don't know the word 'credenza' — is it a table …?")
HOUSEHOLD_FURNITURE = (
    "armchair", "wardrobe", "cabinet", "cupboard", "bookshelf", "bookcase", "sideboard", "credenza",
    "ottoman", "stool", "bench", "counter", "kitchen counter", "chest of drawers", "end table",
    "side table", "dining table", "kitchen table", "night table", "bedside table", "tv stand",
    "piano", "fridge", "refrigerator", "oven", "sink", "windowsill", "fireplace", "recliner",
    "footstool", "coat rack", "filing cabinet", "drawer", "cot", "crib", "futon", "loveseat",
)

#: commands over an everyday room ({r}) or piece of furniture ({f}), with a home's object ({o})
EVERYDAY_TEMPLATES = (
    "go to the {r}", "go into the {r}", "bring me the {o} from the {r}", "the {o} is in the {r}",
    "the {o} is on the {f}", "bring me the {o} from the {f}", "get my {o} from the {f} in the {r}",
    "the {o} is on the {f} in the {r}", "my {o} is on the {f} next to the {f}",
)

#: how many times more often the home's objects appear in the templates than everyday objects
KNOWN_WEIGHT = 5

#: how many times the control phrases are repeated in the model text
CONTROL_WEIGHT = 60

#: what people say to the dialogue outside commands (see :mod:`assistant.dialogue.intents`)
CONTROL_PHRASES = (
    "stop", "stop now", "stop it", "please stop", "halt", "wait", "hold on", "cancel", "never mind",
    "forget it", "abort", "repeat that", "say that again", "what did you say", "pardon", "help",
    "help me", "what can you do", "what can i say", "which home am i in", "where am i",
    "which rooms are there", "start over", "start again", "reset", "yes", "yes please", "yeah",
    "sure", "okay", "ok", "go ahead", "do it", "please do", "correct", "right", "no", "no thanks",
    "no thank you", "nope", "not now", "thank you", "thanks", "hello", "hi", "hello robot",
    "good morning", "good job", "well done", "let me show you", "let me show you what in front of the couch means",
    "watch me", "the one with the chairs", "the first one", "the second one", "the third one",
    "the other one", "the big one", "the small one", "the one by the bed", "the one next to the couch",
)

#: what people say to move the robot itself, ask about the home and ask for things with no place
#: (grounding.motion, dialogue.inventory, the "want" and "no_arm" intents), over an object
#: ({o}), a room ({r}) and a furniture word ({f}); weighted :data:`ROBOT_WEIGHT`
ROBOT_TEMPLATES = (
    "turn left", "turn right", "turn around", "turn back", "spin around", "go forward", "move forward",
    "go straight ahead", "keep going", "back up", "back up a little", "reverse a bit", "move back one meter",
    "go forward two meters", "move forward one meter and then turn right", "turn left ninety degrees",
    "turn right forty five degrees", "turn slightly to the left", "take two steps forward", "take a step back",
    "move left a bit", "take a left", "make a right", "face the other way",
    "what's in the {r}", "what furniture is in the {r}", "is there a {f} in the {r}", "are there any {fs} here",
    "how many {fs} are in the {r}", "how many {fs} are there", "go to the {f}", "take me to the {f}",
    "where is the {f}", "where is the {r}", "i need my {o}", "can i have my {o}", "give me my {o}",
    "what did you see", "what do you remember", "i don't know", "anywhere", "search everywhere",
    "put the {o} on the {f}", "pick up the {o}", "open the door", "can you carry the {o}",
    # yes-or-no place questions, places told, corrections, carrying on, a fall (3 Dec)
    "is my {o} in the {r}", "is the {o} on the {f}", "did i leave my {o} in the {r}", "is it in the {r}",
    "could my {o} be in the {r}", "where should i put my {o}", "remember that my {o} is on the {f} in the {r}",
    "i put my {o} on the {f} next to the bed", "what else is on the {f}", "is there anything on the {f}",
    "no the other one", "not that {f}", "wrong one", "try the other {f}", "sorry i meant the {r}",
    "it's on the {f} by the chair", "where did you see it", "which room is it in", "where exactly",
    "can you bring it to me", "take me to it", "how do i get there", "hang on stop please", "carry on",
    "ok you can carry on now", "no no come back", "help i've fallen and i can't get up", "call my daughter",
    "how are you today", "are you listening", "good robot", "not right now thanks",
)
#: how many times each of :data:`ROBOT_TEMPLATES`' sentences is in the model text
ROBOT_WEIGHT = 8

#: command templates over an object ({o}), a room ({r}) and a furniture word ({f})
OBJECT_TEMPLATES = (
    "where is my {o}", "where is the {o}", "where's my {o}", "have you seen my {o}",
    "where did i leave my {o}", "where did i put the {o}", "do you know where my {o} is",
    "how do i get to my {o}", "how do i find the {o}", "find my {o}", "bring me my {o}",
    "bring me the {o}", "get me the {o}", "can you get my {o}", "fetch the {o}",
)
PLACE_TEMPLATES = (
    "go to the {r}", "go into the {r}", "enter the {r}", "head into the {r}", "walk into the {r}",
    "bring me the {o} from the {r}", "the {o} is in the {r}", "the {o} is on the {f} in the {r}",
    "go to the {r} the {o} is on the {f}", "my {o} is on the {f} in front of the couch",
    "the {o} is on the {f} next to the bed", "the {o} is on the {f} between the chairs",
    "the {o} is on the {f} to the left of the {f}", "the {o} is on the {f} to the right of the {f}",
    "the {o} is on the {f} behind the couch", "the {o} is on the {f} beside the chair",
)


#: the parts of a "where it is" command (written by us from the spatial relations of the RDT
#: model, dissertation 4.3; generic English, not sentences of any test set)
MOTIONS = ("go to the {r}", "go into the {r}", "head into the {r}", "walk into the {r}", "enter the {r}",
           "in the {r}", "go in the {r}", "turn left into the {r}", "turn right into the {r}",
           "go to the {r} and turn left", "go into the {r} and turn right", "enter the {r} turn left",
           "go into the {r} turn right and go forward", "walk straight ahead into the {r}",
           "go into the {r} and go straight ahead", "go into the {r} and walk past the couch",
           "go into the {r} walk up to the far wall and turn left", "go to the {r} and take a right")
SUBJECTS = ("the {o} is", "my {o} is", "the {o} is sitting", "your {o} is", "i left the {o}", "i think the {o} is")
SIZES = ("", "small", "big", "little", "round", "square", "long", "wooden", "low", "large")
RELATIONS = ("in front of the {f}", "behind the {f}", "beside the {f}", "next to the {f}", "by the {f}",
             "to the left of the {f}", "to the right of the {f}", "on the left side of the {f}",
             "on the right side of the {f}", "between the {f} and the {f}", "between the two chairs",
             "near the {f}", "across from the {f}", "across the room from the {f}", "at the end of the {f}",
             "with the chairs around it", "with the {f}", "against the wall", "in the corner",
             "in the middle of the room", "at the far end of the room", "at the back on the left",
             "on your left", "on your right", "ahead of you", "there", "right next to the {f}",
             "right behind the {f}", "opposite the {f}")


@dataclass(frozen=True)
class SpeechVocabulary:
    """The language-model text: ``sentences`` (one utterance each, lower case, words separated
    by single spaces) and ``phrases`` (the short phrase list a grammar-based engine takes)."""

    sentences: tuple[str, ...]
    phrases: tuple[str, ...]

    @property
    def words(self) -> list[str]:
        return sorted({w for s in self.sentences for w in s.split()})

    @property
    def key(self) -> str:
        """A hash of the text: caches built from it are rebuilt when it changes."""
        digest = hashlib.sha1("\n".join(self.sentences).encode("utf-8"))
        return digest.hexdigest()[:16]

    def restricted(self, known) -> tuple["SpeechVocabulary", list[str]]:
        """Only sentences whose words all satisfy ``known(word)``; and the words left out."""
        missing = sorted({w for s in self.sentences for w in s.split() if not known(w)})
        bad = set(missing)
        keep = tuple(s for s in self.sentences if not (set(s.split()) & bad))
        phrases = tuple(p for p in self.phrases if not (set(p.split()) & bad))
        return SpeechVocabulary(keep, phrases), missing


def spoken_form(tokens) -> str:
    """Corpus tokens → the words a speaker says: clitics joined ("you 'll" → "you'll"), the
    corpus's split words joined ("gon na" → "gonna"), punctuation dropped, lower case."""
    out: list[str] = []
    for token in tokens:
        t = token.lower()
        if (t.startswith("'") or t == "n't") and out:
            out[-1] += t
        elif t == "na" and out and out[-1] in ("gon", "wan"):
            out[-1] += t
        else:
            out.append(t)
    text = " ".join(out)
    return normalise_transcript(text)


def normalise_transcript(text: str) -> str:
    """Lower case, punctuation other than in-word apostrophes removed, single spaces: the form
    word error is counted on."""
    text = text.lower().replace("’", "'")
    text = re.sub(r"[^a-z0-9' ]+", " ", text)
    text = re.sub(r"(?<![a-z])'|'(?![a-z])", " ", text)
    return " ".join(text.split())


def home_words(world=None) -> dict[str, list[str]]:
    """Rooms, furniture words and objects of the packaged homes (and of ``world``)."""
    from assistant.generation import known_objects
    from assistant.world import load_world
    from assistant.world.catalogue import load_catalogue
    from assistant.world.worldfile import world_names

    worlds = [load_world(name) for name in world_names()]
    if world is not None:
        worlds.append(world)
    rooms = sorted({r for w in worlds for r in w.floorplan.room_names})
    catalogue = load_catalogue()
    furniture = {"table", "chair", "couch", "sofa", "bed", "desk", "nightstand", "dresser", "shelf"}
    furniture.update(catalogue.category_words.values())
    furniture.update(m.name for m in catalogue.models.values())
    objects = sorted(set(known_objects(world)) | set(catalogue.objects))
    return {"rooms": rooms, "furniture": sorted(furniture), "objects": objects}


def corpus_sentences(paths=None) -> list[str]:
    """The annotated corpus's descriptions in spoken form (default: the repository's corpus)."""
    from assistant.language.corpus import read_corpora

    if paths is None:
        from assistant.language.corpus import repo_root

        paths = [Path(repo_root()) / "corpus" / "descriptions.xml"]
    result = read_corpora(paths)
    return [s for s in (spoken_form(word for word, _ in d.tagged_words()) for d in result.descriptions) if s]


def template_sentences(words: dict[str, list[str]]) -> list[str]:
    """The command templates filled with the home's words and the household objects."""
    known = words["objects"]
    others = [o for o in HOUSEHOLD_OBJECTS if o not in known]
    # the home's objects weigh KNOWN_WEIGHT times an everyday object: heard as themselves first
    out = [t.format(o=o) for o in known for t in OBJECT_TEMPLATES] * KNOWN_WEIGHT
    out += [t.format(o=o) for o in others for t in OBJECT_TEMPLATES]
    for i, r in enumerate(words["rooms"]):
        for j, t in enumerate(PLACE_TEMPLATES):
            # a fixed rotation over objects and furniture keeps the text small and deterministic
            o = known[(i + j) % len(known)]
            for k, f in enumerate(words["furniture"]):
                if "{f}" in t or k == 0:
                    out.append(t.format(o=known[(i + j + k) % len(known)] if "{f}" in t else o, r=r, f=f))
    return [normalise_transcript(s) for s in out]


def everyday_sentences(words: dict[str, list[str]]) -> list[str]:
    """:data:`EVERYDAY_TEMPLATES` over the rooms and furniture of :data:`HOUSEHOLD_ROOMS` and
    :data:`HOUSEHOLD_FURNITURE` the homes lack, each once per template, with the homes' objects
    in a fixed rotation: a little weight, so the homes' own words are still heard first."""
    known = words["objects"]
    rooms = [r for r in HOUSEHOLD_ROOMS if r not in words["rooms"]]
    furniture = [f for f in HOUSEHOLD_FURNITURE if f not in words["furniture"]]
    out = []
    for j, t in enumerate(EVERYDAY_TEMPLATES):
        for i in range(max(len(rooms), len(furniture)) if "{f}" in t else len(rooms)):
            out.append(t.format(o=known[(i + j) % len(known)], r=rooms[i % len(rooms)],
                                f=furniture[i % len(furniture)]))
    return [normalise_transcript(s) for s in out]


def clause_sentences(words: dict[str, list[str]], count: int = 12000) -> list[str]:
    """Commands built from :data:`MOTIONS`, :data:`SUBJECTS`, :data:`SIZES` and :data:`RELATIONS`
    over the home's rooms, objects and furniture: ``count`` of them, picked by fixed strides
    through the combinations so that every part appears and the text is the same every time."""
    rooms, objects = words["rooms"], words["objects"]
    furniture = [f for f in words["furniture"] if len(f.split()) <= 2]
    out = []
    for n in range(count):
        room, obj = rooms[n % len(rooms)], objects[(n // 3) % len(objects)]
        fur, other = furniture[(n * 7) % len(furniture)], furniture[(n * 11 + 3) % len(furniture)]
        size = SIZES[(n * 5) % len(SIZES)]
        subject = SUBJECTS[(n * 3) % len(SUBJECTS)].format(o=obj)
        relation = RELATIONS[(n * 13) % len(RELATIONS)].format(f=other)
        clause = f"{subject} on the {size + ' ' if size else ''}{fur} {relation}"
        motion = MOTIONS[(n * 17) % len(MOTIONS)].format(r=room)
        out.append(clause if n % 4 == 0 else f"{motion} {clause}")
    return [normalise_transcript(s) for s in out]


def robot_sentences(words: dict[str, list[str]]) -> list[str]:
    """:data:`ROBOT_TEMPLATES`, each over the home's rooms, furniture and objects in a fixed
    rotation (a template without a slot once)."""
    from assistant.grounding.objects import plural

    rooms, furniture, objects = words["rooms"], words["furniture"], words["objects"]
    out = []
    for t in ROBOT_TEMPLATES:
        count = max(len(rooms), len(furniture), len(objects)) if "{" in t else 1
        for i in range(count):
            f = furniture[i % len(furniture)]
            out.append(t.format(r=rooms[i % len(rooms)], f=f, fs=plural(f), o=objects[i % len(objects)]))
    return [normalise_transcript(s) for s in dict.fromkeys(out)]


def build_vocabulary(world=None, corpus_paths=None) -> SpeechVocabulary:
    """The sentences and phrases the recogniser's model is built from (see the module doc)."""
    words = home_words(world)
    sentences = (corpus_sentences(corpus_paths) + template_sentences(words) + everyday_sentences(words)
                 + clause_sentences(words))
    # short phrases said on their own: weighted so a sentence start does not drown them
    sentences += [normalise_transcript(p) for p in CONTROL_PHRASES] * CONTROL_WEIGHT
    sentences += robot_sentences(words) * ROBOT_WEIGHT
    phrases = [normalise_transcript(p) for p in CONTROL_PHRASES]
    phrases += [normalise_transcript(t.format(o=o)) for o in words["objects"] for t in OBJECT_TEMPLATES[:4]]
    phrases += words["rooms"] + words["furniture"]
    return SpeechVocabulary(tuple(sentences), tuple(dict.fromkeys(phrases)))

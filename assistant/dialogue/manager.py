"""The dialogue manager: one utterance in, one :class:`Turn` out.

Routing (deterministic, see :mod:`assistant.dialogue.intents`): control phrases (stop, cancel,
repeat, help, which home, start over) are answered at once; "where is my X" / "have you seen
my X" answers from the object memory first and otherwise from the generation layer (static
description), "how do I get to my X" with the dynamic description; "let me show you what
'in front of the couch' means" names the RDT node to record a demonstration of; everything else
goes to the grounding parser, and a plan with nodes, a room or an object is a fetch command.

A fetch runs in a worker thread (the simulator takes seconds); :meth:`DialogueManager.handle`
returns at once with "Going to the bedroom." and the worker reports progress through the
``say`` callback and ends with a final :class:`Turn` (:meth:`DialogueManager.wait`). "stop"
sets a flag that stops the robot at its next call (:class:`~assistant.dialogue.worker.TaskWorker`).

When the plan is ambiguous (several tables in the room, no reference to pick one) or
incomplete (no room), the manager asks instead of guessing and understands the answer in
context ("the one with the chairs", "the second", "never mind"). Unknown words are named back.
"""

from __future__ import annotations

import functools
import math
import re
import time
from dataclasses import dataclass

from assistant.dialogue.clarify import (FURNITURE_CHOICES, choose_option, distinct_phrases,
                                        fetch_command_text, furniture_mentions, model_choice, named_object,
                                        in_place_slot, options_named, owner_phrase, unused_mentions, with_articles)
from assistant.dialogue.intents import (FORGET_THING, NEW_REQUESTS, ON_FURNITURE, POLITE_WORDS, TOLD_CORRECTION,
                                        VAGUE_PHRASES, WANTED, Intent, classify,
                                        LEADING_NEVER_MIND, LEADING_THANKS, drop_courtesies, expand_shorthand, ordinal_choice, teach_phrase,
                                        told_place, told_places, where_check_parts)
from assistant.grounding.destination import LOOKS
from assistant.dialogue.inventory import ANYTHING, furniture_answer, furniture_asked, matching
from assistant.dialogue.distances import floor_distance_m, how_far_question, spoken_distance
from assistant.dialogue.memory import TOLD, TOLD_NOT_SEEN, ObjectMemory
from assistant.dialogue.nearby import RELATION_SIDES, SIDE_WORDS, furniture_by, near_question
from assistant.language.retractions import without_retractions
from assistant.app import known_object_names
from assistant.dialogue.services import Services, furniture_phrase
from assistant.dialogue.turns import HELP_TEXT, NUMBER_WORDS, SOCIAL_REPLIES, Turn
from assistant.dialogue.steps import STEP_BREAK, split_steps, step_place
from assistant.dialogue.turns import join_words as _join
from assistant.dialogue.replies import it_them, near, related_seen
from assistant.generation import is_are, some
from assistant.dialogue.worker import TaskWorker
from assistant.grounding.motion import describe_motion, is_motion_plan
from assistant.grounding.objects import article, is_object_word, plural, singular
from assistant.grounding.rooms import COMMON_ROOMS, ROOM_ALIASES, room_aliases, unknown_room_named
from assistant.grounding.vocabulary import FURNITURE_WORDS, NO_TARGET, STRUCTURE_REFERENCES, furniture_category
#: every other name of a room ("lounge", "study"): said as a thing, it is no thing
ROOM_ALIASES_SAID = frozenset(a for aliases in ROOM_ALIASES.values() for a in aliases)

#: a where-question about one place, before its name ("where's the", "how do I get to the")
PLACE_QUESTION = (r"(?:(?:and|so|ok|okay|um|robot) )*(?:where(?: is| are| s)?|wheres|how (?:do|can) i (?:get|go) to|"
                  r"which way (?:is|to)|where can i find|do you know where) (?:the |my |a |our |your )?")
#: an answer to "which room?" that leaves it to the robot
ANYWHERE = (r"\b(anywhere|everywhere|any room|dont know|do not know|no idea|not sure|no clue|search|look around|"
            r"all over|whole (home|house|flat|apartment|place)|you find it|somewhere)\b")
#: the start of a correction of the furniture the robot went to ("no, the other one", "wrong one")
CORRECTION = (r"^(?:(?:no|nope|nah|not that one|not that|not this one|wrong one|the wrong one|thats the wrong one|"
              r"wrong|sorry|oh|i meant|i mean|actually|i said|try|check|look at|go to)(?: |$))+|^(?=(?:the )?other\b)")
#: a request about the thing just talked of, said with "it" ("can you bring it to me?", "take me to it")
IT_REQUEST = (r"\b(bring|get|fetch|find|show) (me )?(it|them)\b|\b(take|lead|guide) me to (it|them)\b|"
              r"\b(go|drive) (to|and (get|find|check|look at)) (it|them)\b")
#: where the thing just talked of is, said with "it" ("it's on the table by the chairs", "no, they are in
#: the bedroom")
IT_IS_AT = (r"^(?:(?:no|sorry|oh|actually|well|i think|wrong room|wrong place)\b ?)*(?:its|it is|it should be|theyre|"
            r"they are|they should be) (?:probably |maybe |still |now )?(?P<place>(?:on|in|under|by|at|near|next to|"
            r"beside|behind|inside|in front of) [a-z ]+)$")
#: the most things "what did you see?" lists
SEEN_LIST_MAX = 4
#: words that ask for a thing (a fetch or a search), for a thing the catalogue does not know
REQUEST_WORDS = (r"\b(?:find|bring|get|fetch|look|looking|search|searching|where|need|want|grab|take|show|lost|"
                 r"misplaced|check|seen|locate|spot|give|hand|pass)\b")
#: when a told place was so, said after it ("… on the desk this morning"), dropped from the place
WHEN_SAID = (r"\s+(?:this (?:morning|afternoon|evening)|last night|tonight|yesterday(?: evening| morning)?|earlier"
             r"(?: today| on)?|today|just now|a (?:minute|moment|while) ago|an hour ago|(?:a few|some|two|ten) "
             r"minutes ago|before (?:lunch|dinner|breakfast|bed))$")
#: intents about the task under way, not to wait for its end (``about_the_task``)
DURING_TASK = frozenset({"stop", "cancel", "emergency", "status", "start_over", "command"})
#: who a told place may be of that is no thing to keep track of ("my son is in the living room")
PEOPLE_AND_PETS = frozenset({"son", "daughter", "wife", "husband", "mum", "mom", "mother", "dad", "father", "grandson",
                             "granddaughter", "grandma", "grandpa", "friend", "carer", "nurse", "neighbour", "neighbor",
                             "brother", "sister", "partner", "cat", "dog", "kitten", "puppy", "bird"})
#: an answer to "which one?" that leaves the choice to the robot ("you choose", "I don't know", "the nearest")
_ANY_ONE = (r"(?:(?:i )?(?:dont|do not) (?:know|mind|care)|dunno|not sure|no idea|either|either one|any|any one|anyone|"
            r"any of them|whichever|whichever one|whatever|you choose|you pick|your choice|you decide|up to you|"
            r"(?:it )?doesnt matter|(?:the )?(?:nearest|closest|near)(?: one)?)")
#: a place said and then the right one: "not the bedroom, the living room", "no, not the couch but the bed"
NOT_BUT = re.compile(r"^(?:(?:no|nope|sorry|oh)[ ,]+)*not (?:to )?(?:the |my |that )?[a-z]+(?: [a-z]+)?[ ,]+"
                     r"(?:but |i mean |i meant |rather )?(?P<right>(?:the|my|to|into|go|in|on)\b.*)$")


def _pointed(word: str, options: list[dict]) -> list[str]:
    """Which-question options said as "the one …" ("on the table by the bed" → "the one by the bed")."""
    return [re.sub(rf"^on the {re.escape(word)} ", "the one ", o["phrase"]) for o in options]


def _in_sentence(reply: str) -> str:
    """A reply of the robot's quoted inside a sentence: its first letter small, but "I" stays."""
    return reply if reply.startswith(("I ", "I'")) else reply[:1].lower() + reply[1:]


@dataclass(frozen=True)
class DistanceGoal:
    """A place asked "how far" about: how to say it ("the couch", "your mug"), where it is
    (``xy`` metres, world frame), its room, a note on where the place came from, the command
    that goes there, and the thing's name when it is one of the person's things."""

    name: str
    xy: tuple[float, float]
    room: str | None
    note: str = ""
    command: str | None = None
    object: str | None = None


def _lies_on(seen, piece) -> bool:
    """Whether a remembered thing lies on ``piece`` (a world furniture item): seen on it by its
    id, or — the robot's own furniture has the detector's ids — seen in its room within 0.9 m
    of its centre (``replies.near``)."""
    return seen.furniture == piece.id or (seen.room == piece.room and near(seen, piece, {}, 0.9))


def _bare_answer(norm: str) -> str:
    """An answer to one of the robot's questions without the hesitation before it and the
    courtesy after it: "um whatever, you choose please" → "whatever you choose"."""
    words = re.sub(r"^(?:(?:um|uh|er|well|oh|hmm|ok|okay|so) )+", "", norm)
    return re.sub(r"(?: (?:please|then|is fine|will do|thanks|i guess))+$", "", words)


def _capital(phrase: str) -> str:
    """A phrase starting a sentence: its first letter capital ("the couch" → "The couch")."""
    return phrase[:1].upper() + phrase[1:]


def _seen_place(seen) -> str:
    """Where a remembered sighting was, said after the thing: " on the table by the chair in the bedroom"."""
    place = f" {seen.phrase}" if seen.phrase else (f" on the {seen.furniture_word}" if seen.furniture_word else "")
    return place + (f" in the {seen.room}" if seen.room else "")


class DialogueManager:
    """Conversation state for one person and one home.

    ``world``: a world name or :class:`~assistant.world.World`; ``services``: shared
    :class:`Services`; ``memory``: an :class:`ObjectMemory`; ``say``: called with each progress
    sentence of a running fetch (from the worker thread); ``on_event``: also receives the
    executor's raw events (the 3D view draws them).
    """

    _redirected = False  # the command being handled stopped a search for the thing it names
    _last_distance_goal = None  # the place the last "how far" question was about (for "is it far?")
    #: the which-question last answered and the option taken ({... "options", "chosen": index}),
    #: for "no, the other one"; None once another request is made
    last_choice: dict | None = None

    def __init__(self, world="apartment", scene: str = "original", services: Services | None = None,
                 memory: ObjectMemory | None = None, say=None, on_event=None, on_finish=None, on_pose=None):
        from assistant.world import load_world

        self.world = load_world(world) if isinstance(world, str) else world
        self.scene = self.world.scene(scene).name
        self.services = services or Services()
        self.memory = memory or ObjectMemory(None)
        self.say = say or (lambda text: None)
        self.on_event = on_event
        self.on_finish = on_finish
        self.on_pose = on_pose
        self.robot_pose = None  # the robot's pose last reported while a task ran (pose_listener)
        self.steps: list[str] = []  # the errand's steps still to do ("…, then go to the bedroom")
        self._stopped_steps: list[str] = []  # the steps left when the person said "stop" (for "carry on")
        self._stepping = False  # True while the next step starts (it keeps the steps after it)
        self.last_offer: dict | None = None  # the last "Shall I go …?" made (see ``pending``)
        self.pending: dict | None = None
        self.synonyms: dict[str, str] = {}
        self.last_said = ""
        self.history: list[Turn] = []
        self.worker = TaskWorker(self)

    # ------------------------------------------------------------------ helpers
    @property
    def pending(self) -> dict | None:
        """The question the robot's last reply left open (None: none); an offer to go somewhere
        is kept in ``last_offer`` too, so "take me there" later still finds it."""
        return self._pending

    @pending.setter
    def pending(self, value: dict | None) -> None:
        self._pending = value
        if value and value.get("kind") == "confirm" and value.get("command"):
            self.last_offer = value

    @property
    def rooms(self) -> list[str]:
        return list(self.world.floorplan.room_names)

    @property
    def busy(self) -> bool:
        """A fetch or search is running and has not been asked to stop."""
        return self.worker.busy

    @property
    def activity(self) -> tuple[str, float] | None:
        """While a task runs: (what the robot is doing now, seconds since it started); else None."""
        return self.worker.activity

    @functools.cached_property
    def _room_words(self) -> frozenset[str]:
        """The words of this home's room names ("inner" and "hall" of "the inner hall")."""
        return frozenset(w for r in self.rooms for w in r.split())

    @functools.cached_property
    def _place_heads(self) -> frozenset[str]:
        """Words that name a place here: the rooms' words, furniture words (any home's: "sofa",
        "nightstand") and words that describe furniture ("blue", "coffee", "round")."""
        from assistant.grounding.vocabulary import DESCRIPTORS

        rooms = {w for w in self._room_words if len(w) > 2}
        models = {w for f in self.world.scene(self.scene).furniture for w in f.model.split()}
        return frozenset(rooms | set(FURNITURE_WORDS) | set(DESCRIPTORS) | models)

    def pose_listener(self, pose) -> None:
        """Told the robot's true pose now and then while a task runs: kept for "where are you?",
        and passed on to ``on_pose`` (the 3D view) when there is one."""
        self.robot_pose = pose
        if self.on_pose is not None:
            self.on_pose(pose)

    def robot_xy(self) -> tuple[tuple[float, float], bool]:
        """((x, y) metres of the robot, whether it has moved this conversation): from the pose
        last reported, else the last task's final pose, else the world's start pose."""
        if self.robot_pose is not None:
            return (float(self.robot_pose.x), float(self.robot_pose.y)), True
        final = next((t.data["final_pose"] for t in reversed(self.history)
                      if t.final and t.data.get("final_pose")), None)
        if final:
            return (float(final[0]), float(final[1])), True
        return (float(self.world.start.x), float(self.world.start.y)), False

    def robot_room(self) -> tuple[str | None, bool]:
        """(the room the robot is in, whether it has moved this conversation); see :meth:`robot_xy`."""
        xy, moved = self.robot_xy()
        room = self.world.floorplan.room_at(*xy)
        return getattr(room, "name", room), moved

    def greeting(self) -> str:
        return (f"Hello! I'm in the {self.world.name} ({_join(['the ' + r for r in self.rooms])}). "
                "Ask me to fetch something, where something is, or say \"help\" to hear what I can do.")

    def _turn(self, text, intent, reply, action="answer", outcome="answered", start=None, **data) -> Turn:
        turn = Turn(text, intent, reply, action, outcome, data,
                    0.0 if start is None else time.perf_counter() - start)
        if reply:
            self.last_said = reply
        self.history.append(turn)
        return turn

    # ------------------------------------------------------------------ entry point
    def about_the_task(self, text: str) -> bool:
        """Whether an utterance is for the task under way — stop it, cancel it, ask what it is
        doing, or a command (one that changes the task, as telling where the thing searched for
        is, is taken at once; any other answers "I'm still busy") — rather than a question to
        answer once it has ended."""
        return classify(self._written_out(text)).name in DURING_TASK

    def _written_out(self, text: str) -> str:
        """An utterance as the manager reads it: words taken back, courtesies dropped, shorthand
        written out, articles put before places ("pls go 2 bedrm" → "please go to the bedrm")."""
        return with_articles(expand_shorthand(drop_courtesies(without_retractions(text, leading=False))),
                             self._place_heads)

    def handle(self, text: str) -> Turn:
        """Route one utterance; never raises for what a person may say."""
        start = time.perf_counter()
        try:
            return self._handle(text, start)
        except Exception as error:  # a bug must not end the conversation
            from assistant.errors import AssistantError

            if isinstance(error, AssistantError):
                return self._turn(text, "command", f"Sorry — {error}.", "none", "failed", start)
            return self._turn(text, "error", f"Sorry, something went wrong inside me ({type(error).__name__}: "
                              f"{error}). Please say it another way.", "none", "failed", start)

    def _handle(self, text: str, start: float) -> Turn:
        text = self._written_out(text)
        lead = LEADING_THANKS.match(text)
        if lead is not None and classify(lead.group("rest")).name not in ("thanks", "ack", "praise", "empty"):
            # "Thank you. Could you please stop at the bedside table?": the request after the thanks
            turn = self._handle(lead.group("rest"), start)
            if re.search(r"thank|cheers|^ta\b", lead.group("lead"), re.IGNORECASE) and turn.reply:
                turn.reply = f"You're welcome. {turn.reply}"
                self.last_said = turn.reply
            return turn
        lead = LEADING_NEVER_MIND.match(text)
        if lead is not None and classify(lead.group("rest")).name not in ("empty", "cancel", "thanks", "ack"):
            # "never mind, where's my knitting": the question or task before is dropped, the new one taken
            self.pending = None
            if self.busy:
                self.stop()
                self.worker.wait(10.0)
            return self._handle(lead.group("rest"), start)
        intent = classify(text)
        guess = re.fullmatch(r"(?:(?:maybe|perhaps|probably|possibly|try|or|i think|could it be|is it|its|might be) )*"
                             r"(?P<place>(?:in|on|under|by|near|next to|beside|behind|on top of|in front of) "
                             r"(?:(?:the|my|our) )?[a-z]+(?: [a-z]+)?)(?: maybe| perhaps| then)?", intent.text)
        if intent.name == "command" and guess is not None and self.history \
                and self.history[-1].intent in ("where", "where_check") and self._last_object() is not None:
            # "where is my book?" … "maybe in bed?", "on the coffee table?": is it there (the offer is dropped)
            self.pending = None
            obj = self._last_object()
            place = re.sub(r"^in bed$", "on the bed", guess["place"])  # "in bed": on it
            place = re.sub(r"^((?:next to|on top of|in front of|[a-z]+) )(?!the |my |our )", r"\1the ", place)
            return self._where_check(text, Intent("where_check", f"is the {obj} {place}"), start)
        if intent.name == "command" and (place := self._bare_place(intent.text)) is not None:
            text = f"go to the {place}"  # "couch pls", "now the bed": a place said alone, as a request
            intent = classify(text)
        name = intent.name
        if name == "empty":
            if text.strip():  # something was typed, but no word in it (e.g. "!!! ???")
                return self._turn(text, name, "Sorry, I didn't catch any words there. "
                                  "Say \"help\" for what you can ask me.", start=start)
            return self._turn(text, name, "", "none", "answered", start)
        if name == "emergency":  # stop whatever it does and say what to do, before anything else
            self.pending = None
            self.stop()
            return self._turn(text, name, SOCIAL_REPLIES[name], "stop", "answered", start)
        if name == "stop":
            return self._do_stop(text, start)
        if name == "cancel" and re.search(r"\bforget\b", intent.text) and self.history \
                and self.history[-1].intent == "told" and self.history[-1].data.get("object"):
            # "forget that" just after being told where a thing is: the note goes
            obj = self.history[-1].data["object"]
            self.pending = None
            self.memory.forget(self.world.name, obj)
            return self._turn(text, name, f"OK — I've forgotten what you told me about your {obj}.", "none",
                              "cancelled", start, object=obj)
        if name == "forget":
            return self._forget(text, intent, start)
        if name == "cancel":
            was = self.pending is not None
            self.pending = None
            if self.busy:
                return self._do_stop(text, start, intent_name="cancel")
            return self._turn(text, name, "OK, never mind." if was else "OK.", "none", "cancelled", start)
        if name == "repeat":
            reply = self.last_said or "I haven't said anything yet."
            turn = Turn(text, name, reply, "answer", "answered", {}, time.perf_counter() - start)
            self.history.append(turn)
            return turn
        if name == "help":
            return self._turn(text, name, HELP_TEXT, start=start)
        if name == "which_home":
            rooms = _join(["the " + r for r in self.rooms])
            layout = "" if self.scene == "original" else f" ({self.scene} furniture)"  # only when not as built
            return self._turn(text, name, f"You're in the {self.world.name}{layout}, with {rooms}.", start=start,
                              world=self.world.name, scene=self.scene)
        if name == "start_over":
            self.pending = None
            self.synonyms.clear()
            self.stop()
            return self._turn(text, name, "OK, let's start over. What can I do for you?", "none",
                              "cancelled", start)
        if name == "resume":  # "ok, carry on": the task stopped last; else a yes to a pending question
            if self.worker.stopped is not None or self.busy or self.pending is None:
                self.pending = None
                return self._resume(text, start)
            intent = Intent("yes", intent.text)
        if self.pending is not None:
            turn = self._resolve(text, intent, start)
            if turn is not None:
                return turn
        if self.history and self.history[-1].intent == "told" and self.history[-1].data.get("object") and \
                (fix := TOLD_CORRECTION.match(intent.text)) is not None:
            return self._told_again(text, self.history[-1].data["object"], fix.group("place"), start)
        if name == "yes" and re.search(r"\b(there|to it|to them)\b", intent.text) and \
                (last := self._last_object()) is not None:
            offer = self.last_offer if self.last_offer and self.last_offer.get("object") == last else None
            if offer is not None:  # "take me there": where the robot said it is
                return self._command(offer["command"], start, force=True, original=text)
            return self._command(f"bring me the {last}", start, original=text)  # "go there": to the thing talked of
        if name in ("yes", "no"):
            return self._turn(text, name, "OK." if name == "no" else
                              "Yes? Tell me what to do — say \"help\" for examples.", start=start)
        if name == "bye":  # the conversation ends (the REPL leaves on this action)
            return self._turn(text, name, "Goodbye.", "leave", "answered", start)
        if name == "come_here" and (re.search(r"\b(started|start|beginning|began|starting|came from)\b", intent.text)
                                    or (re.search(r"\bcome back\b", intent.text) and self.robot_xy()[1])):
            # "go back to where you started", "come back" after a task: the room it set out from
            here = self.world.floorplan.room_at(self.world.start.x, self.world.start.y)
            room = getattr(here, "name", here)
            if room:
                turn = self._command(f"go to the {room}", start, original=text)
                if turn.action == "fetch" and "started" not in intent.text:
                    turn.reply = f"I'll go back to where I started, in the {room}. {turn.reply}"
                    self.last_said = turn.reply
                return turn
        if name in SOCIAL_REPLIES:
            return self._turn(text, name, SOCIAL_REPLIES[name], start=start)
        if name == "again":
            return self._again(text, intent, start)
        if name == "robot_place":
            return self._robot_place(text, start)
        if name == "why_stopped":
            return self._why_stopped(text, start)
        if name == "what_see":
            return self._what_see(text, start)
        if name == "status":
            doing = self.activity
            return self._turn(text, name, "Nothing right now: I'm waiting for you to ask me something."
                              if doing is None else f"I'm {doing[0]} ({doing[1]:.0f} s so far). Say \"stop\" to "
                              "stop me.", start=start)
        if re.fullmatch(r"(?:(?:and|so|ok|okay|now) )*(?:is there anything(?: else)?|is anything|anything(?: else)?|whats|"
                        r"what is|what else is|"
                        r"what have you seen|what can you see|do you see anything) on (?:it|there|that|top)(?: now)?",
                        intent.text) and (item := self._last_furniture()[1]) is not None:
            # "check the table by the bed" … "is there anything on it?": that piece
            return self._on_furniture(text, Intent("on_furniture", f"whats on the {item.model} in the {item.room}"),
                                      start)
        if name == "furniture":
            return self._furniture(text, intent, start)
        if name == "seen_list":
            return self._seen_list(text, start, intent.text)
        if name == "want":  # "I need my glasses": a fetch of the thing, wherever it is
            thing = re.search(WANTED, intent.text).group("thing")
            return self._command(f"bring me {thing}", start, original=text)
        answers = {"where": self._where, "where_dynamic": self._where, "where_check": self._where_check,
                   "told": self._told, "on_furniture": self._on_furniture, "how_far": self._how_far,
                   "near_furniture": self._near_furniture, "what_known": self._what_known}
        if name in answers:  # questions and statements answered from the map and the memory
            return answers[name](text, intent, start)
        if name == "teach":
            return self._teach(text, start)
        if name == "dont":  # "don't go to the bedroom": stop what it is doing, start nothing
            if self.stop():
                return self._turn(text, name, "OK, I won't — stopping.", "stop", "stopped", start)
            return self._turn(text, name, "OK, I won't.", start=start)
        thing = self._other_thing(text, intent.text, start)
        if thing is not None:
            return thing
        other = self._other_one(text, intent.text, start)
        if other is not None:
            return other
        last = self._last_object() if re.search(r"\b(it|them|its|theyre)\b", intent.text) else None
        if last is not None and re.search(IT_REQUEST, intent.text):  # "bring it to me", "take me to it"
            kept = self.memory.recall(self.world.name, last)
            if kept is not None and kept.source == TOLD_NOT_SEEN and re.search(r"\b(find|search|look for)\b",
                                                                                intent.text):
                # looked where it was said to be and not seen: "find it" searches the home
                return self._search(text, "command", last, "static", start,
                                    lead=f"It wasn't where you said, so I'll look all over the home for your {last}.")
            return self._command(re.sub(r"\b(it|them)\b", f"the {last}", intent.text, count=1), start, original=text)
        if last is not None and (m := re.search(IT_IS_AT, intent.text)):  # "it's on the table by the chairs"
            return self._command(f"the {last} {is_are(last)} {m.group('place')}", start, original=text)
        room_fix = self._other_room(text, intent.text, start)
        if room_fix is not None:
            return room_fix
        bare = re.sub(r"^(the|my|a|an|your|our) ", "", intent.text)
        if bare and len(bare.split()) <= 2 and (self._object_in(bare)[0] == bare
                                                or matching(self.world.scene(self.scene).furniture, bare)):
            # a thing's name on its own ("mug?", "couch"): asked where it is
            return self._where(text, Intent("where", f"where is the {bare}"), start)
        return self._command(text, start)

    # ------------------------------------------------------------------ about the robot itself
    def _robot_place(self, text: str, start: float) -> Turn:
        """"where are you?", "what room are you in?": the robot's room, and what it is doing."""
        room, moved = self.robot_room()
        where = f"I'm in the {room}" if room else "I'm between rooms"
        doing = self.activity
        if doing is not None:
            reply = f"{where}, {doing[0]}."
        else:
            reply = f"{where}{'' if moved else ', where I started'}. What can I do for you?"
        return self._turn(text, "robot_place", reply, start=start, room=room)

    def _what_see(self, text: str, start: float) -> Turn:
        """"what do you see?", "what is near you?": the room the robot is in, its furniture, and
        the things last seen there."""
        room, _ = self.robot_room()
        if room is None:
            return self._turn(text, "what_see", "I'm between rooms just now. Ask me what's in a room, for example "
                              f"\"what's in the {self.rooms[-1]}?\"", start=start)
        furniture = furniture_answer(self.world.scene(self.scene).furniture, self.rooms, "list", "", room)
        things = [s for s in self.memory.sightings(self.world.name) if s.room == room and not s.told]
        seen = (f" Of your things, I last saw {_join([f'your {s.object}' for s in things])} here." if things
                else " I haven't seen any of your things here.")
        return self._turn(text, "what_see", f"I'm in the {room}. {furniture}{seen}", start=start, room=room)

    def _why_stopped(self, text: str, start: float) -> Turn:
        """"why did you stop?": how the last task ended, in its own words."""
        if self.busy:
            doing = self.activity
            going = not re.search(r"\bstop", text.lower())  # "why are you going there?"
            reply = (f"Because you asked me to: I'm {doing[0] if doing else 'at it'}. Say \"stop\" to stop me."
                     if going else f"I haven't stopped — I'm {doing[0] if doing else 'still at it'}.")
            return self._turn(text, "why_stopped", reply, start=start)
        last = next((t for t in reversed(self.history) if t.final and t.action in ("fetch", "search")), None)
        if last is None:
            return self._turn(text, "why_stopped", "I haven't been asked to do anything yet. What can I do for you?",
                              start=start)
        if last.outcome == "stopped":
            reply = "You asked me to stop. Say \"carry on\" and I'll go on."
        elif last.outcome == "success":
            done = re.sub(r"^Done\s*[—-]\s*", "", last.reply)
            reply = f"I'd done what you asked: {_in_sentence(done)}"
        else:
            reply = f"I couldn't go on: {_in_sentence(last.reply)}"  # "… i'm at the table" was lowercased
        return self._turn(text, "why_stopped", reply, start=start)

    # ------------------------------------------------------------------ stop / wait
    def _resume(self, text: str, start: float) -> Turn:
        """"carry on": start again the task a person stopped, from where the robot is now (a
        task still stopping is waited for: "stop" and "carry on" typed at once)."""
        job = self.worker.job
        if job is not None and job.stop.is_set() and job.thread.is_alive():
            self.worker.wait(10.0)
        if self.busy:
            doing = self.activity
            return self._turn(text, "resume", f"I'm still {doing[0] if doing else 'at it'}.", start=start)
        job = self.worker.stopped
        if job is None:
            return self._turn(text, "resume", "There's nothing I was stopped in the middle of. What can I do for "
                              "you?", start=start)
        kind, task_text, room, obj, style = job.args
        data = {"object": obj, "room": room, "resumed": True}
        if kind == "fetch":
            data["command"] = task_text
        what = f"going to the {room}" if job.what == "on my way" and room else job.what
        steps = self._stopped_steps
        after = f" After that, {_join([step_place(s) for s in steps], 'and then')}." if steps else ""
        turn = self._start_job(kind, text, f"OK, carrying on — {what}.{after}", task_text, room, obj, start,
                               intent_name="resume", style=style, **data)
        self.steps, self._stopped_steps = list(steps), []  # the errand goes on after it
        return turn

    def _do_stop(self, text, start, intent_name="stop") -> Turn:
        self.pending = None
        if self.stop():
            return self._turn(text, intent_name, "Stopping.", "stop", "stopped", start)
        return self._turn(text, intent_name, "OK — I'm not doing anything right now.", "none", "answered", start)

    def stop(self) -> bool:
        """Ask a running task to stop (Ctrl-C); True when one was running. The errand's
        steps still to do are dropped (kept for "carry on")."""
        if self.steps:
            self._stopped_steps = self.steps
        self.steps = []
        return self.worker.stop()

    def after_task(self, final: Turn) -> None:
        """Called by the worker when a task has ended and its reply was said: the errand's next
        step starts (its "Going to the bedroom." said), or, when the task failed, the steps
        left are dropped and said so."""
        if not self.steps:
            return
        if final.outcome != "success":
            left, self.steps = self.steps, []
            if final.outcome != "stopped":
                self.say(f"So I haven't done the rest: {_join(left)}.")
            return
        step = self.steps.pop(0)
        self._stepping = True
        try:
            turn = self._command(step, time.perf_counter(), original=step)
        finally:
            self._stepping = False
        if turn.reply:
            self.say(turn.reply)
        if turn.outcome == "not_understood":  # a step it cannot do: the rest is dropped (a question keeps them)
            self.steps = []

    @property
    def fetch_started(self) -> bool:
        """A task was started in this conversation (so :meth:`wait` has one to wait for)."""
        return self.worker.job is not None

    def wait(self, timeout: float | None = None) -> Turn | None:
        """Wait for the last task to end; its final :class:`Turn` (None if none ran, or it is
        still running after ``timeout`` seconds). A stopped task ends at the robot's next call."""
        return self.worker.wait(timeout)

    def close(self, timeout: float = 10.0) -> None:
        """Stop a running task and wait for it, and for the models still loading in the
        background (end of a conversation): a process that ends while a thread is inside
        open3d's or scikit-learn's native code can abort ("terminate called without an active
        exception", seen once after a short piped chat)."""
        self.stop()
        self.worker.close(timeout)
        wait_warm = getattr(self.services, "wait_warm", None)
        if wait_warm is not None:
            wait_warm(timeout)

    # ------------------------------------------------------------------ where / how
    def _object_in(self, norm: str, plan_object: str | None = None) -> tuple[str | None, str | None]:
        """(known object named in the text, or None; the unknown noun asked about, or None)."""
        return named_object(norm, self.world, plan_object)

    def _place_asked(self, text: str, intent, noun: str, start: float) -> Turn | None:
        """A where-question about a room or a piece of furniture: where it is, and an offer to go."""
        room = self._room_in(intent.text)
        if room is not None and intent.name == "where_dynamic":  # "how do I get to the office?"
            route = self._room_route(room)
            if route is None:
                return self._turn(text, intent.name, f"I'm in the {room} now.", "answer", "answered", start,
                                  room=room)
            self.pending = {"kind": "confirm", "command": f"go to the {room}", "object": None}
            return self._turn(text, intent.name, f"{route} Shall I take you there?", "answer", "answered", start,
                              room=room)
        if room is not None:
            self.pending = {"kind": "confirm", "command": f"go to the {room}", "object": None}
            rooms = _join(["the " + r for r in self.rooms])
            return self._turn(text, intent.name, f"The {room} is one of the rooms here ({rooms}). Shall I go there?",
                              "answer", "answered", start, room=room)
        missing = unknown_room_named(intent.text.split(), self.world) or (
            noun if noun in COMMON_ROOMS or f"{noun} room" in COMMON_ROOMS else None)
        if missing is not None:
            return self._no_room(text, intent.name, missing, start)
        furniture = self.world.scene(self.scene).furniture
        found = matching(furniture, noun)
        if not found:
            return None
        homes = [r for r in self.rooms if any(f.room == r for f in found)]
        name = singular(noun)
        if len(found) == 1:
            self.pending = {"kind": "confirm", "command": f"go to the {name} in the {homes[0]}", "object": None}
            return self._turn(text, intent.name, f"The {name} is in the {homes[0]}. Shall I go to it?", "answer",
                              "answered", start, room=homes[0])
        return self._turn(text, intent.name, f"There are {NUMBER_WORDS.get(len(found), len(found))} "
                          f"{plural(found[0].word)} here, in {_join(['the ' + r for r in homes])}. Say which one to "
                          f"go to, for example \"go to the {found[0].model} in the {found[0].room}\".",
                          "answer", "answered", start)

    def _room_in(self, text: str) -> str | None:
        """The first of this home's rooms named in ``text`` (as whole words), by its name or another
        ("the lounge": the living room), or None."""
        named = next((r for r in self.rooms if re.search(rf"\b{re.escape(r)}\b", text)), None)
        if named is None:
            named = next((room for alias, room in room_aliases(self.rooms).items()
                          if re.search(rf"\b{re.escape(alias)}\b", text)), None)
        return named

    def _no_room(self, said: str, intent_name: str, missing: str, start: float, outcome: str = "answered") -> Turn:
        """"There is no kitchen here; the rooms are …": a room this home does not have."""
        return self._turn(said, intent_name, f"There is no {missing} here; the rooms are "
                          f"{_join(['the ' + r for r in self.rooms])}.", "answer", outcome, start,
                          unknown_room=missing)

    def _rooms_with(self, words) -> list[str]:
        """The rooms that have a piece of furniture of each of ``words`` ("bed": only the bedroom)."""
        furniture = self.world.scene(self.scene).furniture
        return [r for r in self.rooms if all(any(f.room == r and f.word == w for f in furniture) for w in words)]

    def _option(self, item) -> dict:
        """A piece of furniture as an option of a which-question (its phrase from the describer)."""
        return {"id": item.id, "phrase": furniture_phrase(self.services.describer, self.world, self.scene, item),
                "room": item.room, "model": item.model}

    def _seen_list(self, text: str, start: float, norm: str = "") -> Turn:
        """"what did you see?", "what did you see in the bedroom?": the things the robot
        remembers in this home (or that room), latest first."""
        room = None
        if (asked := re.search(r"\b(?:in|inside) (?:the|my|our) (?P<room>[a-z]+(?: [a-z]+)?)$", norm)) is not None:
            room = self._room_in(asked.group(0))
            missing = unknown_room_named(asked.group("room").split(), self.world) if room is None else None
            if missing is not None:
                return self._no_room(text, "seen_list", missing, start)
        remembered = sorted((s for s in self.memory.sightings(self.world.name) if room is None or s.room == room),
                            key=lambda s: -s.time_s)
        seen = [s for s in remembered if not s.told]
        told_things = [f"your {s.object}" for s in remembered if s.told]
        told = _join(told_things) if told_things else ""
        if not seen:
            where = f"in the {room}" if room else "here"
            return self._turn(text, "seen_list", f"I haven't seen any of your things {where} yet — ask me to look for "
                              "something." + (f" You told me where to find {told}." if told else ""), start=start,
                              room=room)
        parts, ages = [], []
        for s in seen[:SEEN_LIST_MAX]:
            parts.append(f"your {s.object}{_seen_place(s)}")
            ages.append(self.memory.age(s))
        if len(set(ages)) > 1:  # each with its own time
            parts = [f"{p} ({age})" for p, age in zip(parts, ages)]
        when = f", {ages[0]}" if len(set(ages)) == 1 else ""
        more = f" — and {len(seen) - SEEN_LIST_MAX} more" if len(seen) > SEEN_LIST_MAX else ""
        also = f" You also told me where to find {told}." if told else ""
        return self._turn(text, "seen_list", f"I've seen{when}: {_join(parts)}{more}.{also}", start=start,
                          objects=[s.object for s in seen])

    def _furniture(self, text: str, intent, start: float) -> Turn:
        """"what's in the bedroom?", "is there a couch in the living room?", "how many chairs …?"
        (:mod:`~assistant.dialogue.inventory`); a thing that is not furniture is a where-question."""
        kind, what = furniture_asked(intent.text)
        furniture = self.world.scene(self.scene).furniture
        if what and what not in ANYTHING and not matching(furniture, what) \
                and furniture_category(singular(what)) is None:
            thing = self._object_in(intent.text)[0]
            if thing is not None:  # "is there a mug in the bedroom?": is it there / where is it
                room = self._room_in(intent.text)
                if room is not None:
                    return self._where_check(text, Intent("where_check", f"is the {thing} in the {room}"), start)
                return self._where(text, Intent("where", intent.text), start)
            return self._command(text, start)
        room = self._room_in(intent.text)
        if room is None and re.search(r"\b(this room|in here|the room (you are|youre) in|where you are)\b", intent.text):
            room = self.robot_room()[0]  # "what's in this room?": the room the robot is in
        missing = unknown_room_named(intent.text.split(), self.world) if room is None else None
        if missing is not None:
            return self._no_room(text, "furniture", missing, start)
        reply = furniture_answer(furniture, self.rooms, kind, what, room)
        return self._turn(text, "furniture", reply, "answer", "answered", start, room=room, asked=what or None)

    def _again(self, text: str, intent, start: float) -> Turn:
        """"are you sure?": what the robot goes by, and an offer to look again; "check again",
        "look again": it searches again for the thing last talked of."""
        obj = self._last_object()
        if obj is None:
            return self._turn(text, intent.name, "Which of your things shall I look for? Ask me, for example, "
                              "\"where is my mug?\"", "clarify", "asked", start)
        if re.match(r"^(?:(?:but|and|so|hmm|oh|wait) )*(?:are you|really|is|was|you|u|how|are they)\b",
                    intent.text):  # a doubt, not "check again"
            seen = self.memory.recall(self.world.name, obj)
            if seen is not None:
                said = self._seen_at(obj, seen)
                self.pending = {"kind": "confirm", "command": fetch_command_text(obj, seen.phrase, seen.room),
                                "object": obj}
                return self._turn(text, intent.name, f"{said[:1].upper()}{said[1:]} — that's what I go by. Shall I "
                                  "go and check?", "answer", "answered", start, object=obj, source="memory")
            about = [t.data for t in self.history if t.data.get("object") == obj]
            if about and about[-1].get("source") == "simulator" and about[-1].get("found", True):
                # the answer came from the home's map: say so, and offer to go and see
                offer = self.last_offer if self.last_offer and self.last_offer.get("object") == obj else None
                self.pending = offer or {"kind": "confirm", "command": f"bring me the {obj}", "object": obj}
                return self._turn(text, intent.name, f"I haven't seen your {obj} myself — I went by the map of "
                                  "the home I was given, which may be out of date. Shall I go and check?", "answer",
                                  "answered", start, object=obj, source="simulator")
            self.pending = {"kind": "confirm", "search": obj, "object": obj}
            looked = any(t.get("source") == "search" for t in about)
            return self._turn(text, intent.name, f"I haven't seen your {obj} myself, and nobody has told me where "
                              f"{'they are' if it_them(obj) == 'them' else 'it is'}. Shall I look for {it_them(obj)}"
                              f"{' again' if looked else ''}?", "answer", "answered", start, object=obj)
        return self._search(text, intent.name, obj, "static", start,
                            lead=f"OK, I'll look for your {obj} again.")

    def _where(self, text: str, intent, start: float) -> Turn:
        """"where is my mug?" (see :meth:`_where_of`); someone else's thing is said as theirs
        ("where is John's phone?" → "I haven't seen John's cell phone …", not "your")."""
        turn = self._where_of(text, intent, start)
        owner = owner_phrase(intent.text)
        obj = turn.data.get("object")
        if owner and obj and turn.reply:
            turn.reply = re.sub(rf"\b[Yy]our {re.escape(obj)}\b", f"{owner} {obj}", turn.reply)
            self.last_said = turn.reply
        return turn

    def _door_asked(self, text: str, intent, start: float) -> Turn | None:
        """"where is the front door?": the room a named door of this home opens from (the
        floor plan's doors), with an offer to go there; None when no door of the home is named."""
        doors = {d.name.lower(): d for d in self.world.floorplan.doors if " door" in d.name.lower()}
        named = next((name for name in sorted(doors, key=len, reverse=True)
                      if re.search(rf"\b{re.escape(name)}\b", intent.text)), None)
        if named is None:
            return None
        rooms = [r for r in doors[named].connects if r in self.rooms]
        if not rooms:
            return None
        outside = any(r not in self.rooms for r in doors[named].connects)
        where = (f"in the {rooms[0]}, leading outside" if outside else
                 f"between the {rooms[0]} and the {rooms[1]}" if len(rooms) > 1 else f"in the {rooms[0]}")
        self.pending = {"kind": "confirm", "command": f"go to the {rooms[0]}", "object": None}
        return self._turn(text, intent.name, f"The {named} is {where}. Shall I go there?", "answer", "answered",
                          start, room=rooms[0])

    def _where_of(self, text: str, intent, start: float) -> Turn:
        if intent.name == "where_dynamic" and (room := self._room_in(intent.text)) is not None:
            thing = self._object_in(intent.text)[0]
            if thing is None or set(thing.split()) <= self._room_words:  # "how do I get to the small room?"
                return self._place_asked(text, intent, room, start)
        follow = re.fullmatch(r"(?:and|what about|how about|and what about)(?: in| inside| on)? (?:the|my|our) "
                              r"(?P<place>[a-z]+(?: [a-z]+)?)", intent.text)
        last = self._last_object() if follow else None
        if last is not None and (follow["place"] in self.rooms or follow["place"] in COMMON_ROOMS
                                 or unknown_room_named(follow["place"].split(), self.world) is not None):
            # "and the meeting room?", "what about in the bedroom?": the thing last talked of, there
            return self._where_check(text, Intent("where_check", f"is the {last} in the {follow['place']}"), start)
        parts = [p.strip() for p in re.split(r"\b(?:and|or)\b", intent.text) if p.strip()]
        named = [o for o in (self._object_in(p)[0] or self._object_in(p)[1] for p in parts) if o]
        if len(parts) > 1 and len(dict.fromkeys(named)) > 1 and self._object_in(parts[0])[0] is not None:
            # "where are my keys and my wallet": one at a time, the first now
            turn = self._where(text, Intent(intent.name, parts[0]), start)
            later = _join([f"your {o}" for o in list(dict.fromkeys(named))[1:]])
            turn.reply += f" (You also asked about {later}: ask me again after this.)"
            self.last_said = turn.reply
            return turn
        obj, unknown = self._object_in(intent.text)
        if obj is None and (door := self._door_asked(text, intent, start)) is not None:  # "where is the front door?"
            return door
        if obj is None and unknown is None:
            obj = self._last_object()  # "where did you see it?", "how do I get there?", "where exactly?"
        if obj is None and unknown and (re.fullmatch(PLACE_QUESTION + re.escape(unknown), intent.text)
                                        or unknown in self._room_words):
            # "where is the bedroom?", "where's the couch?": a place, not a thing
            place = self._place_asked(text, intent, unknown, start)
            if place is not None:
                return place
        if obj is None:
            names = _join(sorted(known_object_names(self.world)), "or")
            if unknown and (matching(self.world.scene(self.scene).furniture, unknown)
                            or furniture_category(singular(unknown)) is not None):
                place = self._place_asked(text, intent, unknown, start) if intent.name == "where_dynamic" \
                    and len({furniture_category(singular(w)) for w in intent.text.split()} - {None}) == 1 \
                    else None  # "how do I get to the couch?": where it is, and an offer to go
                if place is not None:
                    return place
                found = [f for f in matching(self.world.scene(self.scene).furniture, unknown)
                         if singular(unknown) in (f.word, f.model, *f.model.split())]  # a dresser is no table
                told_by = re.search(r"\b(between|next to|by|near|beside|behind|in front of|left of|right of|with|"
                                    r"against|opposite)\b", intent.text)
                if found and told_by is None:  # "what room is the desk in?": the rooms from the home's map
                    name = singular(unknown)
                    rooms = [r for r in self.rooms if any(f.room == r for f in found)]
                    if len(found) == 1:
                        self.pending = {"kind": "confirm", "command": f"go to the {name} in the {rooms[0]}",
                                        "object": None}
                        reply = f"The {name} is in the {rooms[0]}. Shall I go to it?"
                    else:
                        count = NUMBER_WORDS.get(len(found), str(len(found)))
                        reply = (f"There are {count} {plural(name)}: " + _join(
                            [f"{NUMBER_WORDS.get(n, str(n)) if n > 1 else 'one'} in the {r}"
                             for r in rooms for n in [sum(f.room == r for f in found)]]) + ". Tell me which to go "
                            f"to, for example \"go to the {name} in the {rooms[-1]}\".")
                    return self._turn(text, intent.name, reply, "answer", "answered", start, furniture=name)
                if told_by is None:  # "where is the dresser?" in a home with none
                    return self._turn(text, intent.name, f"There is no {singular(unknown)} in this home — the "
                                      f"furniture here is {self._furniture_kinds()}.", "answer", "answered", start)
                return self._turn(text, intent.name, "I look for things, not furniture — ask me \"what's in the "
                                  f"{self.rooms[-1]}?\" or \"where's the {singular(unknown)}?\", or tell me to go to "
                                  "a piece of furniture.", "answer", "answered", start)
            if unknown:
                return self._turn(text, intent.name, f"I don't know what {article(unknown)} {unknown} is, so I "
                                  f"can't look for it. I can look for: {names}.", "answer", "not_understood",
                                  start, unknown=unknown)
            return self._turn(text, intent.name, f"What are you looking for? I know about: {names}.", "clarify",
                              "asked", start)
        style = "dynamic" if intent.name == "where_dynamic" else "static"
        seen = self.memory.recall(self.world.name, obj)
        if seen is not None and style == "static":
            said = self._seen_at(obj, seen)
            here = seen.room is not None and not self.busy and self.robot_room()[0] == seen.room
            its = "They're" if it_them(obj) == "them" else "It's"
            offer = f"{its} in this room — shall I go over to {it_them(obj)}?" if here else "Shall I go and check?"
            self.pending = {"kind": "confirm", "command": fetch_command_text(obj, seen.phrase, seen.room),
                            "object": obj}
            if seen.source == TOLD_NOT_SEEN:  # looked there already: the offer is a search of the home
                offer = f"Shall I look for {it_them(obj)} all over the home?"
                self.pending = {"kind": "confirm", "search": obj, "object": obj}
            reply = f"{said[:1].upper()}{said[1:]}. {offer}"
            return self._turn(text, intent.name, reply, "answer", "answered", start, object=obj,
                              source="memory", memory=seen.to_dict())
        if seen is not None and seen.x_m is not None:  # the way to where the robot saw it
            result = self._describe(obj, style, seen)
            if result.found:
                reply = f"{result.description} (That is where I saw it {self.memory.age(seen)}.)"
                return self._turn(text, intent.name, reply, "describe", "answered", start, object=obj,
                                  source="memory", style=style, nodes=list(result.nodes), found=True,
                                  memory=seen.to_dict())
        related = related_seen(obj, [s.object for s in self.memory.sightings(self.world.name)]) \
            if seen is None else None
        if related is not None:  # "where are my glasses?", a glasses case remembered
            other = self.memory.recall(self.world.name, related)
            said = self._seen_at(related, other)
            self.pending = {"kind": "confirm", "command": fetch_command_text(related, other.phrase, other.room),
                            "object": related}
            return self._turn(text, intent.name, f"I haven't seen {some(obj)}, but {said}. Is that what you mean? "
                              f"Shall I go over to {it_them(related)}?", "answer", "answered", start, object=obj,
                              related=related, source="memory")
        if self.services.search_mode == "sensed":
            return self._search(text, intent.name, obj, style, start)
        result = self._describe(obj, style)
        if not result.found:  # nothing of the kind on the map: say so, and offer to look
            self.pending = {"kind": "confirm", "search": obj, "object": obj}
            where = "they are" if it_them(obj) == "them" else "it is"
            reply = f"I haven't seen your {obj}, and I don't know where {where}. Shall I look for {it_them(obj)}?"
            return self._turn(text, intent.name, reply, "answer", "answered", start,
                              object=obj, source="simulator", found=False)
        description = result.description
        place = re.sub(rf"^the {re.escape(obj)} (is|are) ", "", description.rstrip("."), flags=re.I)
        if style == "static":
            self.pending = {"kind": "confirm", "command": f"bring me the {obj} {place}", "object": obj}
            offer = f" Shall I go over to {it_them(obj)}?"
        else:
            offer = ""
        reply = (f"{description} (I haven't seen {it_them(obj)} myself yet — that is from the simulator's map "
                 f"of the home.){offer}")
        return self._turn(text, intent.name, reply, "describe", "answered", start, object=obj,
                          source="simulator", style=style, nodes=list(result.nodes), found=True)

    def _where_check(self, text: str, intent, start: float) -> Turn:
        """"is my mug in the bedroom?": yes or no from what the robot remembers, with an offer to
        fetch it or to go and check that place; not remembered, it goes and looks there. A piece
        of furniture ("is the couch in the living room?") is answered from the home's map."""
        thing, place = where_check_parts(intent.text)
        noun = re.sub(r"^(my|the|our|his|her) ", "", thing)
        if re.search(r" or (?:in |on |at |by )?(?:the|my|our) ", place):  # "in the bedroom or the living room?"
            return self._where(text, Intent("where", f"where is the {noun}" if noun not in ("it", "they", "them")
                                            else f"where is the {self._last_object() or noun}"), start)
        obj = self._last_object() if noun in ("it", "they", "them") else self._object_in(thing)[0]
        room = self._room_in(place)
        word, homes = self._furniture_rooms(place)
        furniture = self.world.scene(self.scene).furniture
        if room is None and len(homes) == 1:  # "near the bed": the one room with a bed
            room = homes[0]
        missing = unknown_room_named(place.split(), self.world) if room is None else None
        if missing is not None:
            return self._no_room(text, intent.name, missing, start)
        if obj is None:
            found = matching(furniture, noun)
            if found and room is not None:  # "is the couch in the living room?"
                here = [f for f in found if f.room == room]
                name = singular(noun)
                homes = _join(sorted({"the " + f.room for f in found}))
                reply = (f"Yes, there is {article(name)} {name} in the {room}." if here
                         else f"No — the {name} is in {homes}." if len(found) == 1
                         else f"No — the {plural(found[0].word)} are in {homes}.")
                return self._turn(text, intent.name, reply, "answer", "answered", start, room=room)
            if noun in ("it", "they", "them"):
                return self._turn(text, intent.name, "Which of your things do you mean? Ask me, for example, \"is "
                                  "my mug in the bedroom?\"", "clarify", "asked", start)
            return self._where(text, Intent("where", f"where is the {noun}"), start)
        check = f"find the {obj} {place}" + (f" in the {room}" if room and room not in place else "")  # "in bed": the bedroom
        seen = self.memory.recall(self.world.name, obj)
        if seen is None and not is_object_word(obj):  # a thing the parser has no word for: search for it
            return self._where(text, Intent("where", f"where is the {obj}"), start)
        if seen is None and self.services.search_mode != "sensed":  # the simulator's map answers (oracle)
            mapped = self._from_map(text, intent, obj, room, start, place)
            if mapped is not None:
                return mapped
        if seen is None:  # nothing remembered: go and look there
            turn = self._command(check, start, original=text)
            turn.intent = intent.name
            if turn.action in ("fetch", "search") and not self._redirected:  # (a search redirected says so)
                turn.reply = f"I haven't seen your {obj} yet, so I'll go and look. {turn.reply}"
                self.last_said = turn.reply
            return turn
        agrees = (room is None or seen.room == room) and (word is None or seen.furniture_word == word) \
            and self._same_model(place, seen)
        if re.match(r"(?:by|near|next to|beside|close to|around) ", place) and word is not None \
                and seen.x_m is not None and (room is None or seen.room == room):
            # "is the fork by the couch?" of a fork seen on the table behind the couch: by it, yes;
            # "… next to the dinner table?" of the same fork: no, whatever it lay on
            landmark = re.sub(r"^(?:by|near|next to|beside|close to|around) (?:the |my |our )?", "", place)
            landmark = re.sub(r" (?:in|inside) (?:the|my|our) [a-z ]+$", "", landmark)
            agrees = any(math.dist((f.x, f.y), (seen.x_m, seen.y_m)) < 1.2 + max(f.spec.length_m, f.spec.width_m) / 2
                         for f in (matching(furniture, landmark) or matching(furniture, word)) if f.room == seen.room)
        at = self._seen_at(obj, seen)
        if agrees:
            self.pending = {"kind": "confirm", "command": fetch_command_text(obj, seen.phrase, seen.room),
                            "object": obj}
            reply = f"Yes — {at}. Shall I go over to {it_them(obj)}?"
        else:
            self.pending = {"kind": "confirm", "command": check, "object": obj}
            reply = f"{'Not as far as I know' if seen.told else 'Not when I last looked'}: {at}. " \
                    f"Shall I go and check {place}?"
        return self._turn(text, intent.name, reply, "answer", "answered", start, object=obj, source="memory",
                          memory=seen.to_dict(), agrees=agrees)

    def _said_models(self, place: str) -> set[str]:
        """The furniture models of this home a place names ("on the coffee table" → coffee table)."""
        return {f.model for f in self.world.scene(self.scene).furniture
                if re.search(rf"\b{re.escape(f.model)}s?\b", place)}

    def _support_models(self, place: str) -> set[str]:
        """The furniture models a place says a thing lies on ("on the coffee table"); none for a
        place told by furniture near it ("near the bed", "next to the couch")."""
        return self._said_models(place) if re.match(r"(?:on|on top of|upon|at)\b", place) else set()

    def _same_model(self, place: str, seen) -> bool:
        """Whether a remembered place can be the kind of furniture a place names: "is it on the
        coffee table?" of a mug seen on a round table is a no (it had said "Yes — … on the table")."""
        said = self._support_models(place)
        if not said:
            return True
        items = {f.id: f for f in self.world.scene(self.scene).furniture}
        if seen.furniture in items:
            return items[seen.furniture].model in said
        if seen.x_m is not None:  # the robot's own furniture (a detector's id): the piece the thing lay on
            under = [f for f in items.values() if f.word == seen.furniture_word and _lies_on(seen, f)]
            if under:
                return min(under, key=lambda f: math.dist((f.x, f.y), (seen.x_m, seen.y_m))).model in said
        models = self._said_models(seen.phrase or "")
        return not models or bool(models & said)

    def _from_map(self, text: str, intent, obj: str, room: str | None, start: float,
                  said_place: str = "") -> Turn | None:
        """A yes-or-no place question answered from the simulator's map of the home (the oracle
        search: nothing is remembered), as :meth:`_where` answers a where-question; None when
        the map has no such thing or neither a room nor a kind of furniture was asked about
        ("is it on the coffee table?": the kind the map has it on is compared)."""
        from assistant.generation import oracle_sighting

        scene = self.world.scene(self.scene)
        models = self._support_models(said_place)
        sighting = oracle_sighting(self.world, self.scene, obj)
        result = self._describe(obj, "static") if sighting is not None and (room is not None or models) else None
        if result is None or not result.found:
            return None
        place = re.sub(rf"^the {re.escape(obj)} (is|are) ", "", result.description.rstrip("."), flags=re.I)
        self.pending = {"kind": "confirm", "command": f"bring me the {obj} {place}", "object": obj}
        on = {f.id: f for f in scene.furniture}.get(next((o.on for o in scene.objects if o.name == obj), None))
        agrees = (room is None or sighting.room == room) and (not models or (on is not None and on.model in models))
        said = result.description[:1].lower() + result.description[1:]
        reply = (f"{'Yes' if agrees else 'No'} — {said} (That is from the simulator's map of the home: "
                 f"I haven't seen {it_them(obj)} myself yet.) Shall I go over to {it_them(obj)}?")
        return self._turn(text, intent.name, reply, "describe", "answered", start, object=obj, source="simulator",
                          agrees=agrees)

    def _told(self, text: str, intent, start: float) -> Turn:
        """"remember that my keys are on the coffee table in the living room", "I've put my
        glasses on the table by the bed", "my wallet's in the office and my phone is on the bed":
        each thing kept in the memory as told (no drive to check); the room is the one named, or
        the only one with the furniture named."""
        told = []
        for thing, place in told_places(intent.text):
            kept = self._tell(thing, place)
            if isinstance(kept, str):  # what it cannot keep, said back
                return self._turn(text, intent.name, kept, "clarify" if kept.startswith("Which") else "answer",
                                  "asked" if kept.startswith("Which") else "not_understood", start)
            if isinstance(kept, Turn):
                return kept
            told.append(kept)
        ask = next((k["ask"] if len(told) == 1 else k["ask_named"] for k in reversed(told) if k["ask"]), "")
        said = _join([k["said"] for k in told])
        data = {"object": told[-1]["object"], "source": TOLD, "memory": told[-1]["memory"]}
        if len(told) > 1:
            data["objects"] = [k["object"] for k in told]
        return self._turn(text, intent.name, f"OK — I'll remember that {said}.{ask}", "answer", "answered", start,
                          **data)

    def _told_again(self, text: str, obj: str, place: str, start: float) -> Turn:
        """A told place put right just after it was said: "no, actually they're in the small room"."""
        if place.startswith("the "):  # "no wait, the living room": in a room, on a piece of furniture
            place = f"in {place}" if self._room_in(place) is not None and not self._furniture_rooms(place)[0] \
                else f"on {place}"
        kept = self._tell(f"my {obj}", place)
        if isinstance(kept, Turn):
            return kept
        if isinstance(kept, str):
            return self._turn(text, "told", kept, "answer", "not_understood", start)
        return self._turn(text, "told", f"Got it — {kept['said']}.{kept['ask']}", "answer", "answered", start,
                          object=obj, source=TOLD, memory=kept["memory"])

    def _forget(self, text: str, intent, start: float) -> Turn:
        """"forget what I told you about my keys": the memory of that thing goes (told or seen)."""
        thing = re.match(FORGET_THING, intent.text).group("thing")
        obj = self._object_in(thing)[0]
        if obj is None:
            noun = re.sub(r"^(my|the|our|his|her) ", "", thing)
            return self._turn(text, intent.name, f"I have nothing noted about {article(noun)} {noun}.", start=start)
        self.pending = None
        if self.memory.recall(self.world.name, obj) is None:
            return self._turn(text, intent.name, f"I have nothing noted about your {obj}.", start=start, object=obj)
        self.memory.forget(self.world.name, obj)
        return self._turn(text, intent.name, f"OK — I've forgotten where your {obj} {is_are(obj)}.", "none",
                          "cancelled", start, object=obj)

    def _tell(self, thing: str, place: str):
        """Keep one told place: {"said", "object", "memory", "ask"} — or a reply (a string, or
        the :class:`Turn` for a room this home lacks) when it cannot."""
        place = re.sub(WHEN_SAID, "", place).strip()  # "… to the bedroom this morning"
        place = re.sub(r"^into ", "in ", re.sub(r"^(to|onto) ", "on ", place))  # "I moved it to the coffee table"
        if (said_room := self._room_in(place)) is not None and re.fullmatch(
                rf"(?:on|in|at) (?:the|my|our) {re.escape(said_room)}", place):
            place = f"in the {said_room}"  # "I moved it to the bedroom": in it, not on it
        noun = re.sub(r"^(my|the|our|his|her) ", "", thing)
        if noun in PEOPLE_AND_PETS:  # "my son is in the living room": no thing
            return "I can only keep track of things, not people or pets — but I can tell you where your things are."
        obj = self._last_object() if noun in ("it", "them") else self._object_in(thing)[0]
        if obj is None and noun in ("it", "them"):
            return "Which of your things do you mean? Say, for example, \"I've put my keys on the table in the hallway\"."
        if obj is None:
            return f"I don't know what {article(noun)} {noun} is, so I can't keep track of it."
        place = re.sub(r"\bmy\b", "your", place)  # "in my bag": said back as "in your bag"
        room = self._room_in(place)
        missing = unknown_room_named(place.split(), self.world) if room is None else None
        if missing is not None:
            return self._no_room(place, "told", missing, time.perf_counter())
        word, homes = self._furniture_rooms(place)
        if room is None and len(homes) == 1:
            room = homes[0]
        phrase = re.sub(rf"\s*\b(in|inside) (the|my|our) {re.escape(room)}$", "", place).strip() if room else place
        if phrase in ("", "in the", "in") or re.fullmatch(r"(in|inside) (the|my|our) [a-z ]+", phrase):
            phrase = None  # only the room was said
        seen = self.memory.remember(self.world.name, obj, room, None, word, phrase, source=TOLD)
        named_room = room is not None and phrase is not None and re.search(rf"\b{re.escape(room)}\b", phrase)
        where = " ".join(p for p in (phrase, f"in the {room}" if room and not named_room else "") if p)
        ask = ""
        if room is None and phrase and len(homes) > 1:  # "on the round table": there is one in two rooms
            self.pending = {"kind": "told_room", "object": obj, "word": word, "phrase": phrase, "rooms": homes}
            ask = (f" Which room {'are they' if it_them(obj) == 'them' else 'is it'} in — "
                   f"{_join(['the ' + r for r in homes], 'or')}?")
        return {"said": f"your {obj} {is_are(obj)} {where}", "object": obj, "memory": seen.to_dict(), "ask": ask,
                "ask_named": ask and f" Which room {is_are(obj)} your {obj} in — {_join(['the ' + r for r in homes], 'or')}?"}

    def _furniture_rooms(self, place: str) -> tuple[str | None, list[str]]:
        """The first furniture word of a place ("on the table next to the bed" → "table") and
        the rooms that have every piece of furniture it names (only the bedroom has a bed)."""
        words = list(dict.fromkeys(w for w in map(furniture_category, place.split()) if w is not None))
        rooms = self._rooms_with(words) if words else []
        if len(rooms) > 1:  # "on the desk": the rooms with a desk, not every room with a table
            furniture = self.world.scene(self.scene).furniture
            models = self._said_models(place)
            with_models = [r for r in rooms if all(any(f.room == r and f.model == m for f in furniture)
                                                   for m in models)]
            rooms = with_models if models and with_models else rooms
        return (words[0] if words else None), rooms

    def _on_furniture(self, text: str, intent, start: float) -> Turn:
        """"what else is on the table?", "is there anything on the bed?": the things the memory
        has on that kind of furniture (in the room named), each with where and when."""
        m = re.search(ON_FURNITURE, intent.text)
        said, named = m.group("furniture"), m.group("room")
        word = furniture_category(said) or furniture_category(singular(said.split()[-1]))
        room = next((r for r in self.rooms if named and named.strip() == r), None)
        if named and room is None:
            return self._no_room(text, intent.name, named, start)
        if word is None:
            return self._turn(text, intent.name, f"I don't know what the {said} is — I know tables, chairs, couches "
                              "and beds.", "answer", "not_understood", start, unknown=said)
        entries = sorted((s for s in self.memory.sightings(self.world.name)
                          if s.furniture_word == word and (room is None or s.room == room)), key=lambda s: -s.time_s)
        furniture = self.world.scene(self.scene).furniture
        pieces = [f for f in furniture if f.model == singular(said)] or [f for f in furniture if f.word == word]
        landmark = m.group("landmark")
        if landmark:  # "the table next to the bed": the tables standing there
            side = RELATION_SIDES[m.group("rel")]
            by = {g.id for ref in matching(furniture, landmark) if room is None or ref.room == room
                  for g, _ in furniture_by(self.world, self.scene, ref.id, side)}
            pieces = [f for f in pieces if f.id in by]
            said = f"{said} {m.group('rel')} the {landmark}"
        if landmark or len(pieces) < sum(f.word == word for f in furniture):  # not every table
            entries = [s for s in entries if any(_lies_on(s, f) for f in pieces)
                       or (s.furniture is None and s.x_m is None and said in (s.phrase or ""))]
        where = f" in the {room}" if room else ""
        if not entries:
            return self._turn(text, intent.name, f"I don't know of anything on the {said}{where}: I only know what "
                              f"I've seen or been told. Ask me, for example, \"is my mug on the {said}?\"", start=start)
        parts = [f"your {s.object}{_seen_place(s)} ({'you told me' if s.source == 'told' else 'seen'} "
                 f"{self.memory.age(s)})" for s in entries[:SEEN_LIST_MAX]]
        return self._turn(text, intent.name, f"On the {plural(word) if len(entries) > 1 else word}{where} I know of "
                          f"{_join(parts)}.", start=start, objects=[s.object for s in entries])

    def _what_known(self, text: str, intent, start: float) -> Turn:
        """"what objects can you recognise?", "can you recognise my slippers?": the things this
        home's map has, honestly — others can be looked for by name, but it may not know them."""
        known = sorted(known_object_names(self.world))
        listed = _join(known)
        m = re.search(r"(?:recogni[sz]e|detect|identify|tell|know what) (?:what )?(?:a |an |my |the |our |his |her |some )"
                      r"(?P<thing>[a-z]+(?: [a-z]+)?)", intent.text)
        if m is None:
            return self._turn(text, intent.name, f"The things I know of in this home are: {listed}. I can look for "
                              "anything else you name too, but I may not know it when I see it. Tell me where a thing "
                              "is and I'll remember it.", start=start, objects=known)
        said = re.sub(r" (?:look|looks) like$", "", m.group("thing"))
        obj = self._object_in(f"my {said}")[0]
        if obj in known:
            return self._turn(text, intent.name, f"Yes — I know your {obj} when I see {it_them(obj)}. Ask me \"where "
                              f"{is_are(obj)} my {obj}?\" and I'll look.", start=start, object=obj)
        return self._turn(text, intent.name, f"I don't know of {'any' if said.endswith('s') else article(said)} "
                          f"{said} in this home, so I may not know {'them' if said.endswith('s') else 'it'} when I see "
                          f"{'them' if said.endswith('s') else 'it'}. I can still look if you like — or tell me where "
                          f"{'they are' if said.endswith('s') else 'it is'} and I'll remember. The things I know of here "
                          f"are: {listed}.", start=start, unknown=said)

    def _near_furniture(self, text: str, intent, start: float) -> Turn:
        """"what's next to the bed?", "anything behind the couch?": the furniture standing there
        (``dialogue.nearby``, from the home's map) and the things remembered on it."""
        rel, said, named = near_question(intent.text)
        room = self._room_in(f"the {named}") if named else None
        if named and room is None:
            return self._no_room(text, intent.name, named, start)
        furniture = self.world.scene(self.scene).furniture
        found = [f for f in matching(furniture, said) if room is None or f.room == room]
        if not found:
            return self._turn(text, intent.name, f"I don't know of {article(said)} {said} "
                              f"{f'in the {room}' if room else 'here'}.", "answer", "not_understood", start,
                              unknown=said)
        if len(found) > 1:
            rooms = _join(sorted({f"the {f.room}" for f in found}))
            return self._turn(text, intent.name, f"There are {NUMBER_WORDS.get(len(found), len(found))} "
                              f"{plural(found[0].word)} here, in {rooms} — which one? Say, for example, \"what's "
                              f"{rel} the {found[0].model} in the {found[0].room}?\"", "clarify", "asked", start)
        reference = found[0]
        by = furniture_by(self.world, self.scene, reference.id, RELATION_SIDES[rel])
        name = f"the {said}"
        if not by:
            return self._turn(text, intent.name, f"Nothing stands {rel} {name} in the {reference.room} that I know of.",
                              start=start, room=reference.room)
        pieces = [f"the {f.model}{'' if RELATION_SIDES[rel] else ' (' + SIDE_WORDS.get(side, 'there') + ')'}"
                  for f, side in by]
        reply = (f"{_capital(rel)} {name} in the {reference.room} {'is' if len(pieces) == 1 else 'are'} "
                 f"{_join(pieces)}.")
        things = []
        for s in sorted(self.memory.sightings(self.world.name), key=lambda s: -s.time_s):
            on = next((f for f, _ in by if _lies_on(s, f)), None)
            if on is not None:
                how = "you told me" if s.told else "seen"
                things.append(f"your {s.object} on the {on.model} ({how} {self.memory.age(s)})")
        if things:
            reply += f" On {'it' if len(by) == 1 else 'them'} I know of {_join(things[:SEEN_LIST_MAX])}."
        return self._turn(text, intent.name, reply, start=start, room=reference.room,
                          furniture=[f.id for f, _ in by])

    def _seen_at(self, obj: str, seen) -> str:
        """Where a remembered thing is, said with where the memory came from: "I saw your mug 3
        minutes ago on the table …" or "you told me an hour ago that your keys are on …"."""
        if seen.told:
            told = f"you told me {self.memory.age(seen)} that your {obj} {is_are(obj)}{_seen_place(seen)}"
            return told + (f", but I couldn't see {it_them(obj)} there when I looked" if seen.source == TOLD_NOT_SEEN
                           else "")
        return f"I saw your {obj} {self.memory.age(seen)}{_seen_place(seen)}"

    def _last_object(self) -> str | None:
        """The thing the conversation was last about ("is *it* in the bedroom?")."""
        for t in reversed(self.history):  # a turn about a thing, or a question asked about one's plan
            found = t.data.get("object") or (t.data.get("plan") or {}).get("object")
            if found:
                return found
        return None

    def _search(self, said: str, intent_name: str, obj: str, style: str, start: float,
                lead: str | None = None) -> Turn:
        """Start the robot's own search for ``obj`` (a worker thread, like a fetch)."""
        if self.busy:
            return self._turn(said, intent_name, "I'm still busy with the last task — say \"stop\" first.",
                              "none", "busy", start)
        reply = lead or f"I haven't seen your {obj} yet — I'll go and look for {it_them(obj)}."
        return self._start_job("search", said, reply, obj, None, obj, start, intent_name=intent_name,
                               style=style, source="search", object=obj)

    def _describe(self, obj: str, style: str, seen=None):
        """The generation layer's answer, the way ``assistant where --search oracle`` composes it
        (the furniture from the simulator's world file; the object's position from there too, or
        from the memory's entry ``seen``): a :class:`~assistant.generation.types.GeneratedDescription`."""
        remembered = None
        if seen is not None:
            from assistant.geometry import Pose2D
            from assistant.perception.objects import Sighting

            remembered = Sighting(obj, seen.x_m, seen.y_m, 0.7, room=seen.room,
                                  seen_from=Pose2D(seen.x_m, seen.y_m, 0.0))
        return self.services.describe(obj, self.world, self.scene, style, remembered).description

    # ------------------------------------------------------------------ teaching
    def _teach(self, text: str, start: float) -> Turn:
        phrase = teach_phrase(text)
        if not phrase or phrase in VAGUE_PHRASES:
            return self._turn(text, "teach", "What would you like to show me? Say it like: let me show you "
                              "what 'in front of the couch' means.", "clarify", "asked", start)
        plan = self.services.parser(self.world).parse(f"go to the table {phrase}").plan
        rdts = [str(n) for n in plan.nodes if "table" in str(n) or not str(n).endswith("-table")]
        rdts = [r for r in rdts if r != "room-center-table" or "middle" in phrase or "center" in phrase
                or "centre" in phrase]
        if not rdts:
            return self._turn(text, "teach", f"I can't tell which place '{phrase}' describes — try a phrase "
                              "like 'in front of the couch' or 'to the left of the bed'.", "none",
                              "not_understood", start, phrase=phrase)
        rdt = rdts[0]
        reply = (f"Please show me '{phrase}' ({rdt}): drive me with the arrow keys or w/a/s/d, "
                 "q when you're done, Esc to give up.")
        return self._turn(text, "teach", reply, "teach", "started", start, rdt=rdt, phrase=phrase,
                          world=self.world.name, scene=self.scene)

    # ------------------------------------------------------------------ fetch commands
    def _substitute(self, text: str) -> str:
        for word, replacement in self.synonyms.items():
            text = re.sub(rf"\b{re.escape(word)}\b", replacement, text, flags=re.I)
        return text

    def _command(self, text: str, start: float, force: bool = False, original: str | None = None) -> Turn:
        self._redirected = False
        self.last_choice = None
        if not force and not self._stepping and STEP_BREAK.search(text):
            here = self.world.floorplan.room_at(self.world.start.x, self.world.start.y)
            if here is not None:  # "…, then come back": to the room it set out from
                text = re.sub(r"(?<=then )(?:please )?(?:come|go) back(?: here| to me| to where you started| to the start)?"
                              r"(?=$|[ ,.!])", f"go back to the {here.name}", text, flags=re.I)
            steps = split_steps(text, self._step_room)
            if len(steps) > 1:  # "go to the living room, then go to the bedroom": one step at a time
                turn = self._command(steps[0], start, original=original or text)
                if turn.action in ("fetch", "clarify") and turn.outcome in ("started", "asked"):
                    self.steps = steps[1:]
                    if turn.action == "fetch":
                        turn.reply = f"{turn.reply} After that, {_join([step_place(s) for s in steps[1:]], 'and then')}."
                        self.last_said = turn.reply
                return turn
        turn = self._command_turn(text, start, force, original)
        if self._redirected and turn.reply:  # a search stopped for what the person just told
            turn.reply = f"OK, I'll stop searching. {turn.reply}"
            self.last_said = turn.reply
        return turn

    # ------------------------------------------------------------------ how far
    @functools.cached_property
    def _walls_map(self):
        """The occupancy the robot plans on with nothing perceived: the floor plan's walls and doors."""
        from assistant.executor.planning import build_occupancy

        return build_occupancy(self.world)

    def _how_far(self, text: str, intent, start: float) -> Turn:
        """"how far is the bedroom?", "is my mug far?", "which is closer, the couch or the bed?":
        the length of the robot's route there over the floor plan (``dialogue.distances``)."""
        asked = how_far_question(intent.text)
        goals = []
        for said in asked.places:
            goal = self._distance_goal(said)
            if isinstance(goal, str):  # what it cannot place, said back
                return self._turn(text, intent.name, goal, "answer", "not_understood", start, unknown=said)
            goals.append(goal)
        here, _ = self.robot_xy()
        if asked.origin is not None:  # "how far is the couch from the bed?"
            origin = self._distance_goal(asked.origin)
            if isinstance(origin, str):
                return self._turn(text, intent.name, origin, "answer", "not_understood", start, unknown=asked.origin)
            distance, _ = floor_distance_m(self._walls_map, origin.xy, goals[0].xy)
            goal = goals[0]
            verb = is_are(goal.object) if goal.object else "is"
            return self._turn(text, intent.name, f"{_capital(goal.name)} {verb} {spoken_distance(distance)} from "
                              f"{origin.name}.{goal.note}", start=start, distance_m=round(distance, 2), place=goal.name)
        metres = [floor_distance_m(self._walls_map, here, g.xy) for g in goals]
        if len(goals) == 2:
            (da, _), (db, _) = metres
            a, b = goals
            if abs(da - db) < 1.0:
                reply = (f"They're about as far as each other: {a.name} {spoken_distance(da)} from me, "
                         f"{b.name} {spoken_distance(db)}.")
            else:
                ranked = sorted(zip(goals, metres), key=lambda gm: gm[1][0], reverse=not asked.nearer)
                (first, (d1, _)), (second, (d2, _)) = ranked
                reply = (f"{_capital(first.name)} is {'closer' if asked.nearer else 'further'}: {spoken_distance(d1)} "
                         f"from me, and {second.name} {spoken_distance(d2)}.")
            return self._turn(text, intent.name, reply, start=start, distances_m=[round(d, 2) for d, _ in metres],
                              places=[g.name for g in goals])
        goal, (distance, by_floor) = goals[0], metres[0]
        self._last_distance_goal = goal
        here_room = self.robot_room()[0]
        data = {"distance_m": round(distance, 2), "place": goal.name, "room": goal.room}
        if goal.object:
            data["object"] = goal.object
        if goal.room is not None and goal.name == f"the {goal.room}" and here_room == goal.room:
            return self._turn(text, intent.name, f"I'm in the {goal.room} now.", start=start, **data)
        through = ""
        if goal.room is not None and here_room is not None and goal.room != here_room:
            path = self._room_path(here_room, goal.room)
            if path and len(path) > 2:
                through = f", through {_join([f'the {r}' for r in path[1:-1]])}"
        how = "" if by_floor else " as the crow flies (I know no way there)"
        where = ""
        if goal.room is not None and goal.name != f"the {goal.room}":
            where = f", here in the {goal.room}" if goal.room == here_room else f", in the {goal.room}"
        verb = is_are(goal.object) if goal.object else "is"
        reply = f"{_capital(goal.name)} {verb} {spoken_distance(distance)} from me{how}{where}{through}.{goal.note}"
        if goal.command and distance >= 1.5:
            self.pending = {"kind": "confirm", "command": goal.command, "object": goal.object}
            reply += " Shall I go there?"
        return self._turn(text, intent.name, reply, start=start, **data)

    def _distance_goal(self, said: str) -> "DistanceGoal | str":
        """Where a place asked "how far" about is — a room (its middle), a piece of furniture (the
        nearest of its kind), one of the person's things where the robot last saw it or was told,
        or "it" / "there" (the last place, thing or room talked about) — or a reply saying why it
        cannot tell."""
        words = re.sub(r"^(?:the|my|our|your|that|this) ", "", said.strip())
        if words in ("it", "that", "there", "they", "them", "this", "that one", "this one", "that room"):
            last = self.history[-1] if self.history else None
            if last is not None and last.intent == "how_far" and self._last_distance_goal is not None:
                return self._last_distance_goal  # "how far is the table?" … "is it far?"
            thing = self._last_object()
            if thing is not None:
                return self._distance_goal(f"my {thing}")
            room = next((t.data.get("room") for t in reversed(self.history) if t.data.get("room")), None)
            if room is not None:
                return self._distance_goal(f"the {room}")
            return "How far is what? Ask me, for example, \"how far is the bedroom?\""
        missing = unknown_room_named(words.split(), self.world)
        if missing is not None:
            return f"There is no {missing} here; the rooms are {_join(['the ' + r for r in self.rooms])}."
        room = self._room_in(words)
        if room is not None:  # "the table in the bedroom": the table, there
            words = re.sub(r"\s*\b(?:in|inside|of) (?:the|my|our) [a-z ]+$", "", words) or words
        furniture = self.world.scene(self.scene).furniture
        found = matching(furniture, words) if words else []
        if room is not None and not found:
            centre = self.world.floorplan.room(room).centre
            return DistanceGoal(f"the {room}", (float(centre[0]), float(centre[1])), room,
                                command=f"go to the {room}")
        if found:
            if room is not None:
                found = [f for f in found if f.room == room] or found
            nearest = self._nearest(found)
            name = f"the {words if len(found) == 1 else nearest.model}"
            there = f"in the {room}" if room is not None and all(f.room == room for f in found) else "here"
            note = "" if len(found) == 1 else (f" (That's the nearest of the {NUMBER_WORDS.get(len(found), len(found))}"
                                               f" {plural(nearest.word)} {there}.)")
            return DistanceGoal(name, (nearest.x, nearest.y), nearest.room, note,
                                command=f"go to the {nearest.model} in the {nearest.room}")
        obj = self._object_in(said)[0]
        if obj is None:
            return (f"I don't know where {said} is. Ask me how far a room, a piece of furniture or one of your "
                    "things is, for example \"how far is the bedroom?\"")
        fetch = f"bring me the {obj}"
        seen = self.memory.recall(self.world.name, obj)
        if seen is not None and seen.x_m is not None:
            return DistanceGoal(f"your {obj}", (seen.x_m, seen.y_m), seen.room, command=fetch, object=obj)
        if seen is not None and seen.room is not None:
            centre = self.world.floorplan.room(seen.room).centre
            return DistanceGoal(f"your {obj}", (float(centre[0]), float(centre[1])), seen.room,
                                f" (You told me it's there; I haven't seen {it_them(obj)} myself.)", fetch, obj)
        if self.services.search_mode != "sensed":
            from assistant.generation import oracle_sighting

            sighting = oracle_sighting(self.world, self.scene, obj)
            if sighting is not None:
                return DistanceGoal(f"your {obj}", (sighting.x_m, sighting.y_m), sighting.room,
                                    f" (That is from the simulator's map of the home: I haven't seen {it_them(obj)} "
                                    "myself yet.)", fetch, obj)
        return (f"I don't know where your {obj} {is_are(obj)} yet, so I can't say how far. Ask me \"where "
                f"{is_are(obj)} my {obj}?\" and I'll look.")

    def _room_path(self, here: str, room: str) -> list[str] | None:
        """The rooms from ``here`` to ``room`` by the floor plan's doors and openings, or None."""
        import networkx as nx

        try:
            return nx.shortest_path(self.world.floorplan.room_graph(), here, room)
        except (nx.NetworkXNoPath, nx.NodeNotFound):
            return None

    def _room_route(self, room: str) -> str | None:
        """The rooms to go through from the robot's room to ``room`` ("From the hallway, go through
        the living room into the office."), by the floor plan's doors and openings; None when the
        robot is in that room."""
        here = self.robot_room()[0]
        if here == room:
            return None
        if here is None:
            return f"The {room} is one of the rooms here."
        path = self._room_path(here, room)
        if path is None:
            return f"I know no way from the {here} into the {room}."
        through = f" through {_join([f'the {r}' for r in path[1:-1]])}" if len(path) > 2 else ""
        return f"From the {here}, where I am, go{through} into the {room}."

    def _bare_place(self, norm: str) -> str | None:
        """The piece of furniture or room said alone as a request ("couch please", "now the
        bed", "the blue chair please"), or None; said alone with nothing around it ("couch") it
        is a question, answered elsewhere."""
        m = re.fullmatch(r"(?:(?P<lead>now|then|and then|next|and now|ok|okay|um|uh) )*(?:the |my )?"
                         r"(?P<place>[a-z]+(?: [a-z]+)??)(?P<tail>(?: please| now| then| thanks)+)?", norm)
        if m is None or not (m["lead"] or m["tail"]):
            return None
        place = m["place"]
        furniture = self.world.scene(self.scene).furniture
        head = place.split()[-1]
        if place in self.rooms or any(place == f.model for f in furniture) or (
                furniture_category(singular(head)) is not None and all(
                    w in LOOKS or w in {x for f in furniture for x in f.model.split()} for w in place.split()[:-1])):
            return place
        return None

    def _furniture_kinds(self) -> str:
        """The kinds of furniture of this home: "beds, a couch, chairs and tables"."""
        furniture = self.world.scene(self.scene).furniture
        counts = {k: sum(f.word == k for f in furniture) for k in sorted({f.word for f in furniture})}
        return _join([plural(k) if n > 1 else f"{article(k)} {k}" for k, n in counts.items()])

    def _step_room(self, part: str) -> str | None:
        """The room one step of an errand sends the robot to (:mod:`~assistant.dialogue.steps`):
        of the rooms its words name, the grounded plan's, else the last said ("through the living
        room into the inner hall"); None when it names none (the grounders give a room even to
        "turn left")."""
        low = part.lower()
        named = sorted((m.start(), r) for r in self.rooms for m in re.finditer(rf"\b{re.escape(r)}\b", low))
        if not named:  # "then to the bed": the one room that has the piece of furniture said
            furniture = self.world.scene(self.scene).furniture
            said = [f for f in furniture if re.search(rf"\b{re.escape(f.model)}\b", low)] or [
                f for f in furniture if any(furniture_category(singular(w)) == f.word for w in low.split())]
            homes = {f.room for f in said}
            return homes.pop() if len(homes) == 1 else None
        plan = self.services.parser(self.world).parse(self._substitute(part)).plan
        return plan.room if plan.room in {r for _, r in named} else named[-1][1]

    def _command_turn(self, text: str, start: float, force: bool, original: str | None) -> Turn:
        said = original or text
        text = self._substitute(text)
        if (rather := NOT_BUT.match(text)) is not None:  # "not the bedroom, the living room": the second
            text = rather.group("right")
        look = re.fullmatch(r"(?:(?:please|now|then|and|can you|could you|will you) )*(?:check|check on|look at|have a look "
                            r"at|take a look at|inspect|visit)(?: out)? (?P<place>(?:the|my) [a-z ]+?)(?: please| now)*",
                            text.lower())
        if look is not None and self._furniture_rooms(look["place"])[0] is not None \
                and self._object_in(look["place"])[0] is None:
            text = f"go to {look['place']}"  # "check the couch": go and look at it
        if re.search(r"\b(?:of|to|by|near|beside|behind|next to) it\b", text, re.I) and self._last_object() is None:
            _, item = self._last_furniture()
            if item is not None:  # "go to the couch", "now the table in front of it": of the couch
                text = re.sub(r"\b(of|to|by|near|beside|behind|next to) it\b", rf"\1 the {item.model}", text, flags=re.I)
        parsed = self.services.parser(self.world).parse(text)
        plan = parsed.plan
        unused = [w for w in plan.unused if w.isalpha() and len(w) > 2 and w.lower() not in POLITE_WORDS]
        tags = dict(zip(parsed.analysis.tokens, parsed.analysis.pos))
        tokens = [str(t).lower() for t in parsed.analysis.tokens]
        # an unknown noun where a piece of furniture would be ("by the wardrobe"); one elsewhere
        # ("my mom keeps her glasses case …") is no landmark to ask about
        nouns = [w for w in unused if str(tags.get(w, "NN")).startswith(("NN", "FUR"))
                 and in_place_slot(tokens, w.lower())]
        # a landmark that is neither furniture nor a thing the robot knows ("by the wardrobe"): ask
        nouns += [r for n in plan.nodes for r, _ in n.pairs if r not in FURNITURE_WORDS.values()
                  and r not in STRUCTURE_REFERENCES and not is_object_word(r) and r not in nouns]
        room_words = self._room_words
        if plan.room is None:  # the parser missed a room the words name ("go to the bedroom")
            named = [r for r in self.rooms if re.search(rf"\b{re.escape(r)}\b", text.lower())]
            if len(named) == 1:
                thing = plan.object if plan.object not in room_words else None  # "inner" of "the inner hall"
                retry = f"go into the {named[0]}" if not (plan.nodes or thing) else f"{text} in the {named[0]}"
                again = self.services.parser(self.world).parse(retry).plan
                if again.room == named[0]:
                    text, plan = retry, again
        if plan.room is not None and plan.room not in self.rooms:  # a room another home has ("the bedroom")
            return self._no_room(said, "command", plan.room, start, "not_understood")
        nouns = [n for n in nouns if n.lower() not in room_words]  # "inner" of "the inner hall" is no unknown noun
        mentions = furniture_mentions(parsed.analysis.tokens, parsed.analysis.pos, self.world, self.scene)
        # the object named in the words when the plan lost it ("get the mug from the table")
        obj = plan.object or (self._object_in(" ".join(str(t).lower() for t in parsed.analysis.tokens))[0]
                              if plan.nodes or plan.room or mentions else None)
        if obj is not None and (set(obj.split()) <= room_words or obj in COMMON_ROOMS or obj in ROOM_ALIASES_SAID):
            # "the inner hall", "the lounge" name a room, not a thing
            obj = None
        missing = unknown_room_named([str(t).lower() for t in parsed.analysis.tokens], self.world) \
            if plan.room is None else None
        if missing is not None:  # "go to the kitchen" in a home with none
            return self._no_room(said, "command", missing, start, "not_understood")
        has_plan = bool(plan.nodes or plan.room or plan.object or (mentions and obj))
        if not has_plan:
            if unused:
                words = _join([f"'{w}'" for w in unused[:3]])
                return self._turn(said, "command", f"Sorry, I didn't understand that — I don't know "
                                  f"{'the word' if len(unused) == 1 else 'the words'} {words}. Say \"help\" "
                                  "to hear what I can do.", "none", "not_understood", start, unknown=unused)
            return self._turn(said, "command", "Sorry, I didn't understand that. Say \"help\" to hear what I can "
                              "do.", "none", "not_understood", start)
        strange = [m for m in mentions if not m.here and m.said not in self.synonyms]
        if not force and (nouns or strange):
            # a word the robot cannot tie to anything in this home: name it back and ask
            first = strange[0] if strange and (not nouns or strange[0].category is not None) else None
            furniture = self.world.scene(self.scene).furniture
            if first is not None and first.category is not None and singular(first.said) == first.category \
                    and not any(f.word == first.category for f in furniture):
                # "get the statue from the bed" in a home with no bed: say so, not "is it a bed?"
                return self._turn(said, "command", f"There is no {first.category} in this home — the furniture "
                                  f"here is {self._furniture_kinds()}.", "answer", "not_understood", start,
                                  unknown=[first.said])
            word = first.said if first is not None else nouns[0]
            suggest = first.category if first is not None else None
            self.pending = {"kind": "word", "word": word, "text": text, "original": said, "suggest": suggest}
            # a furniture word the robot knows, but no piece of this home is called so: which is it?
            ask = (f"I don't know which of the furniture here is the {word} — is it {article(suggest)} {suggest}?"
                   if suggest else f"I don't know the word '{word}' — is it a table, a chair, a couch or a bed?")
            return self._turn(said, "command", ask, "clarify", "asked",
                              start, unknown=[word] + [w for w in unused if w != word], plan=plan.to_dict())
        if self.busy and obj is not None and obj == self.worker.searching_for and (plan.room or plan.nodes):
            # "the remote is on the coffee table" while the robot searches for the remote: go there
            self.worker.stop(quiet=True)
            self._redirected = True
        elif self.busy and not self._stepping and re.match(r"(?:no|nope|not|wrong|sorry|actually|wait|oops)\b",
                                                           said.lower()):
            self.worker.stop(quiet=True)  # "no no, the living room" while driving: there at once
        elif self.busy and not self._stepping:  # (an errand's next step starts as the last one ends)
            return self._turn(said, "command", "I'm still busy with the last task — say \"stop\" first.",
                              "none", "busy", start)
        if is_motion_plan(plan) and re.match(r"^(?:no |and )?(?:the|that|this) (?:one|other one)\b", said.lower()):
            # "the one on the left" with no question open: a choice, not a turn
            return self._turn(said, "command", "Which one do you mean? Tell me the place, for example \"the "
                              f"table by the chair in the {self.rooms[-1]}\".", "clarify", "asked", start)
        if is_motion_plan(plan):  # "turn around", "back up a little": no room to ask for
            reply = describe_motion(plan.nodes)
            return self._start_job("fetch", said, reply[0].upper() + reply[1:] + ".", text, None, None, start,
                                   command=text, motion=True)
        room = plan.room
        remembered = self.memory.recall(self.world.name, obj) if obj else None
        if room is None and remembered is None and plan.nodes and plan.nodes[-1].target != NO_TARGET:
            # "go to the couch": the rooms that have one (a kind word said narrows them: "coffee table")
            node = plan.nodes[-1]
            items = [f for f in self.world.scene(self.scene).furniture if f.word == node.target]
            kind_words = [*node.descriptors, node.support] if node.support and node.support != node.target \
                else list(node.descriptors)  # "the desk": a table whose model is a desk
            kind_words += [w for w in text.lower().split() if w in LOOKS]  # "the blue chair": its model
            kinds = [f for f in items if any(d in f.model.split() for d in kind_words)]
            homes = [r for r in self.rooms if any(f.room == r for f in (kinds or items))]
            # the furniture it is told by ("the table next to the bed"): only a room with that too
            landmarks = {ref for n in plan.nodes for ref, _ in n.pairs if ref in FURNITURE_WORDS.values()}
            with_landmarks = self._rooms_with(landmarks)
            homes = [r for r in homes if r in with_landmarks] or homes
            # a landmark said by its kind ("the chair next to the hexagon table"): the rooms with one
            named = {f.room for f in self.world.scene(self.scene).furniture if f.model != f.word
                     and f.word != node.target and re.search(rf"\b{re.escape(f.model)}\b", text.lower())}
            homes = [r for r in homes if r in named] or homes
            if len(homes) == 1:
                room, text = homes[0], f"{text} in the {homes[0]}"
            elif homes and not force:
                self.pending = {"kind": "room", "text": text, "original": said, "rooms": homes,
                                "furniture": node.support or node.target}
                word = " ".join([*node.descriptors, node.support or node.target]) if kinds else node.target
                return self._turn(said, "command", f"Which room is the {word} in — "
                                  + _join([f"the {r}" for r in homes], "or") + "?", "clarify", "asked",
                                  start, missing="room", plan=plan.to_dict())
        if room is None:
            seen = self.memory.recall(self.world.name, obj) if obj else None
            if seen is not None and seen.room and not plan.nodes and not mentions:
                return self._start_fetch(said, fetch_command_text(obj, seen.phrase, seen.room), seen.room, obj,
                                         start, memory=seen.to_dict())
            if seen is not None and seen.room:
                room = seen.room
                text = f"{text} in the {room}"
            elif not force and obj and not plan.nodes and not is_object_word(obj) and not re.search(
                    REQUEST_WORDS, said.lower()):
                # "i'm feeling a bit lonely today", "thanks, you're a star": no thing asked for
                # (it had asked "Which room should I look for your today in …?")
                return self._turn(said, "command", "Sorry, I didn't understand that. I can look for your things, "
                                  "go to a room or a piece of furniture, or remember where you put something — say "
                                  "\"help\" for examples.", "none", "not_understood", start, unknown=[obj])
            elif not force:
                self.pending = {"kind": "room", "text": text, "original": said, "object": obj}
                rooms = _join(["the " + r for r in self.rooms], "or")
                what = f"your {obj}" if obj else "it"
                offer = " Or shall I search everywhere?" if obj and not plan.nodes else ""
                return self._turn(said, "command", f"Which room should I look for {what} in — {rooms}?{offer}",
                                  "clarify", "asked", start, missing="room", plan=plan.to_dict())
        if not force:
            dropped = unused_mentions(mentions, plan)
            words = [flag.split(":")[1] for flag in plan.flags if flag.startswith("ambiguous_target:")]
            words += [n.target for n in plan.nodes if not getattr(n, "referenced", True)
                      and n.target in FURNITURE_CHOICES]
            words += [m.category for m in dropped if m.category in FURNITURE_CHOICES]
            for word in dict.fromkeys(words):
                turn = self._which_or_go(said, text, word, room, obj, start, mentions, dropped=bool(dropped))
                if turn is not None:
                    return turn
        if obj and plan.object is None and not plan.nodes and room:  # the parser lost the object
            text = fetch_command_text(obj, None, room)
        return self._start_fetch(said, text, room, obj, start, plan=plan.to_dict(),
                                 ignored=unused)

    def _which_or_go(self, said, text, word, room, obj, start, mentions, dropped=False) -> Turn | None:
        """Several ``word``s in the room and nothing said picks one: a model name that singles
        one out ("the hexagon table") picks it, else ask which; when the plan dropped the
        furniture word and the room has just one, go to that one."""
        items = [f for f in self.world.scene(self.scene).furniture if f.word == word and (room is None or f.room == room)]
        if room is None or not items or (len(items) == 1 and not dropped):
            return None  # the only couch of the room: the words as said find it
        named = {str(getattr(m, "said", "")).lower() for m in mentions}
        # the kind said with the word ("the round table": its model's own word, not "table")
        named |= set(re.findall(r"[a-z]+", text.lower())) - {word, *FURNITURE_WORDS}
        models = [f for f in items if named & set(f.model.split())]  # "the desk": only the desks
        shown = word
        if 0 < len(models) < len(items):
            items = models
            shown = models[0].model if len({f.model for f in models}) == 1 else word  # "two round tables", "two desks"
        chosen = model_choice(mentions, items) if len(items) > 1 else (items[0] if dropped or models else None)
        if chosen is not None:
            phrase = furniture_phrase(self.services.describer, self.world, self.scene, chosen)
            turn = self._start_fetch(said, fetch_command_text(obj, phrase, chosen.room), chosen.room, obj, start)
            turn.data["chosen"] = chosen.id
            return turn
        return self._ask_which(said, text, word, room, obj, start, items, shown)

    def _ask_which(self, said, text, word, room, obj, start, items=None, shown=None) -> Turn | None:
        items = items or [f for f in self.world.scene(self.scene).furniture
                          if f.word == word and (room is None or f.room == room)]
        if len(items) < 2 or room is None:
            return None
        options = [self._option(item) for item in items]
        said_options = [("the one " + re.sub(rf"^on the {word} ", "", o["phrase"])) for o in options]
        if len(set(said_options)) < len(said_options) or any(o["phrase"] == f"on the {word}" for o in options):
            said_options = distinct_phrases(self.world, self.scene, items)
            for o, phrase in zip(options, said_options):
                o["phrase"] = phrase.replace("the one ", f"the {word} ", 1)
        count = NUMBER_WORDS.get(len(items), str(len(items)))
        reply = f"There are {count} {plural(shown or word)} in the {room} — {_join(said_options, 'or')}?"
        self.pending = {"kind": "which", "word": word, "room": room, "object": obj, "options": options,
                        "text": text, "original": said, "asked": reply}
        return self._turn(said, "command", reply, "clarify", "asked", start, options=options, object=obj)

    # ------------------------------------------------------------------ answers in context
    def _resolve(self, text: str, intent, start: float) -> Turn | None:
        p = self.pending
        norm = intent.text
        if intent.name in NEW_REQUESTS:  # a new request replaces the question (issue 16)
            self.pending = None
            return None
        if p["kind"] == "confirm":
            self.pending = None
            if intent.name == "yes" and p.get("search"):
                return self._search(text, "yes", p["search"], "static", start,
                                    lead=f"OK, I'll look for your {p['search']}.")
            if intent.name == "yes":
                return self._command(p["command"], start, force=True, original=text)
            if intent.name == "no":
                return self._turn(text, "no", "OK.", "none", "answered", start)
            return None
        if p["kind"] == "told_room":  # "OK — … on the round table. Which room is it in?": "the bedroom one"
            self.pending = None
            picked = ordinal_choice(norm)
            room = self._room_in(norm) or (p["rooms"][picked] if picked is not None and picked < len(p["rooms"])
                                           else None)
            if room is None and re.fullmatch(r"(?:(?:um|uh|well|oh|hmm) )*(?:(?:i )?(?:dont|do not) know|dunno|not sure|"
                                             r"no idea|either|either one|any|either of them|i forget|i cant remember|"
                                             r"(?:i )?(?:dont|do not) remember)(?: sorry| really)*", norm):
                obj = p["object"]  # kept without a room: "on the round table" it stays
                return self._turn(text, "told", f"That's fine — I'll just remember that your {obj} {is_are(obj)} "
                                  f"{p['phrase']}.", "answer", "answered", start, object=obj, source=TOLD)
            if room is None or room not in p["rooms"]:
                return None  # not an answer: handled as itself
            obj = p["object"]
            seen = self.memory.remember(self.world.name, obj, room, None, p["word"], p["phrase"], source=TOLD)
            return self._turn(text, "told", f"Got it — your {obj} {is_are(obj)} {p['phrase']} in the {room}.",
                              "answer", "answered", start, object=obj, source=TOLD, memory=seen.to_dict())
        if p["kind"] == "word":
            word = p["word"]
            if len(norm.split()) > 4 and intent.name == "command":  # "go to the blue chair": a new request
                self.pending = None
                return None
            choice = next((f for f in FURNITURE_CHOICES if re.search(rf"\b{f}s?\b", norm)), None)
            if choice is None and norm in ("sofa",):
                choice = "couch"
            if intent.name == "yes" and choice is None:
                choice = p.get("suggest") or "table"
            if choice is not None:
                self.pending = None
                self.synonyms[word.lower()] = choice
                return self._command(p["text"], start, original=text)
            if intent.name == "no" or re.search(r"\b(dont|do not) know\b|\bnot sure\b|\bno idea\b|\bneither\b|"
                                                r"\bnone of (them|those)\b", norm):
                self.pending = None
                return self._turn(text, "no", f"OK — then I can't use '{word}'. Could you say it another way, for "
                                  "example with the room and a piece of furniture near it?", "none", "not_understood",
                                  start)
            self.pending = None  # anything else is a new request
            return None
        if p["kind"] == "room":
            room = next((r for r in self.rooms if r in norm), None)
            if room is not None and intent.name == "command" and len(norm.split()) > 3 \
                    and self.services.parser(self.world).parse(text).plan.object is not None:
                self.pending = None  # "look for my mug in the bedroom": a request of its own, not an answer
                return None
            if room is None and p.get("object") and (intent.name == "yes" or re.search(ANYWHERE, norm)):
                self.pending = None  # "I don't know", "anywhere", "search everywhere": the robot searches
                return self._search(text, "command", p["object"], "static", start,
                                    lead=f"OK, I'll look for your {p['object']} everywhere.")
            offered = p.get("rooms") or self.rooms  # the rooms the question named, in its order
            if room is None and (i := ordinal_choice(norm)) is not None and -len(offered) <= i < len(offered):
                room = offered[i]  # "the first one", "the second"
            if room is None and p.get("furniture"):  # "go to the table": "the round one", "you choose"
                answer = self._furniture_answer(text, norm, p, start)
                if answer is not None:
                    return answer
            if room is None:
                plan = self.services.parser(self.world).parse(text).plan
                room = plan.room
            if room is not None:
                self.pending = None
                return self._command(f"{p['text']} in the {room}", start, original=text)
            rooms = _join(["the " + r for r in offered], "or")
            missing = unknown_room_named(norm.split(), self.world)
            if missing is not None:
                return self._turn(text, "answer", f"There is no {missing} here; the rooms are {rooms}. "
                                  "Which one should I look in?", "clarify", "asked", start, unknown_room=missing)
            if (intent.name == "command" and self._is_request(text)) or p.get("asked_again"):
                self.pending = None
                return None  # a new command replaces the question; asked twice, it is let go
            p["asked_again"] = True
            return self._turn(text, "answer", f"Sorry, which room — {rooms}?", "clarify", "asked", start)
        if p["kind"] == "which":
            index = self._choose(norm, text, p)
            thing = self._object_in(norm)[0] if index is None else None
            seen = self.memory.recall(self.world.name, thing) if thing else None
            if seen is not None and seen.furniture:  # "the one with the statue": where it was seen
                index = next((k for k, o in enumerate(p["options"]) if o["id"] == seen.furniture), None)
            if index is not None:
                self.pending = None
                return self._fetch_option(text, p, index, start)
            named = options_named(norm, p["options"], lambda: self.services.parser(self.world).parse(text).plan)
            if 1 < len(named) < len(p["options"]):  # "the one near the sofa": two are; which of them
                word = p.get("word") or "table"
                options = [p["options"][k] for k in named]
                asked = f"Which of those — {_join(_pointed(word, options), 'or')}?"
                self.pending = {**p, "options": options, "asked": asked}
                return self._turn(text, "answer", asked, "clarify", "asked", start, options=options)
            manner = self._choose_by_manner(norm, p["options"])
            if manner == "none":  # "neither": nothing goes
                self.pending = None
                return self._turn(text, "no", "OK, I won't go to any of them. Tell me another place if you like.",
                                  "none", "cancelled", start)
            if manner is not None:
                index, lead = manner
                self.pending = None
                return self._fetch_option(text, p, index, start, lead=lead)
            pointing = norm.startswith(("the one", "that one", "this one", "one ", "the other"))
            if (intent.name == "command" and not pointing and (len(norm.split()) > 5 or self._is_request(text))) \
                    or p.get("asked_again"):
                self.pending = None  # a request of its own; or not an answer twice: the question is let go
                return None
            p["asked_again"] = True
            return self._turn(text, "answer", "Sorry, I didn't get which one. " + p["asked"]
                              + " (You can also say \"the first\" or \"never mind\".)", "clarify", "asked", start)
        return None

    def _fetch_option(self, text: str, asked: dict, index: int, start: float, lead: str = "") -> Turn:
        """Fetch from the ``index``-th option of a which-question (``asked``: the pending
        question); remembered with the options tried so far, so "no, the other one" can turn
        to another."""
        option = asked["options"][index]
        command = fetch_command_text(asked["object"], option["phrase"], option["room"])
        turn = self._command(command, start, force=True, original=text)
        turn.data["chosen"] = option["id"]
        if turn.action == "fetch":
            every = asked.get("all", asked["options"])
            self.last_choice = {**asked, "options": every, "all": every,
                                "tried": [*asked.get("tried", []), option["id"]]}
            if lead:
                turn.reply = f"{lead} {turn.reply}"
                self.last_said = turn.reply
        return turn

    def _other_one(self, text: str, norm: str, start: float) -> Turn | None:
        """"no, the other one", "wrong one", "not that one — the one by the chair" after the robot
        went to the piece of furniture picked from a which-question: another of those options (the
        only one not tried yet, or the one pointed at, or the question again without the ones
        tried); a task still running is stopped first. None when the words are not such a
        correction."""
        m = re.match(CORRECTION, norm)
        if m is None:
            return None
        rest = norm[m.end():].strip()
        lead = norm[:m.end()]
        if not re.search(r"\b(no|nope|nah|not|wrong|sorry|meant|mean|actually|said)\b", lead) \
                and not re.search(r"\bother\b", rest):
            return None  # "go to the table …", "check the bedroom": a request, not a correction
        last = self.last_choice or self._last_visited()
        word = (last or {}).get("word") or "table"
        if rest not in ("", "other", "the other", "other one", "the other one", word, f"the other {word}") \
                and not rest.startswith(("the one", "that one", "one ", f"the {word}", "the other one ")):
            return None
        if last is None:
            return self._turn(text, "command", "Which one do you mean? Tell me the place, for example \"the table "
                              f"by the chair in the {self.rooms[-1]}\".", "clarify", "asked", start)
        others = [o for o in last["options"] if o["id"] not in last["tried"]] \
            or [o for o in last["options"] if o["id"] != last["tried"][-1]]  # each tried: all but the last
        if not others:
            return None
        if self.busy:
            self.worker.stop(quiet=True)
        remaining = {**last, "options": others}
        index = None
        if len(others) == 1:
            index = 0
        elif rest.startswith(("the one", "that one", "one ", f"the {word} ")):
            index = self._choose(rest, rest, remaining)
        if index is not None:
            phrase = re.sub(r"^(?:on|at|by|in) ", "", others[index]["phrase"])
            return self._fetch_option(text, remaining, index, start, lead=f"Sorry — {phrase}, then.")
        said = _join(_pointed(word, others), "or")
        reply = f"Sorry — which {word}, then: {said}?"
        self.pending = {**remaining, "kind": "which", "asked": f"Which {word} do you mean: {said}?"}
        self.last_choice = None
        return self._turn(text, "command", reply, "clarify", "asked", start, options=others)

    def _other_room(self, text: str, norm: str, start: float) -> Turn | None:
        """"sorry, I meant the bedroom", "wrong room — the bedroom": the last fetch or search
        again, for the thing it was about, in the room now named; None when the words are not
        such a correction or no thing was talked of."""
        norm = NOT_BUT.sub(r"no \g<right>", norm)  # "not the bedroom, the living room"
        if re.fullmatch(r"(?:(?:no|oh|sorry) )*(?:wrong room|not that room|wrong way|wrong place|not this room)", norm):
            if self.busy:  # "wrong room" while driving: stop, and ask
                self.worker.stop(quiet=True)
            rooms = _join(["the " + r for r in self.rooms], "or")
            return self._turn(text, "command", f"Sorry — which room then: {rooms}?", "clarify", "asked", start)
        m = re.match(r"^(?:(?:no|sorry|oh|actually|i meant|i mean|i said|wrong room|not that room|not there)\b ?)+"
                     r"(?:(?:try|check|look in|go to|its in|it is in|theyre in|they are in|in) )?(?:the |my )?"
                     r"(?P<room>[a-z ]+?)(?: then| please| instead)*$", norm)
        if m is None or not re.match(r"^(no|sorry|oh|actually|i meant|i mean|i said|wrong room|not that room|not there)\b",
                                     norm):
            return None
        room = next((r for r in self.rooms if m.group("room") == r), None)
        obj = self._last_object()
        if room is None and m.group("room") in ("other room", "other one room", "other place") and obj is not None:
            return self._the_other_room(text, obj, start)
        other = re.fullmatch(r"other (?P<kind>[a-z]+(?: [a-z]+)?)", m.group("room"))
        if other is not None and (only := self._room_in(other.group("kind"))) is not None:
            # "no, the other bedroom" in a home with one bedroom
            rooms = _join(["the " + r for r in self.rooms])
            return self._turn(text, "command", f"There's only one {only} here — the rooms are {rooms}. Which one "
                              "did you mean?", "clarify", "asked", start)
        missing = unknown_room_named(m.group("room").split(), self.world) if room is None else None
        if missing is not None:
            return self._no_room(text, "command", missing, start)
        if room is None or obj is None:
            return None
        if self.busy:
            self.worker.stop(quiet=True)
        return self._command(f"find the {obj} in the {room}", start, original=text)

    def _other_thing(self, text: str, norm: str, start: float) -> Turn | None:
        """"no, not the mug — the glasses case": the last request again for the thing now named
        (a where-question stays one, a fetch a fetch); None when the words are not such a
        correction or the thing is not one the robot knows."""
        m = re.match(r"^(?:(?:no|nope|sorry|oh|wait) )*not (?:the |my |that |this )?(?P<wrong>[a-z]+(?: [a-z]+)?) "
                     r"(?:but )?(?:i (?:meant|mean|said) |its |it is |i want |i need )?(?:the |my )(?P<right>[a-z]+(?: [a-z]+)?)"
                     r"(?: please| instead)*$", norm)
        if m is None:
            return None
        right = self._object_in(m.group("right"))[0]
        if right is None:
            return None
        if self.busy:
            self.worker.stop(quiet=True)
        last = next((t for t in reversed(self.history) if t.intent in ("where", "where_dynamic", "command", "want")
                     and t.action in ("answer", "search", "fetch", "clarify")), None)
        if last is not None and last.intent.startswith("where"):
            return self._where(text, Intent("where", f"where is the {right}"), start)
        return self._command(f"bring me the {right}", start, original=text)

    def _the_other_room(self, text: str, obj: str, start: float) -> Turn:
        """"no, the other room": the last request's thing in the room with tables it did not go
        to, or the question which of them when there are several."""
        last = next((t for t in reversed(self.history) if t.action in ("fetch", "search") and t.data.get("room")), None)
        tried = last.data["room"] if last is not None else None
        others = [r for r in self._rooms_with(["table"]) if r != tried]
        if self.busy:
            self.worker.stop(quiet=True)
        if len(others) == 1:
            return self._command(f"find the {obj} in the {others[0]}", start, original=text)
        self.pending = {"kind": "room", "text": f"find the {obj}", "original": text, "object": obj}
        return self._turn(text, "command", f"Which room, then — {_join(['the ' + r for r in others], 'or')}?",
                          "clarify", "asked", start, missing="room")

    def _last_furniture(self):
        """(the last finished fetch's turn, the world's piece of furniture it went to) — a detected
        piece (sensed perception) is the world's piece of that kind nearest its centre; (turn or
        None, None) when there is none."""
        turn = next((t for t in reversed(self.history) if t.action == "fetch" and t.final), None)
        target = (turn.data.get("target_furniture") or {}) if turn is not None else {}
        furniture = self.world.scene(self.scene).furniture
        item = next((f for f in furniture if f.id == target.get("id")), None)
        if item is None and target.get("centre") is not None:
            kind = [f for f in furniture if f.word == furniture_category(str(target.get("name", "")))]
            near = sorted(kind, key=lambda f: math.dist((f.x, f.y), target["centre"][:2]))
            item = near[0] if near and math.dist((near[0].x, near[0].y), target["centre"][:2]) < 1.0 else None
        return turn, item

    def _last_visited(self) -> dict | None:
        """The piece of furniture the last fetch went to, as a which-question among the pieces of
        its kind in its room (the one visited tried), when there are several; else None. A
        detected piece (sensed perception) is the world's piece of that kind nearest its centre."""
        turn, item = self._last_furniture()
        if item is None:
            return None
        furniture = self.world.scene(self.scene).furniture
        items = [f for f in furniture if f.word == item.word and f.room == item.room]
        if len(items) < 2:
            return None
        options = [self._option(f) for f in items]
        return {"word": item.word, "room": item.room, "object": turn.data.get("object") or self._last_object(),
                "options": options,
                "all": options, "tried": [item.id], "text": turn.data.get("command", ""), "original": turn.text}

    def _is_request(self, text: str) -> bool:
        """Whether an answer to a question is rather a new request: it names an object, a place
        or a move of its own ("bring me the mug", "go to the kitchen")."""
        plan = self.services.parser(self.world).parse(text).plan
        return bool(plan.object or plan.nodes or plan.room or unknown_room_named(text.lower().split(), self.world))

    def _furniture_answer(self, text: str, norm: str, p: dict, start: float) -> Turn | None:
        """An answer to "Which room is the table in …?" that names no room: "you choose" / "I
        don't know" / "the nearest" (the nearest such piece in those rooms), "the round one" (the
        kind), "the left one" (asked again — left of what is not known yet); None otherwise."""
        word = p["furniture"]
        words = _bare_answer(norm)
        pieces = [f for f in self.world.scene(self.scene).furniture if f.word == word and f.room in p["rooms"]]
        if not pieces:
            return None
        if re.fullmatch(rf"{_ANY_ONE}(?: {_ANY_ONE})*(?: (?:one|of them|is fine|room))?", words):
            piece = self._nearest(pieces)
            self.pending = None
            turn = self._command(re.sub(rf"\bthe {re.escape(word)}\b", f"the {piece.model}", p["text"], count=1)
                                 + f" in the {piece.room}", start, force=True, original=text)
            if turn.action in ("fetch", "search"):
                turn.reply = f"I'll take the nearest, the {piece.model} in the {piece.room}. {turn.reply}"
                self.last_said = turn.reply
            return turn
        kind = re.fullmatch(r"(?:the |that |this )?(?P<kind>[a-z]+) (?:one|" + re.escape(word) + r")", words)
        if kind is not None and kind["kind"] not in ("left", "right", "other", "first", "second", "third", "last"):
            said = kind["kind"]
            if any(said in f.model.split() for f in pieces):  # "the round one": the round tables
                self.pending = None
                return self._command(re.sub(rf"\bthe {re.escape(word)}\b", f"the {said} {word}", p["text"], count=1),
                                     start, original=text)
        if re.fullmatch(r"(?:the |that |this )?(?:(?:left|right)(?: hand)?(?: one| side)?|one (?:on|to) the (?:left|right)|"
                        r"the one (?:on|to) the (?:left|right))", words):
            rooms = _join(["the " + r for r in p["rooms"]], "or")
            return self._turn(text, "answer", f"Left or right as seen from where? Tell me the room first — {rooms} — "
                              f"or the kind, for example \"the {pieces[0].model}\".", "clarify", "asked", start)
        return None

    def _nearest(self, pieces: list):
        """The piece of furniture the robot would reach first along the floor from where it is."""
        here, _ = self.robot_xy()
        return min(pieces, key=lambda f: floor_distance_m(self._walls_map, here, (f.x, f.y))[0])

    def _choose_by_manner(self, norm: str, options: list[dict]):
        """An answer to a which-question that picks by how, not by what: "either" / "I don't
        know" / "the nearest" (the nearest along the floor), "the bigger one" (by the model's
        footprint), "the left one" (by its bearing from the robot) — (index, what to say first)
        — or "none" for "neither", or None when the answer is none of these."""
        words = _bare_answer(norm)
        if re.fullmatch(r"(?:neither|none|no one|not any)(?: of them| one| of those)?", words):
            return "none"
        items = {f.id: f for f in self.world.scene(self.scene).furniture}
        pieces = [items.get(o.get("id")) for o in options]
        if any(f is None for f in pieces):
            return None
        if re.fullmatch(rf"(?:{_ANY_ONE}|both|try both|all of them)(?: {_ANY_ONE})*(?: (?:one|of them|is fine))?", words):
            return pieces.index(self._nearest(pieces)), "I'll try the nearest."
        size = re.fullmatch(r"(?:the )?(?P<size>big|bigger|biggest|large|larger|largest|small|smaller|smallest|little|"
                            r"tiny|long|longer|longest)(?: one| table| ones?)?", words)
        if size is not None:
            area = [f.spec.length_m * f.spec.width_m for f in pieces]
            pick = max(area) if size["size"] in ("big", "bigger", "biggest", "large", "larger", "largest", "long",
                                                 "longer", "longest") else min(area)
            if area.count(pick) == 1:
                return area.index(pick), ""
            return None
        side = re.fullmatch(r"(?:the )?(?:(?P<a>left|right)(?: hand)?(?: one| side| table)?|one (?:on|to) the "
                            r"(?P<b>left|right))|the one (?:on|to) the (?P<c>left|right)(?: side)?", words)
        if side is not None:
            here, _ = self.robot_xy()
            mid = (sum(f.x for f in pieces) / len(pieces), sum(f.y for f in pieces) / len(pieces))
            heading = math.atan2(mid[1] - here[1], mid[0] - here[0])  # facing the pieces asked about
            bearing = [math.remainder(math.atan2(f.y - here[1], f.x - here[0]) - heading, math.tau) for f in pieces]
            pick = max(bearing) if (side["a"] or side["b"] or side["c"]) == "left" else min(bearing)
            return bearing.index(pick), f"The one on the {side['a'] or side['b'] or side['c']} as I face them."
        return None

    def _choose(self, norm: str, text: str, p: dict) -> int | None:
        return choose_option(norm, p["options"], lambda: self.services.parser(self.world).parse(text).plan)

    # ------------------------------------------------------------------ running a task
    def _start_fetch(self, said, text, room, obj, start, **data) -> Turn:
        reply = f"Going to the {room}." if room else "On my way."
        return self._start_job("fetch", said, reply, text, room, obj, start, command=text, room=room,
                               object=obj, **data)

    def _start_job(self, kind: str, said: str, reply: str, text: str, task_room, task_object, start,
                   intent_name="command", style: str = "static", **data) -> Turn:
        """Reply at once and run a fetch (``text``: the command) or a search (``text``: the
        object) in the worker; its final :class:`Turn` comes through ``say``/``on_finish``. A
        task the person asks for replaces an errand's steps still to do."""
        if not self._stepping:
            self.steps, self._stopped_steps = [], []
        turn = self._turn(said, intent_name, reply, kind, "started", start, **data)
        turn.final = False
        self.worker.start(kind, text, task_room, task_object, style, said=said)
        return turn

"""The manager with the real parser and describer; the simulator is replaced by a stand-in
fetcher (the real one is exercised by `assistant eval dialogue` and the chat CLI test)."""

import contextlib
import math
import sys
import threading
import time
from pathlib import Path

import pytest

from assistant.dialogue import DialogueManager, ObjectMemory, Services
from assistant.dialogue.turns import SOCIAL_REPLIES

sys.path.insert(0, str(Path(__file__).parent))
from standins import fetch_result  # noqa: E402  (the dialogue tests' shared stand-in)


class StandInFetcher:
    """Reports progress like the executor and ends with a chosen result; with ``hold`` it keeps
    reporting until interrupted (the manager's progress callback raises)."""

    def __init__(self, furniture="hexagontable_1", seen=True, hold=False):
        self.furniture, self.seen, self.hold = furniture, seen, hold
        self.texts = []

    def __call__(self, text, world, scene, on_event):
        self.texts.append(text)
        on_event("entered", {"room": "bedroom", "result": None})
        while self.hold:
            time.sleep(0.01)
            on_event("move_to", {"goal": None})
        return fetch_result(bool(self.seen), self.furniture)


@contextlib.contextmanager
def searching_the_map(m):
    """The manager answers "where is my X?" from the simulator's map (oracle search) meanwhile."""
    m.services.search_mode = "oracle"
    try:
        yield m
    finally:
        m.services.search_mode = "sensed"


def make(services, tmp_path, fetcher, said=None):
    services = services.using(fetcher=fetcher)
    return DialogueManager("apartment", services=services, memory=ObjectMemory(tmp_path / "memory.json"),
                           say=(said.append if said is not None else None))


def test_fetch_replies_at_once_then_reports(services, tmp_path):
    said = []
    fetcher = StandInFetcher()
    m = make(services, tmp_path, fetcher, said)
    turn = m.handle("bring me the mug from the table to the right of the chair in the bedroom")
    assert (turn.action, turn.outcome, turn.reply) == ("fetch", "started", "Going to the bedroom.")
    final = m.wait(10)
    assert final.outcome == "success" and "mug" in final.reply
    assert said[0] == "I'm in the bedroom." and said[-1] == final.reply
    assert m.memory.recall("apartment", "mug").furniture == "hexagontable_1"
    where = m.handle("where is my mug?")
    assert where.data["source"] == "memory" and "I saw your mug just now" in where.reply


def test_stop_interrupts_a_running_fetch(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher(hold=True))
    assert m.handle("go into the bedroom").outcome == "started"
    assert m.busy
    assert m.handle("stop").outcome == "stopped"
    final = m.wait(5)
    assert final is not None and final.outcome == "stopped"
    assert not m.busy


def test_clarify_ambiguous_table_by_reference(services, tmp_path):
    fetcher = StandInFetcher(furniture="dinnertable_1")
    m = make(services, tmp_path, fetcher)
    ask = m.handle("get my laptop from the table in the living room")
    assert ask.action == "clarify" and ask.reply.startswith("There are three tables in the living room")
    go = m.handle("the one with the chairs")
    assert go.action == "fetch" and go.data["chosen"] == "dinnertable_1"
    m.wait(10)
    assert "chair" in fetcher.texts[-1] and "living room" in fetcher.texts[-1]


def test_clarify_never_mind_and_ordinals(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    m.handle("get the statue from the table in the bedroom")
    assert m.handle("never mind").outcome == "cancelled"
    assert m.pending is None
    asked = m.handle("get the statue from the table in the bedroom")
    options = [o["id"] for o in asked.data["options"]]
    assert sorted(options) == ["coffeetable_2", "hexagontable_1", "roundtable_2"]
    # the second one offered, not just any table of the bedroom
    assert m.handle("the second").data["chosen"] == options[1]
    m.wait(10)
    m.handle("get the statue from the table in the bedroom")
    assert m.handle("the last one").data["chosen"] == options[-1]
    m.wait(10)


def test_unknown_word_is_named_back_and_learned(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    ask = m.handle("bring me the mug from the credenza in the living room")
    assert "'credenza'" in ask.reply and ask.outcome == "asked"
    follow = m.handle("yes, it's a table")
    assert follow.action == "clarify" and "tables in the living room" in follow.reply


def test_missing_room_is_asked(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    ask = m.handle("bring me my statue")
    assert "Which room" in ask.reply
    go = m.handle("the bedroom")
    assert go.reply == "Going to the bedroom."
    m.wait(10)


def test_where_without_memory_says_it_is_the_simulators_knowledge(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    with searching_the_map(m):
        turn = m.handle("where is my glasses case")
    assert turn.data["source"] == "simulator" and "simulator" in turn.reply
    with searching_the_map(m):
        dyn = m.handle("how do I get to my fork?")
    assert dyn.data["style"] == "dynamic" and dyn.reply.lower().startswith("go into the living room")


def test_fetch_not_finding_object_forgets_it(services, tmp_path):
    fetcher = StandInFetcher(seen=False)
    m = make(services, tmp_path, fetcher)
    m.memory.remember("apartment", "mug", "bedroom", "hexagontable_1", "table", "on the table")
    m.handle("bring me the mug from the table to the right of the chair in the bedroom")
    final = m.wait(10)
    assert final.outcome == "failed" and "can't see your mug" in final.reply
    assert m.memory.recall("apartment", "mug") is None


def test_a_place_told_and_not_seen_there_is_kept_as_told(services, tmp_path):
    """"the hearing aid is on the bed" (a fetch, as the study's descriptions): the robot goes, does
    not see it; asked later, it says what it was told and that it looked, and offers a search of
    the home (it had said "I haven't seen your aid, and I don't know where it is")."""
    m = make(services, tmp_path, StandInFetcher(furniture="bed_1", seen=False))
    m.handle("the hearing aid is on the bed")
    assert "can't see your hearing aid" in m.wait(10).reply
    kept = m.memory.recall("apartment", "hearing aid")
    assert (kept.source, kept.room, kept.furniture) == ("told, not seen", "bedroom", "bed_1") and kept.told
    reply = m.handle("where's my hearing aid?").reply
    assert reply.startswith("You told me just now that your hearing aid is on the bed in the bedroom, but I "
                            "couldn't see it there when I looked.") and "all over the home" in reply
    assert m.pending == {"kind": "confirm", "search": "hearing aid", "object": "hearing aid"}
    assert "hearing aid" in m.handle("what have you seen?").reply  # told, not among the things seen
    m.handle("no")
    m.handle("I've put my glasses case on the bed")  # told, kept as told; then looked at and not seen
    assert m.memory.recall("apartment", "glasses case").source == "told"
    m.handle("bring me my glasses case from the bed")
    m.wait(10)
    assert m.memory.recall("apartment", "glasses case").source == "told, not seen"


def test_a_doubt_is_answered_with_what_the_robot_goes_by(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    with searching_the_map(m):  # answered from the map, not searched for
        for doubt in ("is that right?", "you sure?", "how do you know?", "is it really there?"):
            m.handle("where is my hearing aid?")  # not on the map, nobody said: "I don't know where it is"
            reply = m.handle(doubt).reply
            assert reply == ("I haven't seen your hearing aid myself, and nobody has told me where it is. Shall I "
                             "look for it?"), doubt  # was taken as "yes" to the offer to look
            m.handle("no")


def test_a_place_of_another_kind_of_table_is_a_no(services, tmp_path):
    """The mug seen on the hexagon table: "is it on the coffee table?" had been "Yes — … on the
    table" (any table agreed)."""
    m = make(services, tmp_path, StandInFetcher())
    m.memory.remember("apartment", "mug", "bedroom", "hexagontable_1", "table", "on the table by the chairs")
    m.handle("where is my mug?")
    assert m.handle("is it on the coffee table?").reply.startswith("Not when I last looked: I saw your mug")
    assert m.handle("is it on the hexagon table?").reply.startswith("Yes — I saw your mug")
    assert m.handle("is it on a table?").reply.startswith("Yes — ")


def test_what_asks_for_no_thing_is_not_a_search_and_told_places_read_as_said(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    for said in ("the weather is nice", "my name is Mary", "that was a long day"):
        turn = m.handle(said)  # had been "Which room should I look for your weather in …?"
        assert turn.outcome == "not_understood" and "Which room" not in turn.reply, said
    assert m.handle("i put my phone down next to the couch").reply == \
        "OK — I'll remember that your cell phone is next to the couch in the living room."  # was "your phone down"
    assert m.handle("i moved my mug to the bedroom this morning").reply == \
        "OK — I'll remember that your mug is in the bedroom."  # was "on the bedroom this morning in the bedroom"


def test_a_told_place_in_two_rooms_asks_which_and_keeps_the_answer(services, tmp_path):
    """"I put my glasses case on the coffee table" (one in each room), then "the one in the
    bedroom": that had become a trip to the bedroom, the note left without its room."""
    m = make(services, tmp_path, StandInFetcher())
    reply = m.handle("i put my glasses case on the coffee table").reply
    assert reply.endswith("Which room is it in — the living room or the bedroom?"), reply
    assert m.handle("the one in the bedroom").reply == "Got it — your glasses case is on the coffee table in the bedroom."
    assert m.memory.recall("apartment", "glasses case").room == "bedroom"
    assert m.handle("i left my keys on the coffee table").reply.endswith("Which room are they in — the living room or "
                                                                         "the bedroom?")
    m.handle("what's in the bedroom?")  # a new request: the question is dropped, the note kept without a room
    assert m.pending is None and m.memory.recall("apartment", "keys").room is None
    # "my glasses case" is nobody else's (it had been said as "Glasse's glasses case")
    assert m.handle("where is my glasses case").reply.startswith(
        "You told me just now that your glasses case is on the coffee table in the bedroom.")


def test_the_kind_said_narrows_a_which_question(services, tmp_path):
    """"the round table in the living room" of a room with two round tables among three: "There
    are three tables …" had offered every table."""
    m = DialogueManager("two-bedrooms-house", services=services.using(fetcher=StandInFetcher()),
                        memory=ObjectMemory(tmp_path / "memory.json"))
    reply = m.handle("go to the round table in the living room").reply
    assert reply.startswith("There are two round tables in the living room — "), reply


def test_someone_elses_thing_is_said_as_theirs(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    with searching_the_map(m):
        assert m.handle("where is johns phone").reply.startswith("I haven't seen John's cell phone")  # was "your"
        assert m.handle("wheres grandmas glasses").reply.startswith("I haven't seen Grandma's glasses")
        assert m.handle("where is his hearing aid?").reply.startswith("I haven't seen his hearing aid")


def test_a_room_by_another_name_in_a_question(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    reply = m.handle("what's in the lounge?").reply  # had listed both rooms
    assert reply.startswith("In the living room I know of") and "bedroom" not in reply


def test_find_it_after_a_told_place_was_not_confirmed_searches_the_home(services, tmp_path):
    """"find it" had gone back to the same table ("I can't see your wallet there" again)."""
    m = make(services, tmp_path, StandInFetcher(furniture="bed_1", seen=False))
    m.handle("the wallet is on the bed")
    m.wait(10)
    turn = m.handle("find it")
    assert turn.action == "search" and turn.reply.startswith("It wasn't where you said, so I'll look all over")
    m.close()


def test_forget_that_after_a_told_place_forgets_it(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    m.handle("I put my hearing aids on the bed")
    assert m.memory.recall("apartment", "hearing aids") is not None
    assert m.handle("forget that").reply == "OK — I've forgotten what you told me about your hearing aids."
    assert m.memory.recall("apartment", "hearing aids") is None  # it had said "OK, never mind" and kept it
    assert m.handle("forget it").reply == "OK."  # nothing just told: as before


def test_never_mind_then_a_new_request(services, tmp_path):
    """"never mind, where's my knitting" had only stopped ("Stopping." / "OK, never mind.")."""
    m = make(services, tmp_path, StandInFetcher(hold=True))
    m.handle("go to the bedroom")
    turn = m.handle("never mind, go to the living room")
    assert turn.action == "fetch" and turn.reply == "Going to the living room."
    m.close()
    m = make(services, tmp_path, StandInFetcher())
    with searching_the_map(m):
        m.handle("where are my glasses")
        assert m.handle("never mind, where's my knitting").reply.startswith("I haven't seen your knitting")


def test_a_place_guessed_after_a_where_question_is_checked(services, tmp_path):
    """"where is my mug?" … "maybe on the coffee table?" had asked which room the coffee table
    is in (a new command); from the map it had said "Yes" of any table."""
    m = make(services, tmp_path, StandInFetcher())
    with searching_the_map(m):
        m.handle("where is my mug?")
        assert m.handle("maybe on the coffee table?").reply.startswith("No — the mug is in the bedroom")
        assert m.handle("is it on the hexagon table").reply.startswith("Yes — the mug is in the bedroom")


def test_where_a_door_of_the_home_is(services, tmp_path):
    """"where is the front door" had been "I don't know what a front door is"."""
    m = make(services, tmp_path, StandInFetcher())
    assert m.handle("where is the bedroom door?").reply == \
        "The bedroom door is between the hallway and the bedroom. Shall I go there?"
    assert m.pending["command"] == "go to the hallway"


def test_a_fetch_without_a_place_said_keeps_nothing_it_did_not_see(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher(furniture="bed_1", seen=False))
    m.handle("bring me my hearing aid")
    m.wait(10)
    assert m.memory.recall("apartment", "hearing aid") is None


def test_control_and_odd_input_never_raise(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    for text in ["", "?", "blorp zing", "the " * 300, "shut up", "repeat that", "which home am I in",
                 "let me show you what 'in front of the couch' means", "start over", "yes", "no"]:
        turn = m.handle(text)
        assert turn.intent != "error", (text, turn.reply)
    assert m.handle("let me show you what 'in front of the couch' means").data["rdt"] == "couch-front-table"


def test_reply_is_fast(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher(hold=True))
    turn = m.handle("bring me the mug from the table to the right of the chair in the bedroom")
    m.close()
    assert turn.seconds < 2.0  # the benchmark measures the median; this only catches blocking


def test_text_with_no_words_is_answered_and_a_blank_line_is_silent(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    turn = m.handle("!!! ??? ...")
    assert turn.action == "answer" and "didn't catch any words" in turn.reply
    assert m.handle("   ").reply == ""


class SteppedFetcher:
    """Holds before its events and after them until the test lets it go on."""

    def __init__(self):
        self.waiting, self.go, self.reported, self.release = (threading.Event() for _ in range(4))

    def __call__(self, text, world, scene, on_event):
        self.waiting.set()
        self.go.wait(10)
        on_event("entered", {"room": "bedroom", "result": None})
        on_event("vantage", {"room": "bedroom", "pose": None})
        self.reported.set()
        self.release.wait(10)
        return fetch_result(True, "hexagontable_1")


def test_the_activity_of_a_running_task_follows_its_events(services, tmp_path):
    said = []
    fetcher = SteppedFetcher()
    m = make(services, tmp_path, fetcher, said)
    assert m.activity is None
    m.handle("bring me the mug from the table to the right of the chair in the bedroom")
    assert fetcher.waiting.wait(10)
    assert m.activity[0] == "fetching the mug" and m.activity[1] >= 0
    fetcher.go.set()
    assert fetcher.reported.wait(10)
    assert m.activity[0] == "looking around the bedroom"  # the last event that says what it does
    assert "looking around the bedroom" not in said  # shown on the status line, never spoken
    fetcher.release.set()
    assert m.wait(10).outcome == "success"
    assert m.activity is None


def test_the_chat_shows_its_status_line_on_a_terminal_only(tmp_path, monkeypatch):
    import argparse
    import io

    from assistant.dialogue.repl import ChatSession

    monkeypatch.setenv("ASSISTANT_DATA", str(tmp_path))
    args = argparse.Namespace(world="apartment", scene="original", perception="oracle", memory=None,
                              transcripts=None, seed=0)
    class Terminal(io.StringIO):
        def isatty(self):
            return True

    # typed at a terminal, the replies going to a pipe or a log: no status line in them
    session = ChatSession(args, stdin=Terminal("hello\n"), stdout=io.StringIO())
    session._start_status()
    assert session.status is None
    shown = ChatSession(args, stdin=Terminal("hello\n"), stdout=Terminal())
    shown.read_line = lambda: "hello"  # another front end (speech) reads the utterances: none either
    shown._start_status()
    assert shown.status is None
    shown.read_line = None
    shown._start_status()  # both ends a terminal: shown
    assert shown.status is not None
    shown.status.stop()


def test_the_robot_says_what_it_is_doing_and_answers_what_it_cannot_do(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher(hold=True))
    assert m.handle("what are you doing?").reply.startswith("Nothing right now")  # not "what are you looking for"
    assert m.handle("go into the bedroom").outcome == "started"
    deadline = time.monotonic() + 5
    while m.activity is None or m.activity[0] == "on my way":  # the stand-in enters the bedroom first
        assert time.monotonic() < deadline
        time.sleep(0.01)
    status = m.handle("what are you doing")
    assert status.intent == "status" and status.reply.startswith("I'm in the bedroom (") and "stop" in status.reply
    assert m.busy  # asking does not stop it
    m.handle("stop")
    m.wait(5)
    for said, intent in (("come here", "come_here"), ("what time is it?", "out_of_scope"),
                         ("how are you", "wellbeing"), ("good robot", "praise")):
        turn = m.handle(said)
        assert turn.intent == intent and "don't know the word" not in turn.reply, (said, turn.reply)


def test_moves_alone_are_carried_out_and_said_back(services, tmp_path):
    """"turn left" turns the robot — no "which room?" — and the end says what it did."""
    from types import SimpleNamespace

    from assistant.app import Result, Status

    texts = []

    def turned(text, world, scene, on_event):
        texts.append(text)
        data = {"success": True, "failure": None, "final_pose": [5.0, 0.0, -1.57],
                "executor": {"status": "success", "message": "turned left, then moved forward 1 m",
                             "target_furniture": None}}
        return Result("fetch", Status.SUCCESS, data["executor"]["message"], data,
                      task=SimpleNamespace(details={"motion": True}), object=None)

    m = make(services, tmp_path, turned)
    turn = m.handle("turn left and go forward")
    assert (turn.action, turn.outcome, turn.reply) == ("fetch", "started", "Turning left, then moving forward 1 m.")
    final = m.wait(10)
    assert final.outcome == "success" and final.reply == "Done — I've turned left, then moved forward 1 m."
    assert texts == ["turn left and go forward"]
    assert m.handle("turn around").reply == "Turning around."
    m.wait(10)
    assert m.handle("turn left at the door").reply != "Turning left."  # a landmark: not a move alone


def test_what_did_you_see_lists_the_things_remembered(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    assert "haven't seen any of your things" in m.handle("what did you see?").reply
    m.memory.remember("apartment", "mug", "bedroom", "hexagontable_1", "table", "on the table by the chair")
    m.memory.remember("apartment", "keys", "living room", None, None, None)
    turn = m.handle("what have you seen so far")
    assert turn.intent == "seen_list"
    assert turn.reply.startswith("I've seen, just now: your keys in the living room and your mug on the table by "
                                 "the chair in the bedroom") or "your mug on the table by the chair in the bedroom" in turn.reply


def test_a_pending_question_gives_way_to_a_goodbye_or_a_new_place(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    assert m.handle("bring me the mug from the table in the bedroom").action == "clarify"
    assert m.handle("go to the living room").reply == "Going to the living room."
    m.wait(10)
    assert m.handle("bring me the mug from the table in the bedroom").action == "clarify"
    assert m.handle("thanks, bye").action == "leave"


def test_a_thing_wanted_with_no_place_is_looked_for_when_the_person_does_not_know_where(services, tmp_path):
    m = make(services.using(fetcher=StandInFetcher(), searcher=None), tmp_path, StandInFetcher())
    ask = m.handle("I need my glasses case")
    assert ask.action == "clarify" and "Which room" in ask.reply and "search everywhere" in ask.reply
    assert m.pending["kind"] == "room" and m.pending["object"] == "glasses case"


@pytest.mark.parametrize("said, reply", [
    ("where's the bed", "The bed is in the bedroom. Shall I go to it?"),
    ("where is the kitchen", "There is no kitchen here; the rooms are the hallway, the living room and the bedroom."),
    ("how do I get to the bedroom", "From the hallway, where I am, go into the bedroom. Shall I take you there?"),
])
def test_where_a_room_or_a_piece_of_furniture_is(services, tmp_path, said, reply):
    m = make(services, tmp_path, StandInFetcher())
    assert m.handle(said).reply == reply


def test_pointing_at_an_option_is_an_answer_not_a_new_request(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    assert m.handle("bring me the mug from the table in the bedroom").action == "clarify"
    again = m.handle("the one next to the bed")  # two of them are: the question is asked again
    assert again.action == "clarify" and "Which room" not in again.reply and m.pending["kind"] == "which"


@pytest.mark.parametrize("said, start", [
    ("don't go to the bedroom", "OK, I won't."),
    ("couch", "The couch is in the living room."),
    ("where are my keys and my wallet", "I haven't seen your keys"),
    ("where is the table between the chairs and the couch", "I look for things, not furniture"),
    ("how to get to the couch", "The couch is in the living room. Shall I go to it?"),  # not "not furniture"
])
def test_negations_bare_names_two_things_and_furniture_in_where_questions(services, tmp_path, said, start):
    m = make(services, tmp_path, StandInFetcher())
    turn = m.handle(said)
    assert turn.reply.startswith(start), turn.reply
    assert turn.action != "fetch"
    if "wallet" in said:
        assert "You also asked about your wallet" in turn.reply


def test_dont_while_moving_stops_the_robot(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher(hold=True))
    assert m.handle("go into the bedroom").outcome == "started"
    assert m.handle("no don't go there").outcome == "stopped"
    m.wait(5)


def test_is_it_there_is_answered_from_memory_or_looked_into(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    first = m.handle("is my mug in the bedroom?")  # nothing remembered: it goes and looks there
    assert first.action == "fetch" and first.reply == ("I haven't seen your mug yet, so I'll go and look. "
                                                       "Going to the bedroom.")
    m.wait(10)
    yes = m.handle("is my mug in the bedroom?")
    assert yes.action == "answer" and yes.reply.startswith("Yes — I saw your mug just now on the table")
    assert yes.reply.endswith("in the bedroom. Shall I go over to it?")
    no = m.handle("is it in the living room?")  # "it": the mug the conversation is about
    assert no.reply.startswith("Not when I last looked: I saw your mug") and no.data["agrees"] is False
    assert no.reply.endswith("Shall I go and check in the living room?")
    go = m.handle("yes")
    assert go.action == "fetch" and go.reply == "Going to the living room."
    m.wait(10)


@pytest.mark.parametrize("said, reply", [
    ("is the couch in the bedroom?", "No — the couch is in the living room."),
    ("is the bed in the bedroom", "Yes, there is a bed in the bedroom."),
    ("are my keys in the kitchen?", "There is no kitchen here; the rooms are the hallway, the living room and "
                                    "the bedroom."),
    ("is it on the couch?", "Which of your things do you mean? Ask me, for example, \"is my mug in the bedroom?\""),
    ("where should I put my glasses?", SOCIAL_REPLIES["put_advice"]),
])
def test_place_questions_answered_without_moving(services, tmp_path, said, reply):
    m = make(services, tmp_path, StandInFetcher())
    turn = m.handle(said)
    assert (turn.reply, turn.action != "fetch") == (reply, True)


def test_the_furniture_a_place_is_told_by_picks_the_room(services, tmp_path):
    # tables are in the living room and the bedroom; the bed only in the bedroom
    m = make(services, tmp_path, StandInFetcher())
    turn = m.handle("the glasses are on the table next to the bed")  # a fetch
    assert turn.action == "fetch" and turn.reply == "Going to the bedroom."
    m.wait(10)
    told = m.handle("my glasses are on the table next to the bed")  # one's own thing's place: told
    assert told.reply == "OK — I'll remember that your glasses are on the table next to the bed in the bedroom."


def test_no_the_other_one_turns_to_another_of_the_options(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    assert m.handle("bring me the mug from the table in the bedroom").action == "clarify"
    first = m.handle("the one to the left of the bed")
    tried = first.data["chosen"]
    m.wait(10)
    again = m.handle("no, the other one")  # two are left: which of them
    assert again.action == "clarify" and again.reply.startswith("Sorry — which table, then: the one to the right")
    assert tried not in [o["id"] for o in again.data["options"]] and len(again.data["options"]) == 2
    second = m.handle("the one by the chair")
    assert second.action == "fetch" and second.data["chosen"] not in (tried, None)
    m.wait(10)
    third = m.handle("wrong one")  # one left untried: that one
    assert third.action == "fetch" and third.reply == ("Sorry — the table to the right of the bed, then. "
                                                       "Going to the bedroom.")
    assert third.data["chosen"] not in (tried, second.data["chosen"])
    m.wait(10)
    assert m.handle("no, go to the living room").reply == "Going to the living room."  # a new request
    m.wait(10)
    assert m.handle("the other one").action != "fetch"  # nothing chosen any more


def test_the_other_one_said_while_driving_stops_and_turns(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher(hold=True))
    m.handle("bring me the mug from the table in the bedroom")
    first = m.handle("the second one")
    assert first.action == "fetch" and m.busy
    turn = m.handle("not that one, the one by the chair")
    assert turn.action == "fetch" and turn.outcome == "started" and turn.data["chosen"] != first.data["chosen"]
    assert turn.reply.startswith("Sorry — the table to the right of the chair, then.")
    m.stop()
    m.wait(5)


def test_carry_on_starts_the_stopped_task_again(services, tmp_path):
    fetcher = StandInFetcher(hold=True)
    m = make(services, tmp_path, fetcher)
    assert m.handle("carry on").reply.startswith("There's nothing I was stopped in the middle of")
    m.handle("go to the bedroom")
    assert m.handle("hang on, stop please").outcome == "stopped"
    m.wait(5)
    again = m.handle("ok, you can carry on now")
    assert (again.action, again.outcome, again.reply) == ("fetch", "started", "OK, carrying on — going to the bedroom.")
    assert fetcher.texts[-1] == fetcher.texts[0] and m.busy
    assert m.handle("continue").reply.startswith("I'm still")
    m.stop()
    m.wait(5)


def test_it_there_and_typed_names_follow_the_conversation(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    assert m.handle("where did you see it?").action == "clarify"  # nothing talked about yet
    m.handle("bring me the mug from the table by the chair in the bedroom")
    m.wait(10)
    it = m.handle("where did you see it?")
    assert it.data["object"] == "mug" and it.reply.startswith("I saw your mug just now")
    assert m.handle("wheres my lapptop").data.get("object") == "laptop"
    m.stop()  # the search it started
    m.wait(30)
    assert m.handle("could you pop into the living room").reply == "Going to the living room."
    m.wait(10)


def test_not_that_table_after_a_fetch_that_chose_one(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    assert m.handle("no, the other one").reply.startswith("Which one do you mean?")  # no fetch yet
    m.handle("bring me the mug from the table by the chair in the bedroom")
    m.wait(10)  # the stand-in went to hexagontable_1, one of the bedroom's three tables
    turn = m.handle("not that table")
    assert turn.action == "clarify" and turn.reply.startswith("Sorry — which table, then:")
    assert "hexagontable_1" not in [o["id"] for o in turn.data["options"]] and len(turn.data["options"]) == 2
    assert m.handle("the first one").action == "fetch"
    m.wait(10)


def test_a_fall_stops_the_robot_and_says_how_to_get_help(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher(hold=True))
    m.handle("go to the bedroom")
    turn = m.handle("help, I've fallen and I can't get up")
    assert turn.intent == "emergency" and "call for help" in turn.reply and not m.busy
    m.wait(5)


def test_a_new_request_is_not_taken_for_the_room_asked_for(services, tmp_path):
    fetcher = StandInFetcher()
    m = make(services, tmp_path, fetcher)
    assert m.handle("bring me my laptop").action == "clarify"
    turn = m.handle("look for my mug in the bedroom")
    assert turn.action == "fetch" and turn.data["object"] == "mug"
    m.wait(10)
    assert "laptop" not in fetcher.texts[-1] and "mug" in fetcher.texts[-1]


def test_it_in_a_request_is_the_thing_talked_of(services, tmp_path):
    fetcher = StandInFetcher()
    m = make(services, tmp_path, fetcher)
    m.handle("bring me the mug from the table by the chair in the bedroom")
    m.wait(10)
    turn = m.handle("can you bring it to me?")
    assert turn.action == "fetch" and turn.data["object"] == "mug"
    m.wait(10)
    assert m.handle("which table exactly?").data["object"] == "mug"


def test_i_dont_know_to_an_unknown_word_and_is_there_a_thing_in_a_room(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    assert m.handle("bring me the mug from the wardrobe in the bedroom").action == "clarify"
    assert m.handle("I don't know").reply.startswith("OK — then I can't use 'wardrobe'.")
    turn = m.handle("is there a mug in the living room?")
    assert turn.intent == "where_check" and turn.action == "fetch" and turn.reply.endswith("Going to the living room.")
    m.wait(10)


def test_is_it_there_from_the_simulators_map(tmp_path):
    from assistant.world import load_world

    services = Services(perception="oracle", search="oracle")
    services.warm_up(load_world("apartment"), background=False)
    m = make(services, tmp_path, StandInFetcher())
    no = m.handle("is my laptop in the bedroom?")
    assert no.reply.startswith("No — the laptop is in the living room") and "simulator's map" in no.reply
    yes = m.handle("is the monitor near the bed?")  # only the bedroom has a bed
    assert yes.reply.startswith("Yes — the monitor is in the bedroom")


def test_a_place_told_is_remembered_as_told_and_said_so(services, tmp_path):
    fetcher = StandInFetcher()
    m = make(services, tmp_path, fetcher)
    told = m.handle("please remember that my keys are on the coffee table in the living room")
    assert told.action == "answer" and not fetcher.texts  # kept, not driven to
    assert told.reply == "OK — I'll remember that your keys are on the coffee table in the living room."
    entry = m.memory.recall("apartment", "keys")
    assert (entry.source, entry.room, entry.phrase) == ("told", "living room", "on the coffee table")
    assert ObjectMemory(tmp_path / "memory.json").recall("apartment", "keys") is not None  # saved
    where = m.handle("where are my keys?")
    assert where.reply.startswith("You told me just now that your keys are on the coffee table in the living room.")
    check = m.handle("are my keys in the bedroom?")
    assert check.reply.startswith("Not as far as I know: you told me")
    bed = m.handle("I've put my glasses on the table next to the bed")  # only the bedroom has a bed
    assert bed.reply.endswith("on the table next to the bed in the bedroom.")
    listed = m.handle("what did you see?")
    assert listed.reply.startswith("I haven't seen any of your things") and "your glasses and your keys" in listed.reply


def test_a_thing_told_to_be_on_the_bed_is_fetched_from_the_bed(services, tmp_path):
    """A told place on a bed is fetched from the bed, not from a table (the fetch command made
    from the memory says "on the bed", which grounds to the bed itself)."""
    fetcher = StandInFetcher()
    m = make(services, tmp_path, fetcher)
    m.handle("remember that my keys are on the bed")
    m.handle("bring me my keys")
    m.wait(10)
    assert fetcher.texts[-1] == "bring me the keys on the bed in the bedroom"
    plan = services.parser(m.world).parse(fetcher.texts[-1]).plan
    assert plan.node_strings == ["room-center-bed"] and plan.room == "bedroom"


def test_sorry_i_meant_another_room_and_its_over_there(services, tmp_path):
    fetcher = StandInFetcher()
    m = make(services, tmp_path, fetcher)
    m.handle("find my statue in the living room")
    m.wait(10)
    again = m.handle("sorry, I meant the bedroom")
    assert again.action == "fetch" and again.data["object"] == "statue" and again.reply == "Going to the bedroom."
    m.wait(10)
    assert "statue" in fetcher.texts[-1] and "bedroom" in fetcher.texts[-1]
    assert m.handle("no, the kitchen").reply.startswith("There is no kitchen here")
    there = m.handle("it's on the table by the chair")
    assert there.action == "fetch" and there.data["object"] == "statue"
    m.wait(10)


def test_what_is_on_a_piece_of_furniture_from_memory(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    assert m.handle("is there anything on the bed?").reply.startswith("I don't know of anything on the bed")
    m.handle("bring me the mug from the table by the chair in the bedroom")
    m.wait(10)
    m.handle("remember that my keys are on the coffee table in the living room")
    both = m.handle("what else is on the table?")
    assert both.intent == "on_furniture" and both.data["objects"] == ["keys", "mug"]
    assert "your keys on the coffee table in the living room (you told me just now)" in both.reply
    bedroom = m.handle("whats on the table in the bedroom")
    assert bedroom.data["objects"] == ["mug"]
    coffee = m.handle("what's on the coffee table")  # that kind of table only, not every table
    assert coffee.data["objects"] == ["keys"]


@pytest.mark.parametrize("said", ["go to the table to the right of the bed in the bedroom",
                                  "check the table to the left of the bed in the bedroom"])
def test_a_request_that_starts_like_a_correction_is_a_request(services, tmp_path, said):
    m = make(services, tmp_path, StandInFetcher())
    turn = m.handle(said)
    assert turn.action == "fetch" and turn.reply == "Going to the bedroom."
    m.wait(10)


def test_glasses_asked_and_a_glasses_case_remembered(services, tmp_path):
    from assistant.dialogue.replies import related_seen

    assert related_seen("glasses", ["mug", "glasses case"]) == "glasses case"
    assert related_seen("cell phone", ["phone"]) == "phone" and related_seen("mug", ["mugs box", "fork"]) is None
    m = make(services, tmp_path, StandInFetcher())
    m.handle("remember that my glasses case is on the coffee table in the living room")
    turn = m.handle("where are my glasses?")
    assert turn.reply.startswith("I haven't seen any glasses, but you told me just now that your glasses case")
    assert m.pending["object"] == "glasses case" and m.handle("yes").action == "fetch"
    m.wait(10)


def test_an_answer_that_fits_two_options_narrows_the_question(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    assert m.handle("bring me the laptop from the table in the living room").reply.startswith("There are three")
    narrowed = m.handle("the one near the sofa")  # two tables are by the couch
    assert narrowed.action == "clarify" and narrowed.reply.startswith("Which of those — the one behind the couch")
    assert len(narrowed.data["options"]) == 2
    chosen = m.handle("the one in the middle")
    assert chosen.action == "fetch" and chosen.data["chosen"] == narrowed.data["options"][1]["id"]
    m.wait(10)


@pytest.mark.parametrize("command, reply", [
    ("go to the living room", "Done — I'm in the living room."),
    ("go to the table in front of the couch in the living room", "I'm there, facing the table"),
])
def test_a_room_said_alone_ends_in_the_room_not_at_a_table(services, tmp_path, command, reply):
    from assistant.dialogue.replies import ReplyContext, fetch_reply
    from assistant.world import load_world

    world = load_world("apartment")
    ctx = ReplyContext(world, "original", ObjectMemory(tmp_path / "memory.json"), services)
    turn, _ = fetch_reply(ctx, command, fetch_result(True, "coffeetable_1", obj=None), None, time.perf_counter())
    assert turn.outcome == "success" and turn.reply.startswith(reply)


def test_a_thing_moved_and_rooms_of_other_homes(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    m.handle("remember that my book is on the table in the bedroom")
    moved = m.handle("I moved it to the coffee table")
    assert moved.reply == ("OK — I'll remember that your book is on the coffee table. Which room is it in — the "
                           "living room or the bedroom?")  # a coffee table in each
    assert m.handle("and my book?").reply.startswith("You told me just now that your book is on the coffee table")


def test_a_room_of_two_words_and_a_room_this_home_lacks(tmp_path):
    from assistant.world import load_world

    services = Services(perception="oracle")
    services.warm_up(load_world("two-bedrooms-house"), background=False)
    m = DialogueManager("two-bedrooms-house", services=services.using(fetcher=StandInFetcher()),
                        memory=ObjectMemory(tmp_path / "memory.json"))
    turn = m.handle("go to the inner hall")  # "inner" is no unknown word, nor a thing to look for
    assert turn.action == "fetch" and turn.reply == "Going to the inner hall." and turn.data.get("object") is None
    m.wait(10)
    assert "There is no" not in m.handle("bring me the mug from the small room").reply
    m.wait(10)
    studio = Services(perception="oracle").using(fetcher=StandInFetcher())
    h = DialogueManager("hk-studio", services=studio, memory=ObjectMemory(tmp_path / "hk.json"))
    assert h.handle("bring me the laptop from the bedroom").reply.startswith("There is no bedroom here; the rooms are")


def test_the_desk_is_a_desk_not_any_table(tmp_path):
    from assistant.world import load_world

    for world, said, reply in (("two-bedrooms-house", "bring me the monitor from the desk", "Going to the office."),
                               ("hk-studio", "can you grab my fork off the desk in the studio",
                                "There are two desks in the studio — ")):
        services = Services(perception="oracle")
        services.warm_up(load_world(world), background=False)
        m = DialogueManager(world, services=services.using(fetcher=StandInFetcher()),
                            memory=ObjectMemory(tmp_path / f"{world}.json"))
        assert m.handle(said).reply.startswith(reply)
        m.wait(10)


def test_it_after_a_which_question_is_the_thing_asked_for(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    m.handle("bring me the mug from the table in the bedroom")  # "There are three tables …?"
    turn = m.handle("is it in the living room?")
    assert turn.intent == "where_check" and turn.data["object"] == "mug"
    m.wait(10)


def test_furniture_the_home_lacks_is_said_to_be_missing(tmp_path):
    services = Services(perception="oracle").using(fetcher=StandInFetcher())
    m = DialogueManager("hk-studio", services=services, memory=ObjectMemory(tmp_path / "memory.json"))
    turn = m.handle("get the statue from the bed")
    assert turn.reply.startswith("There is no bed in this home — the furniture here is") and turn.action != "fetch"
    assert m.handle("bring me the mug from the dresser in the studio").reply.startswith(
        "I don't know which of the furniture here is the dresser")  # a word for some other piece: asked


def test_where_are_you_and_why_did_you_stop(services, tmp_path):
    """Questions about the robot itself were taken for a fetch ("which room should I look for it
    in?"): where it is comes from its pose (the start before any task), why it stopped from how
    the last task ended."""
    m = make(services, tmp_path, StandInFetcher())
    assert m.handle("what room are you in?").reply == "I'm in the hallway, where I started. What can I do for you?"
    assert m.handle("why did you stop?").reply.startswith("I haven't been asked to do anything yet")
    m.handle("go to the bedroom")
    m.wait(10)
    assert m.handle("why did you stop?").reply.startswith("I'd done what you asked: ")
    from assistant.geometry import Pose2D

    m.pose_listener(Pose2D(5.0, -3.0, 0.0))  # reported while a task ran: in the bedroom
    assert m.handle("where r u").reply.startswith("I'm in the bedroom.")
    here = m.handle("what is in this room?")
    assert here.intent == "furniture" and here.data["room"] == "bedroom" and "bed" in here.reply


def test_shorthand_and_missing_articles_and_ordinary_words(services, tmp_path):
    """A phone typist and a second-language speaker: "pls", "bedrm", "4" and "go to couch" are
    understood; "my mom …" does not make the robot ask whether "mom" is a table."""
    fetcher = StandInFetcher()
    m = make(services, tmp_path, fetcher)
    check = m.handle("pls check bedrm 4 mug")
    assert check.action == "fetch" and check.reply == "Going to the bedroom."
    m.wait(10)
    couch = m.handle("go to couch")
    assert couch.action == "fetch" and couch.reply == "Going to the living room."
    m.wait(10)
    told = m.handle("My mom keeps her glasses case on the coffee table in the living room")
    assert "mom" not in told.reply and not told.reply.startswith("I don't know")
    m.wait(10)
    assert m.handle("thx").reply == "You're welcome."


def test_a_search_says_the_room_it_sees_the_thing_in_and_a_closed_room_once(services, tmp_path):
    """Seen through a door, "I can see your statue!" while "looking in the office" read as a
    contradiction of the answer: the room is said. A room the robot cannot get into is said
    once a conversation, not at every search."""
    import threading

    from assistant.dialogue.seen import SeenRecorder
    from assistant.dialogue.worker import Job
    from assistant.geometry import Pose2D
    from assistant.perception.objects import Sighting

    said = []
    m = make(services, tmp_path, StandInFetcher(), said)
    events = m.worker._events(Job(threading.Event(), kind="search", object="statue"),
                              SeenRecorder(m.memory, "apartment", source="search"), "statue")
    seen = Sighting("statue", 4.0, -1.9, 0.6, distance_m=2.0, pixels=50, room="bedroom")
    events("objects_seen", {"seen": [seen], "pose": Pose2D(3.0, 0.0, 0.0)})
    for _ in range(2):
        events("room_skipped", {"room": "alcove"})
    assert "I can see your statue, in the bedroom!" in said
    assert sum("alcove" in s for s in said) == 1



def test_no_the_other_room(services, tmp_path):
    """"no, the other room": the thing again in the one other room with tables, or which of
    them when there are several."""
    fetcher = StandInFetcher()
    m = make(services, tmp_path, fetcher)
    m.handle("find my mug in the living room")
    m.wait(10)
    other = m.handle("no, the other room")
    assert other.action == "fetch" and other.reply == "Going to the bedroom."
    m.wait(10)
    assert "mug" in fetcher.texts[-1] and "bedroom" in fetcher.texts[-1]



def test_what_do_you_see_go_there_and_the_way_to_a_room(services, tmp_path):
    """"what do you see?" is the robot's room, its furniture and the things last seen there;
    "cool go there" after a where-answer goes for the thing; "how do I get to the bedroom from
    here?" is about the room (was "I don't know what a bedroom is")."""
    from assistant.geometry import Pose2D

    m = make(services, tmp_path, StandInFetcher())
    m.handle("bring me the mug from the table by the chair in the bedroom")
    m.wait(10)
    m.pose_listener(Pose2D(5.0, -3.0, 0.0))
    seen = m.handle("what do you see?")
    assert seen.intent == "what_see" and seen.reply.startswith("I'm in the bedroom. In the bedroom I know of")
    assert "your mug" in seen.reply
    assert m.handle("where is my mug").reply.startswith("I saw your mug")
    go = m.handle("cool go there")
    assert go.action == "fetch" and go.data["object"] == "mug"
    m.wait(10)
    way = m.handle("how do I get to the bedroom from here?")  # the robot is there
    assert way.reply == "I'm in the bedroom now."


def test_no_arm_is_said_to_bring_requests_only_and_a_thing_corrected(services, tmp_path):
    """"bring me the mug" found: the robot says it cannot carry it; "take me to it": not (it
    was said at every fetch). "no not the mug, the glasses case": the request again for the
    glasses case."""
    said = []
    m = make(services, tmp_path, StandInFetcher(), said)
    m.handle("bring me the mug from the table by the chair in the bedroom")
    m.wait(10)
    assert "I have no arm" in said[-1]
    m.handle("take me to it")
    m.wait(10)
    assert said[-1].startswith("Here it is") and "no arm" not in said[-1]
    fixed = m.handle("no not the mug, the glasses case")
    assert fixed.data.get("object") == "glasses case" or "glasses case" in fixed.reply


def test_a_thing_remembered_in_the_room_the_robot_is_in_is_said_to_be_here(services, tmp_path):
    """"Shall I go and check?" was offered for a thing in the very room the robot stood in."""
    from assistant.geometry import Pose2D

    m = make(services, tmp_path, StandInFetcher())
    m.handle("bring me the mug from the table by the chair in the bedroom")
    m.wait(10)
    m.pose_listener(Pose2D(5.0, -3.0, 0.0))  # in the bedroom
    assert m.handle("where is my mug?").reply.endswith("It's in this room — shall I go over to it?")
    m.pose_listener(Pose2D(4.5, 3.0, 0.0))  # in the living room
    assert m.handle("where is my mug?").reply.endswith("Shall I go and check?")



def test_why_did_you_stop_after_a_failure_keeps_its_capital_i(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher(seen=False))
    m.handle("bring me the mug from the table by the chair in the bedroom")
    m.wait(10)
    reply = m.handle("why did you stop?").reply
    assert reply.startswith("I couldn't go on: ") and "i'm" not in reply


def test_a_thing_told_on_a_kind_of_table_is_fetched_and_answered(services, tmp_path):
    """"the laptop is on the dinner table": the room is found from the kind of table, and the
    fetch's reply is made from the person's words (a list of descriptors had taken their name:
    "something went wrong inside me after the fetch (AttributeError …)")."""
    said = []
    fetcher = StandInFetcher(furniture="dinnertable_1")
    m = make(services, tmp_path, fetcher, said)
    turn = m.handle("the laptop is on the dinner table")
    assert (turn.action, turn.outcome, turn.reply) == ("fetch", "started", "Going to the living room.")
    assert turn.text == "the laptop is on the dinner table"
    final = m.wait(10)
    assert final.outcome == "success" and "went wrong" not in final.reply, final.reply


def test_the_next_task_starts_where_the_last_one_left_the_robot(services, tmp_path):
    """"go to the bedroom", then "turn around": the robot turns in the bedroom (each task used
    to start the simulated robot at the home's start pose, in the hallway)."""
    said = []
    m = DialogueManager("apartment", services=services, memory=ObjectMemory(tmp_path / "memory.json"),
                        say=said.append)
    m.handle("go to the bedroom")
    first = m.wait(120)
    assert first.outcome == "success" and m.robot_room()[0] == "bedroom"
    assert first.reply == "Done — I'm in the bedroom."
    assert "I'm in the bedroom." not in said  # not said as it went in too
    x, y, heading = first.data["final_pose"]
    m.handle("turn around")
    turned = m.wait(60)
    tx, ty, theading = turned.data["final_pose"]
    assert turned.outcome == "success" and m.robot_room()[0] == "bedroom"
    assert math.hypot(tx - x, ty - y) < 0.3
    assert abs(math.remainder(theading - heading - math.pi, 2 * math.pi)) < 0.3


def make_in(world, services, tmp_path, fetcher):
    return DialogueManager(world, services=services.using(fetcher=fetcher),
                           memory=ObjectMemory(tmp_path / "memory.json"))


def test_an_answer_in_the_questions_own_words_picks_that_couch(services, tmp_path):
    """"the one by the table" among two couches (a furniture word told them apart only among
    tables), and the command sent is one the grounders read as that couch."""
    fetcher = StandInFetcher(furniture="couch_1")
    m = make_in("two-bedrooms-house", services, tmp_path, fetcher)
    asked = m.handle("go to the couch")
    assert asked.action == "clarify" and "the one by the table" in asked.reply
    turn = m.handle("the one by the table")
    assert turn.action == "fetch" and turn.data["chosen"] == "couch_1"
    assert turn.data["plan"]["nodes"] == ["table-beside-couch"]
    m.wait(10)


def test_the_only_couch_of_the_room_is_gone_to_as_said(services, tmp_path):
    """One couch in the room: the command is not rewritten with a description the grounders
    could not read ("go to the couch against the left wall" had no node: the robot stopped at
    a table)."""
    fetcher = StandInFetcher(furniture="couch_1")
    m = make_in("training-home", services, tmp_path, fetcher)
    turn = m.handle("go to the couch")
    assert turn.action == "fetch" and turn.data["plan"]["nodes"] == ["room-center-couch"]
    m.wait(10)
    assert fetcher.texts == ["go to the couch in the living room"]


@pytest.mark.parametrize("answer, room", [("the first one", "studio"), ("the second", "office"),
                                          ("the last one", "office")])
def test_a_room_question_is_answered_by_its_order(services, tmp_path, answer, room):
    m = make_in("hk-studio", services, tmp_path, StandInFetcher(furniture="desk_1"))
    asked = m.handle("go to the desk")
    assert asked.reply == "Which room is the desk in — the studio or the office?"
    turn = m.handle(answer)  # gone to, or asked which of that room's desks
    assert (turn.action == "fetch" and turn.data["room"] == room) or (
        turn.action == "clarify" and f"in the {room} —" in turn.reply), turn.reply
    if turn.action == "fetch":
        m.wait(10)
    m2 = make_in("hk-studio", services, tmp_path, StandInFetcher())
    m2.handle("go to the desk")
    again = m2.handle("hmm")  # the question again, with the rooms it offered
    assert again.reply == "Sorry, which room — the studio or the office?"


def test_an_errand_of_two_rooms_is_done_step_by_step(services, tmp_path):
    said = []
    fetcher = StandInFetcher(furniture=None)
    m = make(services, tmp_path, fetcher, said)
    turn = m.handle("go to the living room, then after that go to the bedroom")
    assert turn.reply == "Going to the living room. After that, the bedroom."
    final = m.wait(30)  # waits for the last step too
    assert fetcher.texts == ["go to the living room", "go to the bedroom"]
    assert "Going to the bedroom." in said and final is not None and not m.steps
    # a route told in one go stays one command, its room the one named ("turn left" is no room)
    m.handle("go out the door, turn left, then go into the living room and stop at the couch")
    m.wait(30)
    assert fetcher.texts[-1].startswith("go out the door") and len(fetcher.texts) == 3


def test_stopping_an_errand_drops_its_steps(services, tmp_path):
    fetcher = StandInFetcher(furniture=None, hold=True)
    m = make(services, tmp_path, fetcher)
    m.handle("go to the living room then go to the bedroom")
    assert m.steps == ["go to the bedroom"]
    m.handle("stop")
    m.wait(10)
    assert not m.steps and fetcher.texts == ["go to the living room"]
    # "carry on" takes the errand up again, its steps left with it (they had been lost)
    fetcher.hold = False
    turn = m.handle("carry on")
    assert turn.reply == "OK, carrying on — going to the living room. After that, the bedroom."
    m.wait(30)
    assert fetcher.texts == ["go to the living room", "go to the living room", "go to the bedroom"]


def test_thanks_before_a_request_and_courtesies_inside_it(services, tmp_path):
    fetcher = StandInFetcher(furniture=None)
    m = make(services, tmp_path, fetcher)
    turn = m.handle("Thank you. Could you please go to the couch?")
    assert turn.reply == "You're welcome. Going to the living room." and turn.action == "fetch"
    m.wait(10)
    turn = m.handle("Go to the bedroom, if it's not too much trouble.")
    assert turn.reply == "Going to the bedroom." and "trouble" not in str(turn.data)
    m.wait(10)
    turn = m.handle("go back to where you started")  # the room it set out from
    assert turn.action == "fetch" and turn.data["room"] == "hallway"
    m.wait(10)


def test_a_room_question_is_let_go_after_it_was_asked_again(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    assert m.handle("bring me the fork").action == "clarify"
    assert m.handle("hmm").reply.startswith("Sorry, which room")
    turn = m.handle("hmm")  # not an answer twice: the question is dropped, the words read anew
    assert not turn.reply.startswith("Sorry, which room") and m.pending is None


@pytest.fixture(scope="module")
def map_services():
    """Where-answers from the simulator's map (no search), fetches by a stand-in."""
    from assistant.world import load_world

    s = Services(perception="oracle", search="oracle")
    s.warm_up(load_world("two-bedrooms-house"), background=False)
    return s


def test_follow_ups_about_the_last_thing_asked(map_services, tmp_path):
    m = make_in("two-bedrooms-house", map_services, tmp_path, StandInFetcher(furniture="roundtable_1"))
    assert m.handle("is the fork in the office").reply.startswith("Yes — the fork is in the office")
    assert m.handle("and the meeting room?").reply.startswith("No — the fork is in the office")
    assert m.handle("what about in the bedroom?").reply.startswith("No — the fork")
    assert m.handle("what about the kitchen").reply.startswith("There is no kitchen here")
    doubt = m.handle("are you sure?")  # it goes by the map: it says so and offers to look
    assert doubt.reply == ("I haven't seen your fork myself — I went by the map of the home I was given, which may "
                           "be out of date. Shall I go and check?")
    assert m.pending["command"].startswith("bring me the fork in the office")  # where the map has it
    assert m.handle("no").reply == "OK."
    there = m.handle("take me there")
    assert there.action == "fetch" and there.data["object"] == "fork"
    m.wait(10)


def test_a_piece_of_furniture_asked_for_is_placed_by_room(map_services, tmp_path):
    m = make_in("two-bedrooms-house", map_services, tmp_path, StandInFetcher())
    assert m.handle("what room is the desk in").reply == "The desk is in the office. Shall I go to it?"
    assert m.handle("yes please").action == "fetch"
    m.wait(10)
    m2 = make_in("hk-studio", map_services, tmp_path, StandInFetcher())
    reply = m2.handle("which room is the desk in").reply
    assert reply.startswith("There are") and "in the studio" in reply and "in the office" in reply


@pytest.mark.parametrize("asked, meant", [("wheres grandmas glasses", "glasses"), ("where is moms phone", "cell phone"),
                                          ("where r my glasess", "glasses"), ("wher is teh remote", "remote"),
                                          ("where is his phoen", "cell phone")])
def test_other_peoples_things_and_typed_names(map_services, tmp_path, asked, meant):
    m = make_in("two-bedrooms-house", map_services, tmp_path, StandInFetcher())
    turn = m.handle(asked)
    assert turn.data.get("object") == meant, turn.reply


def test_rooms_by_other_names_routes_and_furniture_the_home_lacks(map_services, tmp_path):
    m = make_in("two-bedrooms-house", map_services, tmp_path, StandInFetcher(furniture=None))
    turn = m.handle("go to the lounge")
    assert turn.reply == "Going to the living room." and turn.data.get("object") is None
    m.wait(10)
    assert m.handle("go to the settee").reply.startswith("There are two couches in the living room")
    assert m.handle("never mind").action == "none"
    assert m.handle("what about the dresser").reply.startswith("There is no dresser in this home")
    route = m.handle("how do I get to the office from here").reply
    assert route.startswith("From the living room, where I am, go") and route.endswith(
        "into the office. Shall I take you there?")
    assert m.handle("how do I get to the living room").reply == "I'm in the living room now."


@pytest.mark.parametrize("said, command", [("bed pls", "go to the bed"), ("couch please", "go to the couch"),
                                           ("now the bedroom", "go to the bedroom"),
                                           ("the couch please", "go to the couch")])
def test_a_place_said_alone_as_a_request_is_gone_to(services, tmp_path, said, command):
    fetcher = StandInFetcher(furniture=None)
    m = make(services, tmp_path, fetcher)
    turn = m.handle(said)
    assert turn.action == "fetch", turn.reply
    m.wait(10)
    assert fetcher.texts[0].startswith(command)


def test_pointing_with_no_question_open_is_no_turn_and_a_which_question_is_let_go(services, tmp_path):
    m = make(services, tmp_path, StandInFetcher())
    assert m.handle("the one on the left").reply.startswith("Which one do you mean?")
    assert m.handle("go to the table in the bedroom").action == "clarify"
    assert m.handle("hmm").reply.startswith("Sorry, I didn't get which one")
    assert not m.handle("whats here").reply.startswith("Sorry, I didn't get which one")
    assert m.pending is None


def test_a_landmark_said_by_its_kind_picks_the_room(services, tmp_path):
    """Only the bedroom has a hexagon table: no "Which room is the chair in?"."""
    m = make(services, tmp_path, StandInFetcher(furniture=None))
    turn = m.handle("go to the chair next to the hexagon table")
    assert turn.action == "fetch" and turn.data["room"] == "bedroom"
    m.wait(10)
    assert m.handle("go to the chair").action == "clarify"  # said alone, either room

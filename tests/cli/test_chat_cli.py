"""`assistant chat` end to end through a pseudo-terminal (pexpect): the real program, the real
parser, describer and simulator (oracle perception to keep it quick)."""

import json
import os
import sys
from pathlib import Path

import pytest

pexpect = pytest.importorskip("pexpect")

ROOT = Path(__file__).resolve().parents[2]
PROMPT = "you> "


def spawn(tmp_path, *extra):
    env = dict(os.environ, ASSISTANT_DATA=str(tmp_path / "data"), PYTHONWARNINGS="ignore", TERM="dumb")
    child = pexpect.spawn(sys.executable, ["-m", "assistant", "chat", "--world", "apartment", "--perception",
                                           "oracle", *extra], cwd=str(ROOT), env=env, encoding="utf-8",
                          timeout=240, dimensions=(40, 200))
    return child


def transcript(tmp_path):
    files = list((tmp_path / "data" / "transcripts").glob("*.json"))
    assert len(files) == 1
    return json.loads(files[0].read_text())


def test_conversation_ctrl_c_stops_then_leaves(tmp_path):
    child = spawn(tmp_path)
    child.expect("apartment")
    child.expect_exact(PROMPT)
    child.sendline("which home am I in?")
    child.expect("You're in the apartment")
    child.expect_exact(PROMPT)
    child.sendline("where is my mug")  # never seen: the robot searches the home
    child.expect("I'll go and look for it")
    child.expect("Found it: the mug is in the bedroom")
    searching = child.before
    assert "Looking in the" in searching  # the robot's sentences
    # and between them a status line above the prompt, ticking while it works (a terminal only)
    assert "— \"stop\" stops me)" in searching and "(looking around the " in searching
    child.expect_exact(PROMPT)
    # Ctrl-C the instant the robot has set off, several times in a row, with no pause: the
    # watcher thread handles each SIGINT as it arrives, whatever the main thread is doing
    for _ in range(3):
        child.sendline("bring me the statue from the table to the right of the bed in the bedroom")
        child.expect_exact("Going to the bedroom.")
        child.sendintr()  # Ctrl-C: stop the robot
        child.expect("Stopping")
        child.expect("I've stopped")
        child.sendline("hello")  # a typed line ends the run of Ctrl-Cs
        child.expect("What can I do for you")
    child.sendintr()
    child.expect_exact("(Ctrl-C again to leave)")
    # (two Ctrl-Cs sent within a few milliseconds can reach the program as one signal: the
    # kernel keeps one pending SIGINT per process; a person's two presses are further apart)
    child.sendintr()  # a second Ctrl-C in a row leaves
    child.expect("Goodbye")
    child.expect(pexpect.EOF)
    child.close()
    assert child.exitstatus == 0
    turns = transcript(tmp_path)["turns"]
    intents = [t["intent"] for t in turns]
    assert intents[:3] == ["which_home", "where", "where"]  # the question, then the search's answer
    assert [t["action"] for t in turns][2] == "search" and turns[2]["outcome"] == "success"
    assert sum(t["outcome"] == "stopped" for t in turns) == 3  # "I've stopped." after each Ctrl-C


def test_fetch_to_the_end_updates_memory_and_eof_leaves(tmp_path):
    child = spawn(tmp_path, "--memory", str(tmp_path / "mem.json"))
    child.expect_exact(PROMPT)
    child.sendline("bring me the mug from the table to the right of the chair in the bedroom")
    child.expect_exact("Going to the bedroom.")
    child.expect("I'm in the bedroom")
    child.expect("Here it is: I can see your mug")
    child.sendline("where is my mug")
    child.expect("I saw your mug just now")
    child.expect_exact(PROMPT)  # Ctrl-D once readline reads again (see the earlier-session test)
    child.sendeof()
    child.expect("Goodbye")
    child.expect(pexpect.EOF)
    child.close()
    assert child.exitstatus == 0
    memory = json.loads((tmp_path / "mem.json").read_text())
    rooms = {s["object"]: s["room"] for s in memory["sightings"]}
    assert rooms["mug"] == "bedroom"  # and whatever else the robot saw on the way
    assert set(rooms) <= {"mug", "monitor", "statue", "fork", "glasses case", "laptop"}


def test_ctrl_d_while_the_robot_works_waits_with_its_status_line_ticking(tmp_path):
    child = spawn(tmp_path)
    child.expect_exact(PROMPT)
    child.sendline("where is my mug")  # never seen: a search of the home, many seconds
    child.expect("I'll go and look for it")
    child.expect_exact('"stop" stops me)')  # the status line: readline is reading by now
    child.sendeof()  # Ctrl-D: leave once the robot has finished
    child.expect_exact("(waiting for the robot to finish")
    child.expect_exact('"stop" stops me)')  # it goes on ticking while the chat waits ...
    assert PROMPT not in child.before  # ... with no prompt under it
    child.expect("Found it: the mug is in the bedroom")
    child.expect("Goodbye")
    child.expect(pexpect.EOF)
    child.close()
    assert child.exitstatus == 0


def test_ctrl_c_at_the_prompt_then_ctrl_c_leaves_at_once(tmp_path):
    child = spawn(tmp_path)
    child.expect_exact(PROMPT)
    child.sendintr()
    child.expect_exact("(Ctrl-C again to leave)")
    child.sendintr()
    child.expect("Goodbye")
    child.expect(pexpect.EOF)
    child.close()
    assert child.exitstatus == 0


def test_a_sighting_from_an_earlier_session_says_when_and_a_bad_entry_is_skipped(tmp_path):
    import time

    data = tmp_path / "data"
    data.mkdir()
    earlier = time.time() - 3 * 86400
    (data / "memory.json").write_text(json.dumps({"version": 2, "sightings": [
        {"object": ["mug"], "world": "apartment", "room": "bedroom"},  # malformed: skipped, reported
        {"object": "mug", "world": "apartment", "room": "bedroom", "furniture": "roundtable_2",
         "furniture_word": "table", "phrase": "on the table by the bed", "time_s": earlier}]}))
    child = spawn(tmp_path)
    child.expect("skipped sightings\\[0\\]")
    child.expect_exact(PROMPT)
    child.sendline("where is my mug")
    when = time.strftime("%d %B", time.localtime(earlier)).lstrip("0")
    child.expect(f"I saw your mug on {when}")
    # Ctrl-D once readline reads again: sent while the reply is still being printed, the terminal's
    # line discipline could take it before readline set the terminal up, and it was lost
    child.expect_exact(PROMPT)
    child.sendeof()
    child.expect(pexpect.EOF)
    child.close()


def test_the_chat_says_it_is_getting_ready_before_its_greeting(tmp_path):
    """Loading the product, the home and the language models took 12–16 s under load with
    nothing on screen; a progress line ticks meanwhile, then the greeting comes."""
    child = spawn(tmp_path)
    child.expect("getting ready to talk")
    child.expect("apartment")  # the greeting
    child.expect_exact(PROMPT)
    child.sendeof()
    child.expect(pexpect.EOF)


def test_bye_ends_the_chat(tmp_path):
    child = spawn(tmp_path)
    child.expect_exact(PROMPT)
    child.sendline("ok bye")
    child.expect("Goodbye")
    child.expect(pexpect.EOF)
    child.close()
    assert child.exitstatus == 0
    assert [t["intent"] for t in transcript(tmp_path)["turns"]] == ["bye"]


def test_a_chat_read_from_a_pipe_takes_each_command_after_the_last(tmp_path):
    """Lines from a file come faster than the robot moves: each command waits for the task
    before it (no "I'm still busy"), and the goodbye comes last."""
    import subprocess

    env = dict(os.environ, ASSISTANT_DATA=str(tmp_path / "data"), PYTHONWARNINGS="ignore")
    run = subprocess.run([sys.executable, "-m", "assistant", "chat", "--world", "apartment", "--perception",
                          "oracle"], input="turn around\nback up a little\nbye\n", capture_output=True,
                         text=True, cwd=str(ROOT), env=env, timeout=240)
    out = run.stdout
    assert run.returncode == 0, run.stderr
    assert "still busy" not in out
    order = ["Turning around.", "Done — I've turned around.", "Backing up 0.5 m.", "Done — I've backed up 0.5 m.",
             "Goodbye."]
    places = [out.find(s) for s in order]
    assert all(p >= 0 for p in places) and places == sorted(places), out
    assert out.rstrip().endswith("Goodbye."), out


def test_a_question_read_from_a_pipe_is_answered_after_the_task_before_it(tmp_path):
    """"the hearing aid is on the bed" (a fetch) then "where's my hearing aid?": the question waits
    for the robot to have looked (it was answered at once, "I haven't seen your hearing aid"), and
    the answer says what it was told and that it looked."""
    import subprocess

    env = dict(os.environ, ASSISTANT_DATA=str(tmp_path / "data"), PYTHONWARNINGS="ignore")
    run = subprocess.run([sys.executable, "-m", "assistant", "chat", "--world", "apartment", "--perception",
                          "oracle", "--search", "oracle"], input="the hearing aid is on the bed\n"
                          "where's my hearing aid?\nbye\n", capture_output=True, text=True, cwd=str(ROOT), env=env,
                          timeout=240)
    out = run.stdout
    looked = out.find("I'm at the bed, but I can't see your hearing aid there.")
    told = out.find("You told me just now that your hearing aid is on the bed in the bedroom, but I couldn't see it "
                    "there when I looked.")
    assert 0 <= looked < told, out
    assert "I haven't seen your hearing aid" not in out, out


def test_telling_where_a_thing_is_while_the_robot_searches_for_it_sends_it_there(tmp_path):
    """"the remote is on the coffee table in the living room" during the search for the remote:
    the search stops (without a word) and the robot goes there."""
    import subprocess

    env = dict(os.environ, ASSISTANT_DATA=str(tmp_path / "data"), PYTHONWARNINGS="ignore")
    run = subprocess.run([sys.executable, "-m", "assistant", "chat", "--world", "apartment", "--perception",
                          "oracle"], input="where is my remote\nthe remote is on the coffee table in the living room\n"
                          "bye\n", capture_output=True, text=True, cwd=str(ROOT), env=env, timeout=240)
    out = run.stdout
    assert "I'll go and look for it" in out and "OK, I'll stop searching. Going to the living room." in out, out
    assert "I've stopped" not in out and "still busy" not in out, out


def test_a_real_robot_that_is_not_there_is_said_before_the_greeting(tmp_path):
    import subprocess

    env = dict(os.environ, ASSISTANT_DATA=str(tmp_path / "data"), PYTHONWARNINGS="ignore")
    missing = str(tmp_path / "ttyUSB9")
    for command in (["chat", "--world", "apartment"], ["fetch", "go to the couch", "--world", "apartment"]):
        run = subprocess.run([sys.executable, "-m", "assistant", *command, "--robot", f"p3dx:{missing}"],
                             input="go to the bedroom\n", capture_output=True, text=True, cwd=str(ROOT), env=env,
                             timeout=240)
        assert run.returncode == 2 and f"cannot open serial port {missing}: no such device" in run.stderr, run
        assert "Hello" not in run.stdout and "Traceback" not in run.stderr

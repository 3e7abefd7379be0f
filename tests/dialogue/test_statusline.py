"""The chat's status line above the prompt (assistant.dialogue.statusline), drawn into a
string: what it writes on the first tick and the next, how a printed sentence takes its place,
and when it stays quiet. The real terminal is exercised by tests/cli/test_chat_cli.py."""

import io
import threading

from assistant.dialogue.statusline import StatusLine, status_text

PROMPT = "you> "


def line(activity, at_prompt=True, typed="wh"):
    out = io.StringIO()
    now = {"activity": activity, "at_prompt": at_prompt}
    status = StatusLine(out, threading.RLock(), PROMPT, lambda: now["activity"], lambda: now["at_prompt"],
                        lambda: typed)
    return status, out, now


def test_the_first_tick_moves_the_prompt_down_and_later_ticks_rewrite_the_line_above():
    status, out, now = line(("looking around the kitchen", 12.4))
    assert status.tick()
    first = out.getvalue()
    assert first == "\r\033[K(looking around the kitchen … 0:12 — \"stop\" stops me)\n" + PROMPT + "wh"
    now["activity"] = ("going to the bedroom", 75.0)
    assert status.tick()
    later = out.getvalue()[len(first):]
    # cursor saved, one line up, the line rewritten, cursor restored: readline's line untouched
    assert later == "\0337\033[A\r\033[K(going to the bedroom … 1:15 — \"stop\" stops me)\0338"


def test_a_sentence_printed_meanwhile_takes_the_status_lines_place():
    status, out, _ = line(("looking for your mug", 3.0))
    assert status.erase() == "\r\033[K"  # nothing drawn: the prompt's line only
    status.tick()
    assert status.erase() == "\r\033[K\033[A\r\033[K"  # the prompt's line cleared, then the status line
    assert status.erase() == "\r\033[K"
    written = out.getvalue()
    status.tick()  # drawn again below the sentence: the prompt moves down once more
    assert out.getvalue()[len(written):].endswith("\n" + PROMPT + "wh")


def test_quiet_when_the_robot_is_idle_or_no_prompt_waits():
    status, out, now = line(None)
    assert not status.tick()
    now.update(activity=("looking for your mug", 1.0), at_prompt=False)
    assert not status.tick()
    assert out.getvalue() == ""
    now["at_prompt"] = True
    assert status.tick()
    status.left_prompt()  # Enter pressed: the next tick starts a fresh line above the new prompt
    before = out.getvalue()
    status.tick()
    assert not out.getvalue()[len(before):].startswith("\0337")


def test_the_status_text_fits_the_terminal_width():
    assert status_text("looking around the living room", 3601.0) == \
        "(looking around the living room … 60:01 — \"stop\" stops me)"
    assert len(status_text("looking around the living room", 5.0, width=20)) < 20


def test_a_typed_line_wider_than_the_terminal_moves_the_status_line_up_by_its_rows():
    out = io.StringIO()
    typed = "x" * 40  # "you> " + 40 characters on a 20-column terminal: rows 0, 1 and 2 (cursor)
    status = StatusLine(out, threading.RLock(), PROMPT, lambda: ("looking for your mug", 2.0),
                        lambda: True, lambda: typed, columns=lambda: 20)
    status.tick()
    first = out.getvalue()
    assert first.startswith("\r\033[2A\033[J(")  # the wrapped rows cleared, not only the last one
    status.tick()
    assert out.getvalue()[len(first):].startswith("\0337\033[3A\r\033[K(")  # above all three rows
    assert status.erase() == "\r\033[3A\033[J"
    typed = "x" * 15  # exactly one full row: the cursor waits at its end, no wrap yet
    assert status.erase() == "\r\033[K"

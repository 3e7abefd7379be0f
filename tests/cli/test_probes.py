"""Bad input from the trust review (issue 21): each a one-line message with exit 2, or correct
behaviour — never a traceback, a hang or a silent wrong answer."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from assistant.cli import main
from assistant.cli.common import join_negative_values
from assistant.grounding.parser import MAX_CHARS as MAX_COMMAND_CHARS


def run(argv, capsys):
    try:
        code = main(argv)
    except SystemExit as exit_:  # argparse's usage errors
        code = exit_.code
    out = capsys.readouterr()
    assert "Traceback" not in out.err
    return code, out.out, out.err


@pytest.mark.parametrize("argv, words", [
    (["fetch", "", "--world", "apartment"], "the command is empty"),
    (["fetch", "x" * (MAX_COMMAND_CHARS + 1), "--world", "apartment"], "characters"),
    (["relations", "--world", "apartment", "--resolution", "0.0001"], "--resolution must be from 0.01"),
    (["sim", "render", "apartment", "--pose", "1,1,0", "--out", "somewhere/"], "is a folder"),
    (["sim", "render", "apartment", "--pose", "1,1,0", "--out", "x.png", "--seed", "-1"], "a seed is from 0"),
    (["sim", "render", "apartment", "--pose", "1,1,0", "--out", "x.png", "--tilt", "inf"], "finite number"),
    (["sim", "render", "apartment", "--pose", "1,1,0", "--out", "x.png", "--tilt", "400"], "--tilt must be"),
    (["perceive", "--depth", "d.png", "--intrinsics", "1,1,1,1", "--depth-scale", "0.001", "--tilt", "inf"],
     "finite number"),
    (["perceive", "--depth", "d.png", "--intrinsics", "1,1,1,1", "--depth-scale", "0.001",
      "--camera-height", "nan"], "finite number"),
    (["perceive", "--world", "apartment", "--pose", "-100,0.75,3.14"], "outside the map"),
])
def test_bad_values_get_one_line_and_status_2(argv, words, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, out, err = run(argv, capsys)
    assert code == 2 and words in err.strip().splitlines()[-1], err  # argparse's usage lines come first


def test_a_negative_pose_is_a_value_not_an_option():
    assert join_negative_values(["perceive", "--pose", "-1.8,0.75,3.14", "--json"]) == \
        ["perceive", "--pose=-1.8,0.75,3.14", "--json"]
    assert join_negative_values(["x", "--seed", "-1"]) == ["x", "--seed", "-1"]  # one number: argparse's own


def test_a_negative_pose_is_accepted_on_the_command_line(capsys, tmp_path):
    out_png = tmp_path / "view.png"
    code, out, err = run(["sim", "render", "apartment", "--pose", "-1.8,0.75,3.14", "--out", str(out_png),
                          "--json"], capsys)
    assert code == 0, err
    pose = json.loads(out)["robot_pose"]
    assert (pose["x"], pose["y"]) == (-1.8, 0.75) and out_png.is_file()


@pytest.fixture
def pngs(tmp_path):
    grey = tmp_path / "grey.png"
    Image.fromarray(np.full((48, 64), 100, np.uint8)).save(grey)
    big = tmp_path / "big.png"
    Image.new("I;16", (5000, 5000)).save(big)  # compresses to a few kilobytes
    bomb = tmp_path / "bomb.png"
    Image.new("L", (12000, 12000)).save(bomb)
    return grey, big, bomb


def test_pictures_that_are_not_depth_frames_are_refused(pngs, capsys):
    grey, big, bomb = pngs
    for path, words in ((grey, "picture, not depth"), (big, "more than a depth camera gives"), (bomb, "pixels")):
        code, out, err = run(["perceive", "--depth", str(path), "--intrinsics", "500,500,32,24",
                              "--depth-scale", "0.001"], capsys)
        assert code == 2 and words in err, err


def test_a_batch_answers_every_line(tmp_path, capsys):
    batch = tmp_path / "requests.jsonl"
    batch.write_bytes(b'{"text": "the mug", "world": "apartment", "seed": 1e400}\n'
                      b'\xff\xfe{"text": "x"}\n'
                      b'[1, 2]\n'
                      b'{"text": "go", "world": "apartment", "seed": -1}\n'
                      b'{"text": "", "world": "apartment"}\n'
                      b'{"text": "go", "world": ["apartment"]}\n' + b"x" * 70_000 + b"\n")
    code, out, err = run(["fetch", "--batch", str(batch), "--json"], capsys)
    answers = [json.loads(line) for line in out.splitlines()]
    assert code == 0 and [a["line"] for a in answers] == [1, 2, 3, 4, 5, 6, 7]
    assert all("error" in a for a in answers)
    assert "out of range" in answers[0]["error"] and "UTF-8" in answers[1]["error"]


def test_a_pasted_page_is_refused_before_any_work(capsys):
    import time

    from assistant.grounding import CommandParser

    parser = CommandParser.load()
    started = time.perf_counter()
    with pytest.raises(Exception, match="characters, more than"):
        parser.parse("mug " * 250_000)
    assert time.perf_counter() - started < 0.5


def test_a_world_file_nested_too_deeply_is_one_line(tmp_path, capsys):
    deep = tmp_path / "deep.yaml"
    deep.write_text("rooms: " + "[" * 5000 + "]" * 5000 + "\n")
    code, out, err = run(["world", str(deep), "--check"], capsys)
    assert code == 2 and "nested too deeply" in err and len(err.strip().splitlines()) == 1, err


@pytest.mark.parametrize("argv", [["world", "/dev/zero", "--check"], ["world", "FIFO", "--check"],
                                  ["parse", "--batch", "/dev/zero", "--json"], ["fetch", "--batch", "/dev/zero", "--json"]])
def test_endless_files_are_refused_before_reading(argv, tmp_path, capsys):
    """``world /dev/zero`` read until it filled 21 GB; ``--batch /dev/zero`` never ended; a named
    pipe nobody writes to waited for ever."""
    import os

    fifo = tmp_path / "fifo.yaml"
    os.mkfifo(fifo)
    argv = [str(fifo) if a == "FIFO" else a for a in argv]
    code, out, err = run(argv, capsys)
    assert code == 2 and ("is a device" in err or "is a pipe" in err) and out == "", err


def test_a_batch_line_that_never_ends_ends_the_batch(tmp_path, capsys):
    from assistant.cli.common import MAX_SKIPPED_BYTES

    batch = tmp_path / "endless.txt"
    batch.write_bytes(b"go to the kitchen\n" + b"x" * (MAX_SKIPPED_BYTES + 2**20))
    code, out, err = run(["parse", "--batch", str(batch), "--json"], capsys)
    assert code == 2 and "without a line end" in err
    assert json.loads(out.splitlines()[0])["text"] == "go to the kitchen"  # earlier lines were answered


@pytest.mark.parametrize("argv", [
    ["sim", "render", "apartment", "--pose", "5,0,3.14", "--out", "/proc/view.png"],
    ["record", "--robot", "sim:apartment", "/proc/session.mcap"],
    ["teach", "couch-front-table", "--world", "training-home", "--out", "/proc/demo.json"],
])
def test_a_file_that_cannot_be_written_is_refused_before_any_work(argv, capsys, monkeypatch):
    """``teach --out /proc/x.json`` taught, then failed to save with a traceback."""
    import io
    import sys

    monkeypatch.setattr(sys, "stdin", io.StringIO("w 2\nq\n"))
    code, out, err = run(argv, capsys)
    assert code == 2 and "cannot write" in err and "/proc" in err, err


def test_keys_piped_to_teach_that_are_not_utf8_are_reported_not_fatal(tmp_path, capsys, monkeypatch):
    import io
    import sys

    monkeypatch.setenv("ASSISTANT_DATA", str(tmp_path / "data"))
    monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(b"w 2\n\xff\xfe\nq\n"), encoding="utf-8"))
    code, out, err = run(["teach", "couch-front-table", "--world", "training-home", "--accept-outlier"], capsys)
    assert code == 0 and "is not a key" in out + err


def test_a_chat_fed_bytes_that_are_not_utf8_goes_on(tmp_path, capsys, monkeypatch):
    import io
    import sys

    monkeypatch.setenv("ASSISTANT_DATA", str(tmp_path / "data"))
    monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(b"\xff\xfe\nwhich home am I in?\n"), encoding="utf-8"))
    code, out, err = run(["chat", "--world", "apartment", "--perception", "oracle"], capsys)
    assert code == 0 and "You're in the apartment" in out, out


def test_a_recording_of_loud_noise_is_heard_as_something_or_nothing(tmp_path, capsys):
    import wave

    noise = tmp_path / "noise.wav"
    with wave.open(str(noise), "wb") as handle:
        handle.setnchannels(1)
        handle.setsampwidth(2)
        handle.setframerate(16000)
        handle.writeframes(np.random.default_rng(0).integers(-32768, 32767, 48000).astype("<i2").tobytes())
    code, out, err = run(["listen", str(noise), "--json"], capsys)  # was pocketsphinx's IndexError
    assert code in (0, 2)


def test_looking_around_in_tiny_steps_is_refused(tmp_path, capsys):
    code, out, err = run(["record", "--robot", "sim:apartment", "--step-deg", "0.0001", str(tmp_path / "r.mcap")], capsys)
    assert code == 2 and "--step-deg must be from 1" in err


def test_depth_inputs_beyond_reason_are_refused(tmp_path, capsys):
    import os

    fifo = tmp_path / "depth.png"
    os.mkfifo(fifo)  # waited for ever
    frame = tmp_path / "max.png"
    Image.fromarray(np.full((48, 64), 65535, np.uint16)).save(frame)
    sample = str(Path(__file__).resolve().parents[2] / "sample_scans" / "apartment_fetch.mcap")
    for argv, words in (
        (["perceive", "--depth", str(fifo), "--intrinsics", "525,525,32,24", "--depth-scale", "0.001"], "is a pipe"),
        (["perceive", "--depth", str(frame), "--intrinsics", "525,525,32,24", "--depth-scale", "1e300"], "at most 1"),
        (["perceive", "--replay", sample, "--at", "1e300", "--json"], "a recording is at most"),  # was OverflowError
    ):
        code, out, err = run(argv, capsys)
        assert code == 2 and words in err, err


def test_a_model_cache_that_cannot_be_a_folder_is_one_line(tmp_path, monkeypatch):
    """``ASSISTANT_CACHE`` naming a file (or /proc/x) was a FileExistsError traceback at the
    first model's cache; every cache user goes through ``cache_dir``."""
    from assistant.errors import AssistantError
    from assistant.fileio import cache_dir

    blocker = tmp_path / "a-file"
    blocker.write_text("not a folder")
    for place in (blocker, "/proc/nope"):
        monkeypatch.setenv("ASSISTANT_CACHE", str(place))
        with pytest.raises(AssistantError, match="ASSISTANT_CACHE"):
            cache_dir()


@pytest.mark.parametrize("folds", ["-1", "1"])
def test_tagging_folds_that_mean_nothing_are_refused(folds, capsys):
    code, out, err = run(["eval", "tagging", "--folds", folds], capsys)
    assert code == 2 and "give 0" in err


def test_a_where_request_naming_a_list_is_refused_not_searched_for(tmp_path, capsys):
    batch = tmp_path / "where.jsonl"
    batch.write_text('{"object": ["mug"], "world": "apartment"}\n{"object": "mug", "world": ["apartment"]}\n')
    code, out, err = run(["where", "--batch", str(batch), "--json"], capsys)
    answers = [json.loads(line) for line in out.splitlines()]
    assert code == 0 and len(answers) == 2 and all("are names, as text" in a["error"] for a in answers)


@pytest.mark.parametrize("argv, words", [
    (["eval", "grounding", "--rounds", "-1"], "from 0 to 1000, got -1"),
    (["eval", "grounding", "--seed", "-3"], "a seed is from 0"),
    (["eval", "fetch", "--limit", "0"], "got 0"),
    (["eval", "policy", "--trials", "two"], "expected a whole number, got 'two'"),
    (["eval", "speech", "--per-kind", "-4"], "got -4"),
])
def test_counts_that_mean_nothing_are_refused_before_any_work(argv, words, capsys):
    code, out, err = run(argv, capsys)
    assert code == 2 and words in err.strip().splitlines()[-1], err


def test_a_viewer_heading_of_many_turns_is_the_same_heading_without_overflow(capsys, recwarn):
    code, out, err = run(["relations", "--world", "apartment", "--viewer", "1e300", "--json"], capsys)
    heading = json.loads(out)["viewer_heading"]
    assert code == 0 and -np.pi <= heading <= np.pi and not [w for w in recwarn if "overflow" in str(w.message)]
    code, out, err = run(["relations", "--world", "apartment", "--viewer", str(0.5 + 4 * np.pi), "--json"],
                         capsys)
    assert code == 0 and json.loads(out)["viewer_heading"] == pytest.approx(0.5)


def test_perceive_text_says_its_doubts_and_what_it_would_not_name(capsys, shared_dir):
    """The text output (not only --json) says a detection is unsure or cut by the range, lists
    the things it would not name, and takes intrinsics separated by spaces."""
    frame = shared_dir / "realdata" / "sunrgbd_kv2_mmdet3d" / "000001_depth.png"
    if not frame.is_file():
        pytest.skip("no ../shared/realdata")
    code, out, err = run(["perceive", "--depth", str(frame), "--intrinsics", "529.5 529.5 365 265",
                          "--depth-scale", "0.001"], capsys)
    assert code == 0, err
    bed = next(line for line in out.splitlines() if line.startswith("bed "))
    assert "unsure, beyond range" in bed
    assert "unknown thing at x" in out and "not one of the five kinds" in out


def test_perceive_warns_of_a_floor_at_an_unlikely_height(capsys, shared_dir, tmp_path):
    """Depth in the wrong units made up furniture and said nothing: a floor found 0.28 m below
    the camera is now said to be unlikely, with the scale to check."""
    frame = shared_dir / "realdata" / "nyu_livingroom_unidepth" / "depth.png"
    if not frame.is_file():
        pytest.skip("no ../shared/realdata")
    shrunk = tmp_path / "wrong_units.png"
    Image.fromarray((np.asarray(Image.open(frame)).astype(np.float64) * 0.28).astype(np.uint16)).save(shrunk)
    code, out, err = run(["perceive", "--depth", str(shrunk), "--json"], capsys)
    assert code == 0, err
    assert json.loads(out)["floor"]["height"] < 0.35
    assert "unlikely height for a depth camera" in err and "check --depth-scale" in err

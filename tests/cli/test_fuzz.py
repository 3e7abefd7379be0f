"""Fuzzing the command line's text, batch and file inputs (Hypothesis).

Whatever the input: no traceback, exit status 0 or 2, and with ``--batch`` exactly one JSON
object per non-blank line, in order. Calls ``assistant.cli.main`` in this process (the trained
models load once), with few examples per property so the default test run stays quick; run
``pytest tests/cli/test_fuzz.py --hypothesis-seed=N`` or raise ``FUZZ_EXAMPLES`` for more.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from assistant.cli import main
from assistant.dialogue.memory import ObjectMemory
from assistant.world.worldfile import resolve_world_path

EXAMPLES = int(os.environ.get("FUZZ_EXAMPLES", "8"))
FUZZ = settings(max_examples=EXAMPLES, deadline=None, derandomize=True,
                suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])

# lines of bytes: text, non-UTF-8 bytes, JSON-ish fragments, huge numbers
WORDS = st.sampled_from(["go", "to", "the", "kitchen", "mug", "table", "in", "front", "of", "couch",
                         "dinner", "1e400", "NaN", "-1", "\u00e9", "\U0001f600", "{", "}", '"', ","])
TEXT_LINE = st.one_of(st.lists(WORDS, max_size=12).map(" ".join), st.text(max_size=40))
BYTE_LINE = st.one_of(TEXT_LINE.map(lambda t: t.encode("utf-8", "surrogatepass")),
                      st.binary(max_size=30))
KEYS = st.sampled_from(["text", "world", "scene", "perception", "object", "seed", "pose", "listener",
                        "style", "question", "search", "miss_rate", "reference", "depth", "intrinsics",
                        "depth_scale", "camera_height", "tilt", "bogus"])
# any JSON value, but never a real home's name (a real request would run a whole fetch)
VALUES = st.recursive(st.none() | st.booleans() | st.integers() | st.floats() | st.text(max_size=12)
                      .filter(lambda t: t.strip() not in {"apartment", "hk-studio", "training-home",
                                                          "one-bedroom-house", "two-bedrooms-house"}),
                      lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=5), inner,
                                                                                  max_size=3),
                      max_leaves=6)
REQUEST = st.dictionaries(KEYS, VALUES, max_size=5).map(lambda d: json.dumps(d).encode())
JSON_LINE = st.one_of(REQUEST, BYTE_LINE)


def run(argv, capsys):
    try:
        code = main(argv)
    except SystemExit as exit_:
        code = exit_.code
    out = capsys.readouterr()
    assert "Traceback" not in out.err, out.err
    assert code in (0, 2), (code, out.err)
    return code, out.out, out.err


def check_batch(path: Path, lines: list[bytes], out: str) -> None:
    expected = sum(1 for number, raw in enumerate(lines) if not _blank(raw[3:] if number == 0 and
                                                                       raw.startswith(b"\xef\xbb\xbf") else raw))
    answers = [json.loads(line) for line in out.splitlines()]
    assert len(answers) == expected, (lines, answers)
    numbered = [a["line"] for a in answers if "line" in a]
    assert numbered == sorted(numbered)


def _blank(raw: bytes) -> bool:
    try:
        return not raw.decode("utf-8").strip()
    except UnicodeDecodeError:
        return False


def _write_lines(path: Path, lines: list[bytes]) -> list[bytes]:
    clean = [raw.replace(b"\n", b" ").replace(b"\r", b" ") for raw in lines]
    path.write_bytes(b"\n".join(clean) + b"\n")
    return clean


@FUZZ
@given(lines=st.lists(BYTE_LINE, min_size=1, max_size=6))
def test_parse_batch_answers_every_line(lines, tmp_path, capsys):
    path = tmp_path / "lines.txt"
    lines = _write_lines(path, lines)
    code, out, _ = run(["parse", "--batch", str(path), "--json"], capsys)
    assert code == 0
    check_batch(path, lines, out)


@FUZZ
@given(command=st.sampled_from(["fetch", "where", "relations"]), lines=st.lists(JSON_LINE, min_size=1, max_size=5))
def test_json_batches_answer_every_line(command, lines, tmp_path, capsys):
    path = tmp_path / "requests.jsonl"
    lines = _write_lines(path, lines)
    code, out, _ = run([command, "--batch", str(path), "--json"], capsys)
    assert code == 0
    check_batch(path, lines, out)


@FUZZ
@given(text=TEXT_LINE)
def test_parse_text(text, capsys):
    code, out, err = run(["parse", text, "--json"], capsys)
    if code == 0:
        assert len(out.splitlines()) == 1 and json.loads(out)["tokens"] is not None
    else:
        assert len(err.strip().splitlines()) == 1


NUMBER_TEXT = st.one_of(st.floats().map(repr), st.integers().map(str), st.sampled_from(
    ["inf", "-inf", "nan", "1e400", "", "-", "0", "-0.0", "1,2", "abc"]))


@FUZZ
@given(tilt=NUMBER_TEXT, seed=NUMBER_TEXT, pose=st.lists(NUMBER_TEXT, min_size=1, max_size=4).map(",".join),
       out=st.sampled_from(["x.png", "dir/", "x.txt", "", "sub/x.png"]))
def test_sim_render_options(tilt, seed, pose, out, tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    run(["sim", "render", "training-home", f"--pose={pose}", f"--tilt={tilt}", f"--seed={seed}",
         f"--out={out}", "--json"], capsys)


def _mutate(data, path, value):
    node = data
    for key in path[:-1]:
        node = node[key]
    node[path[-1]] = value
    return data


WORLD_PATHS = st.sampled_from([
    ("start", "x"), ("rooms", 0, "polygon"), ("rooms", 0, "polygon", 1), ("rooms", 1, "name"),
    ("scenes", "original", "furniture", 0, "x"), ("scenes", "original", "furniture", 1, "yaw"),
    ("scenes", "original", "furniture", 0, "model"), ("scenes", "original", "objects"), ("walls", 0),
    ("doors", 0, "width"), ("scenes", "original", "furniture", 2, "room"), ("name",)])


@FUZZ
@given(where=WORLD_PATHS, value=VALUES)
def test_world_files(where, value, tmp_path, capsys):
    data = yaml.safe_load(resolve_world_path("training-home").read_text())
    path = tmp_path / "home.yaml"
    path.write_text(yaml.safe_dump(_mutate(data, where, value)))
    code, out, err = run(["world", str(path), "--json"], capsys)
    if code == 2:
        assert err.startswith("assistant world: ") and len(err.strip().splitlines()) == 1


@FUZZ
@given(entries=st.lists(st.dictionaries(st.sampled_from(["object", "world", "room", "furniture", "time_s",
                                                           "x_m", "y_m", "source", "phrase", "extra"]),
                                          VALUES, max_size=6), max_size=4),
       version=st.sampled_from([1, 2, 3, "2", None]))
def test_memory_files_never_stop_the_chat(entries, version, tmp_path):
    path = tmp_path / "memory.json"
    path.write_text(json.dumps({"version": version, "sightings": entries}))
    memory = ObjectMemory(path)  # never raises
    memory.remember("apartment", "mug", "kitchen")
    assert ObjectMemory(path).recall("apartment", "mug") is not None

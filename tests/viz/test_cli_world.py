"""``assistant world NAME --html FILE`` and ``--view`` from the command line."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

from assistant.cli import main
from assistant.viz import external_urls
from tests.viz.conftest import gone, page_commands

ROOT = Path(__file__).resolve().parents[2]


def children_of(pid: int) -> list[int]:
    out = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                stat = (entry / "stat").read_text()
            except OSError:
                continue
            if int(stat.rsplit(")", 1)[1].split()[1]) == pid:
                out.append(int(entry.name))
    return out


def test_world_html_writes_a_self_contained_page(tmp_path, capsys, apartment):
    target = tmp_path / "apartment.html"
    assert main(["world", "apartment", "--html", str(target)]) == 0
    assert f"wrote {target}" in capsys.readouterr().out
    page = target.read_text(encoding="utf-8")
    assert external_urls(page) == []
    drawn = {c["path"] for c in page_commands(page) if c["type"] == "set_object"}
    for item in apartment.scene("original").furniture:
        assert f"/meshcat/world/furniture/{item.id}" in drawn
    assert "/meshcat/world/floors/living_room" in drawn and "/meshcat/robots/robot/body" in drawn


def test_world_html_for_an_unknown_scene_is_one_line_of_advice(tmp_path, capsys):
    assert main(["world", "apartment", "--scene", "tidy", "--html", str(tmp_path / "x.html")]) == 2
    err = capsys.readouterr().err
    assert "unknown scene 'tidy'" in err and "original" in err
    assert not (tmp_path / "x.html").exists()


def test_world_html_to_an_unwritable_place_is_one_line_of_advice(tmp_path, capsys):
    blocker = tmp_path / "a-file"
    blocker.write_text("not a folder")
    assert main(["world", "apartment", "--html", str(blocker / "x.html")]) == 2
    err = capsys.readouterr().err
    assert "cannot write the 3D view" in err and "x.html" in err


@pytest.mark.skipif(not Path("/proc").is_dir(), reason="needs /proc to find the server process")
def test_world_view_serves_until_ctrl_c_and_leaves_no_server():
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.Popen([sys.executable, "-m", "assistant", "world", "apartment", "--view"],
                            cwd=ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True)
    try:
        url = None
        deadline = time.monotonic() + 60
        while url is None and time.monotonic() < deadline:
            line = proc.stdout.readline()
            if not line:
                break
            if "3D view of apartment" in line:
                url = line.rsplit(" ", 1)[1].strip()
        assert url and url.startswith("http://127.0.0.1:"), proc.stderr.read()
        servers = children_of(proc.pid)
        assert len(servers) == 1
        with urllib.request.urlopen(url, timeout=5) as reply:
            assert reply.status == 200
        proc.send_signal(signal.SIGINT)  # what Ctrl-C in the terminal sends
        assert proc.wait(timeout=20) == 0
        assert gone(servers[0])
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()

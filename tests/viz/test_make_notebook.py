"""``make notebook``: the set-up installs JupyterLab and ipywidgets, and the server command of
the Makefile's ``notebook`` recipe — started here as written there, on a free port — listens on
127.0.0.1 only, answers its API with the token it printed (and refuses without it), and stops."""

from __future__ import annotations

import os
import re
import signal
import socket
import subprocess
import sys
import time
import tomllib
import urllib.error
import urllib.request
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
JUPYTER = Path(sys.executable).with_name("jupyter")


def recipe(target: str) -> tuple[list[str], list[str]]:
    """(prerequisites, recipe lines with continuations joined) of a Makefile target."""
    text = ROOT.joinpath("Makefile").read_text(encoding="utf-8").replace("\\\n", " ")
    match = re.search(rf"^{target}:([^\n]*)\n((?:\t[^\n]*\n)+)", text, re.M)
    assert match, f"no {target} target in the Makefile"
    return match.group(1).split(), [line.strip() for line in match.group(2).splitlines()]


def test_the_setup_installs_jupyterlab_and_ipywidgets_before_the_notebook_starts():
    deps = tomllib.loads(ROOT.joinpath("pyproject.toml").read_text())["project"]["dependencies"]
    names = {re.split(r"[<>=!~\[ ;]", d, maxsplit=1)[0].lower() for d in deps}
    assert {"jupyterlab", "ipywidgets"} <= names, "not in the project's own dependencies"
    prerequisites, _ = recipe("notebook")
    assert "setup" in prerequisites or "warm-up" in prerequisites
    assert "setup" in recipe("warm-up")[0]
    _, setup_lines = recipe(r"\$\(STAMP\)")
    assert any("pip install" in line and "-e '.[dev" in line for line in setup_lines)


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _other_address() -> str | None:
    """An address of this machine that is not loopback (None when it has none)."""
    try:
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
            s.connect(("192.0.2.1", 9))  # no packet is sent: this only picks the outgoing interface
            address = s.getsockname()[0]
    except OSError:
        return None
    return None if address.startswith("127.") else address


def _get(url: str) -> tuple[int, bytes]:
    try:
        with urllib.request.urlopen(url, timeout=5) as reply:
            return reply.status, reply.read()
    except urllib.error.HTTPError as error:
        return error.code, b""


@pytest.mark.skipif(not JUPYTER.exists(), reason="JupyterLab is not installed (make setup)")
@pytest.mark.timeout(120)
def test_the_make_notebook_server_is_on_loopback_with_its_token(tmp_path):
    psutil = pytest.importorskip("psutil")
    _, lines = recipe("notebook")
    server = next(line for line in lines if "jupyter lab" in line)
    # the recipe as make runs it: $(VENV) is this interpreter's environment, $$ a shell $
    command = server.replace("$(VENV)", str(JUPYTER.parents[1])).replace("$$", "$")
    port = _free_port()
    env = {**os.environ, "JUPYTER_RUNTIME_DIR": str(tmp_path / "runtime"),
           "JUPYTER_CONFIG_DIR": str(tmp_path / "config")}
    env.pop("JUPYTER_TOKEN", None)
    log = tmp_path / "server.log"
    with log.open("w") as out:
        process = subprocess.Popen(["sh", "-c", f"exec {command} --ServerApp.port={port} --ServerApp.port_retries=0"],
                                   cwd=ROOT, env=env, stdout=out, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        deadline = time.monotonic() + 60
        token = None
        while token is None and time.monotonic() < deadline and process.poll() is None:
            found = re.search(rf"http://127\.0\.0\.1:{port}/lab\?token=([0-9a-f]+)", log.read_text())
            token = found.group(1) if found else None
            time.sleep(0.3)
        assert token, f"no URL with a token printed:\n{log.read_text()[-2000:]}"
        listening = [c.laddr for c in psutil.Process(process.pid).net_connections(kind="inet")
                     if c.status == psutil.CONN_LISTEN]
        assert listening and {a.ip for a in listening} == {"127.0.0.1"}, listening
        assert {a.port for a in listening} == {port}
        if (other := _other_address()) is not None:
            with socket.socket() as s, pytest.raises(OSError):
                s.settimeout(2)
                s.connect((other, port))
        status, body = _get(f"http://127.0.0.1:{port}/api/status?token={token}")
        assert status == 200 and b"started" in body
        assert _get(f"http://127.0.0.1:{port}/api/status")[0] == 403, "answers without the token"
        status, body = _get(f"http://127.0.0.1:{port}/api/contents?token={token}")
        assert status == 200 and b"results.ipynb" in body, "serves notebooks/"
    finally:
        process.send_signal(signal.SIGTERM)
        try:
            process.wait(timeout=20)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait()
    with socket.socket() as s, pytest.raises(OSError):
        s.settimeout(2)
        s.connect(("127.0.0.1", port))

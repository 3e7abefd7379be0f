"""Atomic writes and trained-model caches."""

import os
import stat
import subprocess
import sys

import pytest

from assistant.fileio import (FileBusyError, atomic_write_text, cached, file_lock, insecure_cache_reason,
                              read_cache, write_cache)


def test_atomic_write_replaces_whole_file_with_the_usual_mode(tmp_path):
    path = tmp_path / "sub" / "note.txt"
    atomic_write_text(path, "first")
    atomic_write_text(path, "second")
    assert path.read_text() == "second"
    assert [p.name for p in path.parent.iterdir()] == ["note.txt"]  # no temporary left behind
    umask = os.umask(0)
    os.umask(umask)
    assert stat.S_IMODE(path.stat().st_mode) == 0o666 & ~umask


def test_cache_round_trip_and_damaged_or_foreign_caches_mean_retrain(tmp_path):
    path = tmp_path / "model.pickle"
    assert read_cache(path) is None  # missing
    write_cache(path, {"weights": [1, 2, 3]})
    assert read_cache(path, dict) == {"weights": [1, 2, 3]}
    assert read_cache(path, list) is None  # not what the caller trains
    path.write_bytes(path.read_bytes()[:5])  # truncated by a crash elsewhere
    assert read_cache(path) is None


def test_a_cache_others_can_write_is_not_unpickled(tmp_path, caplog):
    folder = tmp_path / "cache"
    path = folder / "model.pickle"
    write_cache(path, {"weights": [1]})
    assert stat.S_IMODE(path.stat().st_mode) == 0o600
    assert read_cache(path, dict) == {"weights": [1]}
    os.chmod(folder, 0o777)
    assert insecure_cache_reason(path) and read_cache(path, dict) is None
    assert "chmod go-w" in caplog.text
    os.chmod(folder, 0o700)
    os.chmod(path, 0o666)
    assert read_cache(path, dict) is None


def test_temporaries_of_a_killed_writer_are_removed_by_the_next_write(tmp_path):
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True).stdout.strip()
    left = tmp_path / f".notes.txt.{dead}.abc123.tmp"
    left.write_text("half")
    mine = tmp_path / f".notes.txt.{os.getpid()}.xyz.tmp"  # a live writer's file stays
    mine.write_text("busy")
    atomic_write_text(tmp_path / "notes.txt", "whole", mode=0o600)
    assert not left.exists() and mine.exists()
    assert stat.S_IMODE((tmp_path / "notes.txt").stat().st_mode) == 0o600


def test_file_lock_serialises_and_times_out_with_a_clear_message(tmp_path):
    target = tmp_path / "shared.json"
    holder = subprocess.Popen([sys.executable, "-c", (
        "import sys, time\nfrom assistant.fileio import file_lock\n"
        f"with file_lock({str(target)!r}):\n    print('held', flush=True)\n    time.sleep(30)\n")],
        stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout.readline().strip() == "held"
        with pytest.raises(FileBusyError, match="locked by another session"):
            with file_lock(target, timeout_s=0.3):
                pass
    finally:
        holder.kill()
        holder.wait()
    with file_lock(target, timeout_s=5):  # the lock of a killed holder is free
        pass


def test_two_processes_needing_one_model_train_it_once(tmp_path):
    """The second process waits for the first one's training and reads its model."""
    path, log = tmp_path / "cache" / "model.pickle", tmp_path / "trained.log"
    script = (
        "import os, sys, time\nfrom assistant.fileio import cached\n"
        "def train():\n"
        f"    open({str(log)!r}, 'a').write(f'{{os.getpid()}}\\n')\n"
        "    time.sleep(1.0)\n    return {'weights': [4, 2]}\n"
        f"print(cached({str(path)!r}, train, dict))\n")
    workers = [subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
               for _ in range(2)]
    outputs = [w.communicate(timeout=60)[0].strip() for w in workers]
    assert outputs == ["{'weights': [4, 2]}"] * 2
    assert len(log.read_text().split()) == 1  # trained by one of them only
    assert cached(path, lambda: {"weights": "again"}, dict) == {"weights": [4, 2]}
    assert cached(path, lambda: {"fresh": 1}, dict, use_cache=False) == {"fresh": 1}
    path.write_bytes(b"damaged")  # a damaged cache is made again and rewritten
    assert cached(path, lambda: {"weights": [5]}, dict) == {"weights": [5]} == read_cache(path, dict)

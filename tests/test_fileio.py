"""Atomic writes and trained-model caches."""

import os
import stat

from assistant.fileio import atomic_write_text, read_cache, write_cache


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

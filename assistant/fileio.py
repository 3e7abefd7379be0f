"""Atomic file writes: what a user taught or recorded is never half-written.

A file is written to a temporary sibling, flushed to disk, then renamed over the target, so a
crash leaves either the old file or the new one, never a truncated mix.
"""

from __future__ import annotations

import os
import tempfile
from pathlib import Path


def atomic_write_bytes(path: str | os.PathLike[str], data: bytes) -> Path:
    """Write ``data`` to ``path`` atomically (creating parent folders); return the path."""
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp_name = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
    try:
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
        os.chmod(tmp_name, 0o666 & ~_umask())  # mkstemp makes 0600; give the usual mode
        os.replace(tmp_name, target)
    except BaseException:
        try:
            os.unlink(tmp_name)
        except FileNotFoundError:
            pass
        raise
    return target


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def atomic_write_text(path: str | os.PathLike[str], text: str, encoding: str = "utf-8") -> Path:
    """Write ``text`` to ``path`` atomically; see :func:`atomic_write_bytes`."""
    return atomic_write_bytes(path, text.encode(encoding))


def cache_dir() -> Path:
    """Folder for trained-model caches (``$ASSISTANT_CACHE`` or ``~/.cache/assistant``)."""
    root = os.environ.get("ASSISTANT_CACHE") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "assistant"
    )
    path = Path(root)
    path.mkdir(parents=True, exist_ok=True)
    return path


def read_cache(path: str | os.PathLike[str], expected: type | tuple[type, ...] | None = None):
    """The object pickled at ``path`` by :func:`write_cache`, or None to retrain.

    None when the file is missing, unreadable, truncated, written by older code that no longer
    unpickles, or not of the ``expected`` type; the reason is logged. A trained-model cache
    never stops the product: the caller retrains and writes it again.
    """
    import logging
    import pickle

    cache = Path(path)
    if not cache.is_file():
        return None
    try:
        with open(cache, "rb") as handle:
            obj = pickle.load(handle)
    except Exception as error:  # stale or damaged cache of any kind: retrain
        logging.getLogger(__name__).warning("ignoring unreadable model cache %s: %s", cache, error)
        return None
    if expected is not None and not isinstance(obj, expected):
        logging.getLogger(__name__).warning("ignoring model cache %s: holds a %s", cache, type(obj).__name__)
        return None
    return obj


def write_cache(path: str | os.PathLike[str], obj) -> Path:
    """Pickle a trained model to ``path`` atomically (read back with :func:`read_cache`)."""
    import pickle

    return atomic_write_bytes(path, pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL))

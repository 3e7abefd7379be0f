"""Atomic file writes, file locks and the user's folders: what a user taught or recorded is
never half-written, never lost to a concurrent session, and private.

A file is written to a temporary sibling (``.NAME.<pid>.<random>.tmp``), flushed to disk, then
renamed over the target, so a crash leaves either the old file or the new one, never a
truncated mix; the temporary files of writers that were killed are removed by the next write.
:func:`file_lock` serialises the read-merge-write of files that several sessions share (object
memory, taught demonstrations). Model caches are unpickled only from a folder that only the
user can write.
"""

from __future__ import annotations

import contextlib
import os
import re
import tempfile
from pathlib import Path

from assistant.errors import AssistantError

#: mode of the files that hold what a person said, taught or was seen having (owner only)
PRIVATE_FILE_MODE = 0o600
#: mode of the folders that hold them and the model caches
PRIVATE_DIR_MODE = 0o700
#: how long a session waits for another one's lock on a shared file (seconds)
LOCK_TIMEOUT_S = 15.0
#: how long a process waits for another one that is training the model it needs (seconds; the
#: longest first-use training, the furniture views and classifiers, takes about 2 minutes)
TRAINING_LOCK_TIMEOUT_S = 900.0


class FileBusyError(AssistantError):
    """Another session held a shared file's lock for too long."""


def atomic_write_bytes(path: str | os.PathLike[str], data: bytes, mode: int | None = None) -> Path:
    """Write ``data`` to ``path`` atomically (creating parent folders); return the path.

    ``mode`` (e.g. :data:`PRIVATE_FILE_MODE`) sets the file's permissions; None gives the usual
    mode (``0666`` less the umask).
    """
    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    _sweep_stale_temporaries(target)
    fd, tmp_name = tempfile.mkstemp(prefix=f".{target.name}.{os.getpid()}.", suffix=".tmp",
                                    dir=target.parent)
    try:
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
        os.chmod(tmp_name, (0o666 & ~_umask()) if mode is None else mode)  # mkstemp makes 0600
        os.replace(tmp_name, target)
    except BaseException:
        try:
            os.unlink(tmp_name)
        except FileNotFoundError:
            pass
        raise
    return target


def _sweep_stale_temporaries(target: Path) -> None:
    """Remove ``.NAME.<pid>.*.tmp`` siblings of ``target`` left by writers that no longer run
    (killed with ``kill -9`` between creating and renaming them)."""
    pattern = re.compile(rf"^\.{re.escape(target.name)}\.(\d+)\.[^.]+\.tmp$")
    with contextlib.suppress(OSError):
        for sibling in target.parent.iterdir():
            found = pattern.match(sibling.name)
            if found and not _process_runs(int(found.group(1))):
                with contextlib.suppress(OSError):
                    sibling.unlink()


def _process_runs(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:  # someone else's process
        return True
    return True


@contextlib.contextmanager
def file_lock(path: str | os.PathLike[str], timeout_s: float = LOCK_TIMEOUT_S):
    """Hold the lock of ``path`` (an OS lock on ``.NAME.lock`` beside it) for a
    read-merge-write: another process holding it is waited for up to ``timeout_s``."""
    import filelock

    target = Path(path)
    target.parent.mkdir(parents=True, exist_ok=True)
    lock = filelock.FileLock(str(target.with_name(f".{target.name}.lock")), timeout=timeout_s,
                             mode=PRIVATE_FILE_MODE)
    try:
        with lock:
            yield target
    except filelock.Timeout:
        raise FileBusyError(f"{target} is locked by another session for over {timeout_s:g} s; "
                            "close the other session (or remove its .lock file if it crashed) "
                            "and try again") from None


def private_dir(path: str | os.PathLike[str]) -> Path:
    """Create ``path`` (and parents) if needed, readable by its owner only (``0700``)."""
    folder = Path(path)
    folder.mkdir(parents=True, exist_ok=True, mode=PRIVATE_DIR_MODE)
    with contextlib.suppress(OSError):  # a folder the user made with other rights is tightened
        if folder.stat().st_uid == os.getuid():
            os.chmod(folder, PRIVATE_DIR_MODE)
    return folder


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def atomic_write_text(path: str | os.PathLike[str], text: str, encoding: str = "utf-8",
                      mode: int | None = None) -> Path:
    """Write ``text`` to ``path`` atomically; see :func:`atomic_write_bytes`."""
    return atomic_write_bytes(path, text.encode(encoding), mode=mode)


def user_data_dir() -> Path:
    """The user's data folder — object memory, taught demonstrations, chat transcripts and
    history: ``$ASSISTANT_DATA``, else ``$XDG_DATA_HOME/assistant``, else
    ``~/.local/share/assistant``. Not created here; writers create it with
    :func:`private_dir`."""
    root = os.environ.get("ASSISTANT_DATA") or os.path.join(
        os.environ.get("XDG_DATA_HOME") or os.path.expanduser("~/.local/share"), "assistant")
    return Path(root)


def cache_dir() -> Path:
    """Folder for trained-model caches (``$ASSISTANT_CACHE`` or ``~/.cache/assistant``)."""
    root = os.environ.get("ASSISTANT_CACHE") or os.path.join(
        os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "assistant"
    )
    try:
        return private_dir(root)
    except OSError as error:  # a file of that name, a folder that cannot be made
        raise AssistantError(f"the model cache {root} cannot be used ({error.strerror or error}); set "
                             "$ASSISTANT_CACHE to a folder you can write") from None


def insecure_cache_reason(path: str | os.PathLike[str]) -> str | None:
    """Why a cache file must not be unpickled (unpickling runs code), or None when it is safe:
    the file and its folder belong to this user and no one else can write them."""
    cache = Path(path)
    for item in (cache.parent, cache):
        try:
            info = item.stat()
        except OSError as error:
            return f"cannot check {item}: {error.strerror}"
        if info.st_uid != os.getuid():
            return f"{item} belongs to another user"
        if info.st_mode & 0o022:
            return f"{item} can be written by other users (run: chmod go-w {item})"
    return None


def read_cache(path: str | os.PathLike[str], expected: type | tuple[type, ...] | None = None):
    """The object pickled at ``path`` by :func:`write_cache`, or None to retrain.

    None when the file is missing, unreadable, truncated, written by older code that no longer
    unpickles, or not of the ``expected`` type; the reason is logged. A trained-model cache
    never stops the product: the caller retrains and writes it again. A file that someone else
    could have written (:func:`insecure_cache_reason`) is never unpickled.
    """
    import logging
    import pickle

    cache = Path(path)
    if not cache.is_file():
        return None
    if (reason := insecure_cache_reason(cache)) is not None:
        logging.getLogger(__name__).warning("not loading model cache %s: %s; retraining", cache, reason)
        return None
    try:
        with open(cache, "rb") as handle:
            obj = pickle.load(handle)
    except Exception as error:  # stale or damaged cache of any kind: retrain
        logging.getLogger(__name__).warning("ignoring unreadable model cache %s (%s); retraining", cache, error)
        return None
    if expected is not None and not isinstance(obj, expected):
        logging.getLogger(__name__).warning("ignoring model cache %s: holds a %s; retraining",
                                            cache, type(obj).__name__)
        return None
    return obj


def write_cache(path: str | os.PathLike[str], obj) -> Path:
    """Pickle a trained model to ``path`` atomically (read back with :func:`read_cache`)."""
    import pickle

    private_dir(Path(path).parent)
    return atomic_write_bytes(path, pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL),
                              mode=PRIVATE_FILE_MODE)


def cached(path: str | os.PathLike[str], make, expected: type | tuple[type, ...] | None = None, *,
           read=None, write=None, use_cache: bool = True):
    """The model cached at ``path``, else ``make()`` written there — made by one process at a
    time: a second process (a notebook beside the chat, a second test worker) that needs the
    same model while the first trains it waits on the file's lock (up to
    :data:`TRAINING_LOCK_TIMEOUT_S`) and reads what the first wrote instead of training it too.

    ``read(path)`` gives the object or None (default :func:`read_cache` with ``expected``);
    ``write(path, obj)`` stores it atomically (default :func:`write_cache`). ``use_cache``
    False makes it afresh and writes nothing."""
    if not use_cache:
        return make()
    read = read or (lambda where: read_cache(where, expected))
    write = write or write_cache
    if (obj := read(path)) is not None:
        return obj
    with file_lock(path, timeout_s=TRAINING_LOCK_TIMEOUT_S):
        if (obj := read(path)) is not None:  # made by another process while this one waited
            return obj
        obj = make()
        write(path, obj)
    return obj


_YAML_LOADER: list = []


def _yaml_loader():
    """PyYAML's safe loader with YAML 1.2's booleans: only ``true`` and ``false`` (any case).
    YAML 1.1 also reads on/off/yes/no/y/n as booleans, so the key ``on:`` of a world file's
    object (the furniture it lies on) became ``True`` and was refused as an unknown key, and a
    scripted ``say: no`` became False."""
    import re

    import yaml

    if not _YAML_LOADER:
        class Loader(yaml.SafeLoader):
            pass

        Loader.yaml_implicit_resolvers = {
            first: [(tag, regexp) for tag, regexp in resolvers if tag != "tag:yaml.org,2002:bool"]
            for first, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()}
        Loader.add_implicit_resolver("tag:yaml.org,2002:bool", re.compile(r"^(?:true|True|TRUE|false|False|FALSE)$"),
                                     list("tTfF"))
        _YAML_LOADER.append(Loader)
    return _YAML_LOADER[0]


def read_yaml(text: str):
    """The data of a YAML file a person gave (PyYAML's safe loader, with YAML 1.2's booleans:
    :func:`_yaml_loader`): nesting too deep for the parser (it recurses once per level and hit
    Python's limit with a traceback) is a ``yaml.YAMLError`` too, so a reader's one ``except
    yaml.YAMLError`` turns every kind of bad YAML into its one-line message."""
    import yaml

    try:
        return yaml.load(text, Loader=_yaml_loader())  # noqa: S506 - a SafeLoader subclass
    except RecursionError:
        raise yaml.YAMLError("nested too deeply (hundreds of levels of [ or {)") from None


def check_readable_file(path: str | os.PathLike[str], what: str = "file", pipes: bool = False) -> os.stat_result:
    """The ``stat`` of ``path`` if it is a file to read; an ``OSError`` saying what it is
    otherwise: a folder, a device such as ``/dev/zero`` (endless: reading a world file from it
    filled 21 GB of memory), a named pipe unless ``pipes`` (opening one nobody writes to waits
    for ever), or a missing file."""
    import stat

    info = os.stat(path)  # FileNotFoundError and the like say themselves
    if stat.S_ISDIR(info.st_mode):
        raise IsADirectoryError(f"{path} is a folder; give a {what}")
    if stat.S_ISCHR(info.st_mode) or stat.S_ISBLK(info.st_mode):
        raise OSError(f"{path} is a device, not a {what}")
    if stat.S_ISFIFO(info.st_mode) and not pipes:
        raise OSError(f"{path} is a pipe, not a {what}")
    return info


def read_user_text(path: str | os.PathLike[str], max_bytes: int, what: str = "file",
                   encoding: str = "utf-8-sig") -> str:
    """The text of a file a person named, read only if it is one (:func:`check_readable_file`)
    and at most ``max_bytes`` long (checked while reading: a pipe has no size). Raises
    ``OSError`` (what is wrong, in words) or ``UnicodeDecodeError``."""
    check_readable_file(path, what)
    with open(path, "rb") as handle:
        data = handle.read(max_bytes + 1)
    if len(data) > max_bytes:
        raise OSError(f"{path} is over {max_bytes // 1_000_000 or max_bytes} "
                      f"{'MB' if max_bytes >= 1_000_000 else 'bytes'}; is it really a {what}?")
    return data.decode(encoding)


def check_writable_target(path: str | os.PathLike[str], what: str = "file") -> None:
    """Refuse, before any work, a file to write whose folder cannot hold it: the nearest folder
    that exists is tried with a temporary file (as :func:`atomic_write_bytes` will write; the
    permission bits alone do not tell, e.g. in ``/proc`` or on a read-only disk). Raises
    :class:`AssistantError`."""
    folder = Path(path).absolute().parent
    while not folder.exists() and folder != folder.parent:
        folder = folder.parent
    if not folder.is_dir():
        raise AssistantError(f"cannot write the {what} {path}: {folder} is a file, not a folder")
    try:
        fd, probe = tempfile.mkstemp(prefix=".write-check.", dir=folder)
        os.close(fd)
        os.unlink(probe)
    except OSError as error:
        raise AssistantError(f"cannot write the {what} {path}: {error.strerror or error} in {folder}; "
                             "give a path in a folder you can write") from None


def text_lines(stream):
    """The lines of a text stream a person typed or piped, with bytes that are not UTF-8
    replaced (``�``) instead of ending the stream with a ``UnicodeDecodeError``."""
    buffer = getattr(stream, "buffer", None)
    if buffer is None:
        yield from stream
        return
    for raw in buffer:
        yield raw.decode("utf-8", "replace")

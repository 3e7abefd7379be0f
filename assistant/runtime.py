"""Process-wide settings a program applies once at start-up or at its end (never on import).

:func:`limit_openmp_threads` is called by the command line's ``main`` (and by the test
harness) before anything imports open3d: measured on the 2-core machine with other
work running, open3d's OpenMP threads made normal estimation 5–10× slower (threads spinning
against each other), while one thread per call kept a 640×480 frame's features under 15 ms
(``benchmarks/bench_perception.py --threads``: a whole frame took 55 ms of CPU with two OpenMP
threads and 19 ms with one). The variable only counts when open3d loads after it, so
:func:`~assistant.perception.frame.analyse_frame` also limits open3d's OpenMP and numpy's BLAS
to one thread while it runs (open3d obeys that limit only with ``OMP_NUM_THREADS`` set, so
the limit sets it when it is not: :func:`~assistant.perception.frame.thread_limit`). Library
users (notebooks) may call it themselves, or set ``OMP_NUM_THREADS`` to override.

:func:`keep_freed_memory` (glibc's allocator keeps the memory numpy frees for the next array
instead of handing it back to the kernel) is applied by the same thread limit, once per process.
"""

from __future__ import annotations

import gc
import os
import sys

__all__ = ["keep_freed_memory", "limit_openmp_threads", "prepare_to_exit"]

#: glibc ``mallopt`` parameters (malloc.h): M_TRIM_THRESHOLD, M_MMAP_THRESHOLD
_M_TRIM_THRESHOLD, _M_MMAP_THRESHOLD = -1, -3
_KEPT: list[bool] = []


def limit_openmp_threads(threads: int = 1) -> bool:
    """Set ``OMP_NUM_THREADS`` to ``threads`` unless it is set already or open3d is loaded.

    Returns True when the setting will take effect for open3d (it was not loaded yet).
    """
    if "open3d" in sys.modules:
        return False
    os.environ.setdefault("OMP_NUM_THREADS", str(int(threads)))
    return True


def keep_freed_memory(mmap_below_mb: int = 32, trim_above_mb: int = 64) -> bool:
    """Let glibc's allocator keep freed memory for reuse: arrays under ``mmap_below_mb`` come
    from the heap, and the heap is handed back to the kernel only when more than
    ``trim_above_mb`` of it is free at its top. Once per process; False when the C library is
    not glibc (nothing changes).

    By default glibc moves these thresholds as it goes (a freed ``mmap`` chunk raises them to its
    size), and a frame's analysis — many arrays of 0.1–2 MB made and freed, numpy's and
    open3d's — kept crossing them: memory was unmapped or trimmed at one step and faulted in
    again, page by page, at the next — 250–1 200 minor page faults per real depth frame,
    ~2.5 µs each on this virtual machine, ~1–3 ms of a frame's ~35 ms of CPU (``docs/perception.md``,
    2 Dec night). With fixed thresholds the pages stay mapped: no faults after the first
    frame. No value changes (where an array lives is not what it holds); the cost is up to
    ``trim_above_mb`` of freed memory the process keeps."""
    if _KEPT:
        return _KEPT[0]
    import ctypes
    import ctypes.util

    ok = False
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
        mallopt = getattr(libc, "mallopt", None)
        if mallopt is not None and hasattr(libc, "gnu_get_libc_version"):
            ok = bool(mallopt(_M_MMAP_THRESHOLD, int(mmap_below_mb) << 20)
                      and mallopt(_M_TRIM_THRESHOLD, int(trim_above_mb) << 20))
    except OSError:
        ok = False
    _KEPT.append(ok)
    return ok


def prepare_to_exit() -> None:
    """Call as a program's last step, just before it returns its exit status: the interpreter's
    finalization will not walk the objects alive now.

    At exit CPython's finalization runs several full garbage collections over every object
    still alive, then frees them one by one. After a command that loaded open3d, scikit-learn,
    NLTK and the trained models (about 240 000 objects the collector tracks) that took about
    1 s of CPU after the command's last line — 3–4 s of silent wall time on a loaded machine
    (``assistant warm-up``, issue 21; perf: half of it in ``gc_collect_main``, the rest in
    deallocation). :func:`gc.freeze` moves those objects to the collector's permanent
    generation, so finalization leaves them to the operating system: measured 0.13 s of CPU
    instead of 1.0 s (``benchmarks/bench_trust.py exit``). Nothing a program needs is skipped:
    atexit handlers (the 3D view's server, the robot's stop), the flush of stdout and stderr and
    every ``with`` block's close still run; only objects still in reference cycles at exit are
    not collected — Python never promised their ``__del__`` runs at exit. Not for a library
    user's interpreter (a notebook, the tests): freezing their objects keeps them in memory.
    """
    gc.freeze()

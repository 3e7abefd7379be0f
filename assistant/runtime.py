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
"""

from __future__ import annotations

import gc
import os
import sys

__all__ = ["limit_openmp_threads", "prepare_to_exit"]


def limit_openmp_threads(threads: int = 1) -> bool:
    """Set ``OMP_NUM_THREADS`` to ``threads`` unless it is set already or open3d is loaded.

    Returns True when the setting will take effect for open3d (it was not loaded yet).
    """
    if "open3d" in sys.modules:
        return False
    os.environ.setdefault("OMP_NUM_THREADS", str(int(threads)))
    return True


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

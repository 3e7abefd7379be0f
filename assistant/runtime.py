"""Process-wide settings a program applies once at start-up (never on import).

:func:`limit_openmp_threads` is called by the command line's ``main`` (and by the test and
benchmark harnesses) before anything imports open3d: measured on the 2-core machine with other
work running, open3d's OpenMP threads made normal estimation 5–10× slower (threads spinning
against each other), while one thread per call kept a 640×480 frame's features under 15 ms
(``benchmarks/bench_perception.py --threads``: a whole frame took 55 ms of CPU with two OpenMP
threads and 19 ms with one). The variable only counts when open3d loads after it, so
:func:`~assistant.perception.frame.analyse_frame` also limits open3d's OpenMP and numpy's BLAS
to one thread while it runs. Library users (notebooks) may call it themselves, or set
``OMP_NUM_THREADS`` to override.
"""

from __future__ import annotations

import os
import sys

__all__ = ["limit_openmp_threads"]


def limit_openmp_threads(threads: int = 1) -> bool:
    """Set ``OMP_NUM_THREADS`` to ``threads`` unless it is set already or open3d is loaded.

    Returns True when the setting will take effect for open3d (it was not loaded yet).
    """
    if "open3d" in sys.modules:
        return False
    os.environ.setdefault("OMP_NUM_THREADS", str(int(threads)))
    return True

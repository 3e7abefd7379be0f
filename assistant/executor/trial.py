"""Judging a fetch trial in the simulator: is the object in the final view?

After the fetch task has ended (:meth:`assistant.app.Fetcher.fetch` runs it), the final depth
frame's pixels whose simulator hit id is the target object are counted
(:func:`object_visibility`). The hit ids are ground truth and are read here, after the task has
ended — the task itself never sees them.

Success (Table 5-4, our threshold): the target object covers at least
:data:`MIN_PIXELS` pixels of the final 640×480 depth frame at a median distance of at most
:data:`MAX_DISTANCE_M`.
"""

from __future__ import annotations

import numpy as np

#: evaluation threshold: pixels of the target object in the final frame
MIN_PIXELS = 50
#: evaluation threshold: median distance (metres) of those pixels
MAX_DISTANCE_M = 4.5


def object_visibility(frame, object_name: str | None) -> dict:
    """``{pixels, distance}`` of ``object_name`` in a simulated frame (hit ids; evaluation
    only). ``distance`` is the median depth (metres) of its pixels, None when none."""
    if frame is None or object_name is None or frame.hit_ids is None:
        return {"pixels": 0, "distance": None}
    names = list(frame.hit_names)
    if object_name not in names:
        return {"pixels": 0, "distance": None}
    mask = frame.hit_ids == names.index(object_name)
    pixels = int(mask.sum())
    if pixels == 0:
        return {"pixels": 0, "distance": None}
    depth = frame.depth_m[mask]
    depth = depth[depth > 0]
    distance = float(np.median(depth)) if len(depth) else None
    return {"pixels": pixels, "distance": None if distance is None else round(distance, 3)}


def is_visible(visibility: dict) -> bool:
    d = visibility.get("distance")
    return visibility.get("pixels", 0) >= MIN_PIXELS and d is not None and d <= MAX_DISTANCE_M

"""Perception: depth frame → point cloud → floor → furniture samples → features → category and
pose → entities (dissertation 3.6).

Importing this package before open3d sets ``OMP_NUM_THREADS=1`` unless it is set already:
measured on the 2-core machine with other work running, open3d's OpenMP threads made normal
estimation 5–10× slower (threads spinning against each other), while one thread per call
kept a 640×480 frame's features under 15 ms. Set ``OMP_NUM_THREADS`` yourself to override.
Re-measured (``benchmarks/bench_perception.py --threads``, load average ~20): a whole frame
took 55 ms of CPU with two OpenMP threads and 19 ms with one. The variable only counts when
open3d loads after it — the simulator imports open3d first — so
:func:`~assistant.perception.frame.analyse_frame` also limits open3d's OpenMP and numpy's BLAS
to one thread while it runs (``FrameParams.threads``; two BLAS threads doubled a real frame's
CPU time).
"""

import os as _os
import sys as _sys

if "open3d" not in _sys.modules:
    _os.environ.setdefault("OMP_NUM_THREADS", "1")

from assistant.perception.classifiers import (
    CLASSIFIERS,
    AutoencoderClassifier,
    FurnitureClassifier,
    category_of,
    view_subclasses,
)
from assistant.perception.cloud import Floor, depth_to_points, find_floor
from assistant.perception.detector import Detection, DetectionResult, FurnitureDetector, detections_to_entities
from assistant.perception.features import (
    FeatureParams,
    estimate_normals,
    normal_histogram,
    orientation_features,
    shape_descriptor,
)
from assistant.perception.frame import FrameAnalysis, FrameParams, analyse_frame
from assistant.perception.objects import ObjectDetector, SimObjectDetector, Sighting
from assistant.perception.orientation import LinearOrientationEstimator, PlaneOrientationEstimator
from assistant.perception.samples import FurnitureSample, SampleParams, extract_samples

__all__ = [
    "AutoencoderClassifier", "CLASSIFIERS", "Detection", "DetectionResult", "FeatureParams",
    "Floor", "FrameAnalysis", "FrameParams", "FurnitureClassifier", "FurnitureDetector",
    "FurnitureSample", "LinearOrientationEstimator", "ObjectDetector", "PlaneOrientationEstimator", "SampleParams",
    "analyse_frame", "category_of", "depth_to_points", "detections_to_entities",
    "estimate_normals", "extract_samples", "find_floor", "normal_histogram",
    "orientation_features", "shape_descriptor", "SimObjectDetector", "Sighting", "view_subclasses",
]

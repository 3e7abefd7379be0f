"""Perception: depth frame → point cloud → floor → furniture samples → features → category and
pose → entities (dissertation 3.6).

Importing this package changes no process setting: programs call
:func:`assistant.runtime.limit_openmp_threads` once at start-up (the command line does), and
:func:`~assistant.perception.frame.analyse_frame` limits open3d's OpenMP and numpy's BLAS to one
thread while it runs (``FrameParams.threads``; two BLAS threads doubled a real frame's CPU time).
"""

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

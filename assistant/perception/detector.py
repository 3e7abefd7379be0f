"""The furniture detector: a depth frame → furniture entities (Figure 3.5).

Front half (:func:`~assistant.perception.frame.analyse_frame`): point cloud, floor, samples,
features. Back half (here): the subclass classifier, the orientation estimator, the position.
Detections are in the world frame when the frame carries the robot's pose, otherwise in the
camera-floor frame (x forward along the camera's heading, y left, origin under the camera).
"""

from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass, field
from functools import lru_cache

import numpy as np

from assistant.geometry import GridMap, Pose2D, wrap_angle
from assistant.perception.classifiers import category_of, verified_category
from assistant.perception.features import (
    covariance,
    estimate_normals,
    normal_histogram,
    orientation_features,
    percentiles,
    shape_descriptor,
)
from assistant.perception.frame import FrameAnalysis, FrameParams, analyse_frame, thread_limit
from assistant.perception.instances import OTHER
from assistant.perception.regroup import range_cut, regroup
from assistant.perception.samples import centred_xy
from assistant.robot.frames import DepthFrame
from assistant.world.entity import Entity, EntityKind

ORIENTATION_METHODS = ("plane", "linear")
#: how many camera poses' floors the detector remembers (``analyse(pose_key=…)``)
FLOOR_MEMORY = 16


@dataclass(frozen=True, eq=False)
class Detection:
    """One recognised piece of furniture.

    ``x``, ``y`` (metres) and ``facing`` (radians, None for tables) are in ``frame`` ("world"
    or "camera-floor"); ``cells_xy`` (M, 2) the centres (metres, same frame) of the 0.05 m floor
    cells it covers; ``partial`` says it runs out of the image (left, right or bottom);
    ``confidence`` is the classifier's (0–1); ``coverage`` (0–1) how much of the item the view
    showed: the floor area seen over the category's typical footprint, halved for a partial
    view. Fusion weighs a detection by ``confidence × coverage`` (:attr:`weight`): a glimpse of
    a couch's arm or a view cut by the image border says less about the item's centre and
    category than a whole view. ``unsure``: the classifier's confidence is under the
    detector's ``sure_confidence`` — a caller should look again from another pose before acting
    on it (a bed it is unsure of may be a desk); ``beyond_range``: the sample reaches the far
    end of the sample range, so the item may go on beyond what was seen (a partial view, kept
    apart from ``partial`` — the image border — which fusion reads).
    """

    category: str
    subclass: str
    x: float
    y: float
    facing: float | None
    confidence: float
    cells_xy: np.ndarray
    height_m: float
    partial: bool
    frame: str
    coverage: float = 1.0
    unsure: bool = False
    beyond_range: bool = False

    @property
    def weight(self) -> float:
        """What this detection counts for in fusion: ``confidence × coverage``."""
        return float(self.confidence * self.coverage)

    def to_dict(self) -> dict:
        return {"category": self.category, "subclass": self.subclass, "x": round(self.x, 3),
                "y": round(self.y, 3),
                "facing": None if self.facing is None else round(float(self.facing), 4),
                "confidence": round(float(self.confidence), 3), "height": round(self.height_m, 3),
                "cells": int(len(self.cells_xy)), "partial": bool(self.partial),
                "coverage": round(float(self.coverage), 3), "unsure": bool(self.unsure),
                "beyond_range": bool(self.beyond_range)}


@dataclass(frozen=True, eq=False)
class UnknownItem:
    """Something standing on the floor that the detector would not name: ``best`` is the
    classifier's choice (a category, or "other": a bench, dresser or other thing that is none of
    the five) and ``probability`` its confidence; ``why`` is "other", "unsure" (under
    ``min_confidence``), "disputed" (a bed or couch cut by the range that the verifier reads
    otherwise) or "no surface" (tall, with no seat, mattress or top). Same frame and
    units as :class:`Detection`."""

    best: str
    probability: float
    x: float
    y: float
    height_m: float
    cells: int
    why: str

    def to_dict(self) -> dict:
        return {"category": "unknown", "best": self.best, "probability": round(float(self.probability), 3),
                "x": round(self.x, 3), "y": round(self.y, 3), "height": round(self.height_m, 3),
                "cells": self.cells, "why": self.why}


@dataclass(eq=False)
class DetectionResult:
    """Detections of one frame, the floor found, why nothing was found (or None), timings."""

    detections: list[Detection]
    analysis: FrameAnalysis
    reason: str | None
    timings_ms: dict = field(default_factory=dict)
    unknown: list[UnknownItem] = field(default_factory=list)

    @property
    def floor(self):
        return self.analysis.floor

    def to_dict(self) -> dict:
        floor = self.analysis.floor
        out = {"detections": [d.to_dict() for d in self.detections],
               "floor": floor.to_dict() if floor is not None else None,
               "samples": len(self.analysis.samples),
               "frame": self.detections[0].frame if self.detections else None,
               "unknown": [u.to_dict() for u in self.unknown]}
        if self.reason:
            out["reason"] = self.reason
        return out


class FurnitureDetector:
    """Detects furniture in depth frames.

    ``models`` is a :class:`~assistant.perception.models.PerceptionModels` (default: the cached
    models trained on the simulator's database, trained on first use); ``orientation`` picks
    the estimator ("plane" — this product's, default — or "linear", Table 3-3);
    ``min_confidence`` drops samples the classifier is unsure of (clutter, walls' remains) —
    they, the samples it calls ``other`` (benches, dressers) and a bed or couch cut by the
    sample range that the verifier reads as something else ("disputed": the item goes on
    beyond what was seen) are reported as :class:`UnknownItem` — except a bed's foot end joined
    across its footboard's shadow and cut by the range, a partial bed (:meth:`_foot_end_of_bed`);
    a detection under ``sure_confidence``, or such a partial bed, is marked ``unsure``;
    ``regroup`` joins a bed cut by its footboard's shadow and splits a night stand off a bed's
    side when the classifier confirms it (:mod:`assistant.perception.regroup`); ``verify``
    lets the models' verifier overrule a bed or couch (``classifiers.verified_category``);
    a sample taller than ``tall_m`` with under ``min_surface_share`` of its points on upward
    surfaces 0.3–0.75 m high (seat, mattress, table top) is not furniture of any category —
    measured on real frames, these are shelves, wardrobes and water heaters the classifier
    would otherwise call beds (a night stand found beside a bed, :func:`night_stands`, is
    exempt: with a tall lamp on it it has little top to see).
    ``weigh_coverage`` sets each detection's ``coverage`` (how much of the item the view
    showed; 1 when False), which weighs it in fusion.
    """

    def __init__(self, models=None, orientation: str = "plane", params: FrameParams | None = None,
                 min_confidence: float = 0.45, min_height_m: float = 0.3, tall_m: float = 1.3,
                 min_surface_share: float = 0.05, weigh_coverage: bool = True,
                 sure_confidence: float = 0.7, regroup: bool = True, verify: bool = True):
        if orientation not in ORIENTATION_METHODS:
            from assistant.errors import UnknownNameError

            raise UnknownNameError("orientation estimator", orientation, ORIENTATION_METHODS)
        if models is None:
            from assistant.perception.models import trained_models

            models = trained_models()
        self.models = models
        self.orientation = orientation
        self.params = params or FrameParams()
        self.min_confidence = min_confidence
        self.min_height_m = min_height_m
        self.tall_m = tall_m
        self.min_surface_share = min_surface_share
        self.weigh_coverage = weigh_coverage
        self.sure_confidence = sure_confidence
        self.regroup = regroup
        self.verify = verify
        self._floors: dict = {}  # pose key → the floor plane last found from that pose

    def analyse(self, frame: DepthFrame, use_mount: bool = True, pose_key=None) -> DetectionResult:
        """Detections of a frame with the floor and the reason when there are none; never raises
        on bad depth (empty, NaN, no floor, a wall filling the view).

        ``pose_key`` (any hashable value naming the camera's pose, e.g. a recording's pose id
        or a robot pose that has not changed) reuses the floor found in the last frame with the
        same key as the prediction, checked against this frame's points (``cloud.find_floor``):
        a camera that has not moved skips the floor search. The whole analysis runs with
        ``params.threads`` OpenMP and BLAS threads (``frame.thread_limit``)."""
        if self.params.threads is None:
            return self._analyse(frame, use_mount, pose_key)
        with thread_limit(self.params.threads):
            return self._analyse(frame, use_mount, pose_key)

    def _analyse(self, frame: DepthFrame, use_mount: bool, pose_key) -> DetectionResult:
        t0 = time.perf_counter()
        previous = self._floors.get(pose_key) if pose_key is not None else None
        inner = dataclasses.replace(self.params, threads=None)  # within ``analyse``'s thread limit
        analysis = analyse_frame(frame, inner, use_mount=use_mount, previous_floor=previous)
        if pose_key is not None and analysis.floor is not None:
            self._floors.pop(pose_key, None)
            self._floors[pose_key] = analysis.floor
            while len(self._floors) > FLOOR_MEMORY:
                self._floors.pop(next(iter(self._floors)))
        t1 = time.perf_counter()
        if not analysis.samples:
            return DetectionResult([], analysis, analysis.reason,
                                   {**analysis.timings_ms, "total": (t1 - t0) * 1e3})
        cam = analysis.camera_xyz
        shapes = [shape_descriptor(s.points, s.normals, camera_xy=cam[:2]) for s in analysis.samples]
        samples = list(analysis.samples)
        for sample, shape in zip(samples, shapes):
            sample.info["shape"] = shape
        labels = self._labels(np.hstack([analysis.features, np.array(shapes)]), samples)
        if self.regroup:
            samples, labels, notes = regroup(samples, labels, [float(sh[43]) for sh in shapes], cam,
                                             lambda parts: self._classify(parts, cam))
            if notes:
                analysis.stats["regrouped"] = notes
        out, unknown = self._detections(samples, labels, cam, frame.robot_pose)
        t2 = time.perf_counter()
        reason = None if out else f"{len(samples)} sample(s), none recognised as furniture"
        return DetectionResult(out, analysis, reason, {**analysis.timings_ms,
                                                       "classify": (t2 - t1) * 1e3,
                                                       "total": (t2 - t0) * 1e3}, unknown)

    def _classify(self, samples: list, camera_xyz: np.ndarray) -> list[tuple[str, float]]:
        """(subclass, confidence) of samples made by regrouping (normals, M_h and shape
        descriptor computed here; the shape kept in ``sample.info``)."""
        rows = []
        for s in samples:
            if s.normals is None:
                s.normals = estimate_normals(s.points, camera_xyz, self.params.features)
            s.info["shape"] = shape_descriptor(s.points, s.normals, camera_xy=camera_xyz[:2])
            rows.append(np.hstack([normal_histogram(s.points, s.normals, self.params.features),
                                   s.info["shape"]]))
        return self._labels(np.array(rows), samples, every=True)

    def _labels(self, X: np.ndarray, samples: list, every: bool = False) -> list[tuple[str, float]]:
        """(subclass, confidence) per row of ``[M_h | shape descriptor]``: the main
        classifier's, and for the beds and couches among them (``every``: for all, as the
        regrouped parts need) the verifier's say
        (:func:`~assistant.perception.classifiers.verified_category`) — a sample it turns into
        another category gets the verifier's subclass and confidence; ``sample.info["verified"]``
        records the change; ``sample.info["bed_probability"]`` keeps the larger of the two
        classifiers' probabilities of a bed."""
        subs, conf, main_p = self.models.classifier.predict_with_categories(X)
        labels = [(str(a), float(b)) for a, b in zip(subs, conf)]
        for sample, p in zip(samples, main_p.get("bed", np.zeros(len(samples)))):
            sample.info["bed_probability"] = float(p)
        verifier = getattr(self.models, "verifier", None)
        if verifier is None or not self.verify:
            return labels
        rows = [i for i, (sub, _) in enumerate(labels) if every or category_of(sub) in ("bed", "couch")]
        if not rows:
            return labels
        vsubs, vconf, verifier_p = verifier.predict_with_categories(X[rows])
        for k, (i, vsub, vc) in enumerate(zip(rows, vsubs, vconf)):
            samples[i].info["checked"] = category_of(str(vsub))
            samples[i].info["bed_probability"] = max(samples[i].info["bed_probability"],
                                                     float(verifier_p.get("bed", np.zeros(len(rows)))[k]))
            solid, open_ = X[i, -2], X[i, -1]
            final = verified_category(category_of(labels[i][0]), category_of(str(vsub)), solid, open_)
            if final != category_of(labels[i][0]):
                samples[i].info["verified"] = f"{labels[i][0]} → {vsub}"
                labels[i] = (str(vsub), float(vc))
        return labels

    def _detections(self, samples: list, labels: list, cam: np.ndarray, pose
                    ) -> tuple[list[Detection], list[UnknownItem]]:
        """Detections of the classified samples, and the unknown items among them."""
        frame_name = "world" if pose is not None else "camera-floor"
        out: list[Detection] = []
        unknown: list[UnknownItem] = []
        labels = night_stands(samples, labels)
        for sample, (sub, conf) in zip(samples, labels):
            if self._foot_end_of_bed(sample, category_of(sub)):
                sub, conf = "bed", float(sample.info.get("bed_probability", 0.0))
            category = category_of(sub)
            why = self._why_unknown(sample, category, conf)
            if why is not None:
                if why != "low":
                    ux, uy = _centre(sample.points[:, :2], None)
                    if pose is not None:
                        ux, uy = pose.transform_points(np.array([[ux, uy]]))[0]
                    unknown.append(UnknownItem(category, conf, float(ux), float(uy),
                                               float(sample.height_m), len(sample.cells_xy_m), why))
                continue
            foot_end = "partial_bed" in sample.info
            facing = None if foot_end else self._facing(sample, sub, cam[:2])
            cx, cy = _centre(sample.points[:, :2], facing, category, cam[:2])
            area = len(sample.cells_xy_m) * self.params.samples.grid_m ** 2
            coverage = view_coverage(area, category, sample.touches_border) if self.weigh_coverage else 1.0
            cells = sample.cells_xy_m
            beyond = range_cut(sample, self.params.samples.max_forward_m)
            if pose is not None:
                cx, cy = pose.transform_points(np.array([[cx, cy]]))[0]
                cells = pose.transform_points(cells)
                facing = None if facing is None else wrap_angle(facing + pose.theta)
            out.append(Detection(category, sub, float(cx), float(cy), facing, conf, cells,
                                 float(sample.height_m), sample.touches_border, frame_name, coverage,
                                 bool(conf < self.sure_confidence or foot_end), beyond))
        return out, unknown

    def _foot_end_of_bed(self, sample, category: str) -> bool:
        """Whether a sample is the foot end of a bed that goes on beyond the sample range: its
        board joined across its shadow with the mattress strip beyond it (``regroup``), cut by
        the range, read as a bed or couch by the main classifier and otherwise by the verifier.
        Neither classifier has seen such a view (a board and a strip of mattress, the rest out
        of range), but the join is the shape of a bed seen from its foot end: it is reported as
        a bed, partial (``beyond_range``) and unsure, with the classifiers' bed probability
        (``sample.info["partial_bed"]`` notes it)."""
        if (sample.info.get("joined") != "shadow" or category not in ("bed", "couch")
                or sample.info.get("checked", category) == category
                or not range_cut(sample, self.params.samples.max_forward_m)):
            return False
        sample.info["partial_bed"] = "a board joined across its shadow with what lies beyond, cut by the range"
        return True

    def _why_unknown(self, sample, category: str, conf: float) -> str | None:
        """Why a classified sample is not reported as a detection (:class:`UnknownItem`'s
        ``why``, or "low" for a sample under ``min_height_m``, dropped), or None."""
        if sample.height_m < self.min_height_m:
            return "low"
        if category == OTHER:
            return "other"
        if "partial_bed" in sample.info:
            return None
        if conf < self.min_confidence:
            return "unsure"
        if (category in ("bed", "couch") and sample.info.get("checked", category) != category
                and range_cut(sample, self.params.samples.max_forward_m)):
            return "disputed"  # cut by the range and the verifier reads it otherwise
        if "night_stand" not in sample.info and not _has_furniture_surface(
                sample.info["shape"], self.tall_m, self.min_surface_share):
            return "no surface"  # a tall thing with no seat, mattress or top: shelf, wardrobe, door
        return None

    def _facing(self, sample, subclass: str, camera_xy) -> float | None:
        if self.orientation == "linear":
            q = orientation_features(sample.points, sample.normals, self.params.features)
            value = self.models.linear_orientation.predict(q[None], [subclass])[0]
        else:
            value = self.models.plane_orientation.estimate(sample.points, sample.normals, subclass,
                                                           camera_xy)
        return None if not math.isfinite(value) else float(value)

    def detect(self, frame: DepthFrame, grid: GridMap | None = None) -> list[Entity]:
        """Detections as short-term entities on ``grid`` (default: a 0.1 m grid around them)."""
        return detections_to_entities(self.analyse(frame).detections, grid)


def night_stands(samples: list, labels: list, max_gap_m: float = 0.6, max_length_m: float = 1.4,
                 min_closed: float = 0.5) -> list:
    """``labels`` with each closed box called ``other`` (side cue ``solid`` ≥ ``min_closed``,
    no longer than ``max_length_m``) that stands within ``max_gap_m`` of a sample labelled a bed
    relabelled a small table: a night stand — the small, tall box beside a bed (with a lamp on
    it the verifier reads it as a dresser, ``other``)."""
    beds = [s.cells_xy_m for s, (sub, _) in zip(samples, labels) if category_of(sub) == "bed"]
    if not beds:
        return labels
    out = list(labels)
    for i, (s, (sub, conf)) in enumerate(zip(samples, labels)):
        shape = s.info.get("shape")
        if category_of(sub) != OTHER or shape is None or shape[-2] < min_closed or shape[41] > max_length_m:
            continue
        gap = min(_gap_m(b, s.cells_xy_m[::4], max_gap_m) for b in beds)
        if gap <= max_gap_m:
            s.info["night_stand"] = f"beside a bed, {gap:.2f} m"
            out[i] = ("small table", conf)
    return out


def _gap_m(a: np.ndarray, b: np.ndarray, within_m: float) -> float:
    """The least distance (metres) between two sets of cell centres, or ``inf`` when their
    bounding boxes already lie more than ``within_m`` apart (no pair can be nearer)."""
    apart = np.maximum(a.min(axis=0) - b.max(axis=0), b.min(axis=0) - a.max(axis=0))
    if float(np.hypot(*np.maximum(apart, 0.0))) > within_m:
        return math.inf
    dx = a[:, 0, None] - b[None, :, 0]
    dy = a[:, 1, None] - b[None, :, 1]
    dx *= dx
    dy *= dy
    dx += dy  # the squared distances as ``np.linalg.norm`` sums them, without its (M, K, 2) copy
    return math.sqrt(float(dx.min()))  # the least root is the root of the least square


def _has_furniture_surface(shape: np.ndarray, tall_m: float, min_share: float) -> bool:
    """False for a tall sample without a seat, mattress or table top (shape descriptor)."""
    top = shape[40]
    surface = shape[26:35].sum()  # upward-facing share in the 0.30–0.75 m height bins
    return not (top > tall_m and surface < min_share)


def _centre(xy: np.ndarray, facing: float | None, category: str | None = None,
            camera_xy=(0.0, 0.0)) -> tuple[float, float]:
    """Middle of the points' 2nd–98th percentile extent along the item's axes (its facing,
    else the principal axes): nearer the true centre than the mean of the visible points.

    Along the front axis of a chair, couch or bed seen over less than 85 % of its category's
    typical depth (the catalogue's models), the far side is hidden: the centre is put half a
    typical depth beyond the near side, away from the camera.
    """
    if len(xy) < 3:
        c = xy.mean(axis=0)
        return float(c[0]), float(c[1])
    if facing is not None:
        a = facing
        axes = np.array([[math.cos(a), math.sin(a)], [-math.sin(a), math.cos(a)]])
    else:
        _, vecs = np.linalg.eigh(covariance(centred_xy(xy)[0].T))
        axes = vecs.T
    local = xy @ axes.T
    lo, hi = percentiles(local, (2, 98))
    mid = (lo + hi) / 2
    depth = typical_depth_m(category) if facing is not None else None
    if depth and hi[0] - lo[0] < 0.85 * depth:
        cam = float(np.asarray(camera_xy, dtype=float) @ axes[0])
        if cam <= lo[0]:
            mid[0] = lo[0] + depth / 2
        elif cam >= hi[0]:
            mid[0] = hi[0] - depth / 2
    c = mid @ axes
    return float(c[0]), float(c[1])


def view_coverage(area_m2: float, category: str, partial: bool, floor: float = 0.2) -> float:
    """How much of an item one view showed (0–1): the floor area its sample covers over the
    category's typical footprint (capped at 1, at least ``floor``), halved when the sample runs
    out of the image."""
    typical = typical_area_m2(category)
    share = 1.0 if not typical else min(1.0, max(floor, area_m2 / typical))
    return share * (0.5 if partial else 1.0)


@lru_cache(maxsize=None)
def typical_area_m2(category: str | None) -> float | None:
    """Median footprint (m², length × width) of the catalogue's models of a category."""
    from assistant.world import load_catalogue

    areas = load_catalogue().footprints_m2(category)
    return float(np.median(areas)) if areas else None


@lru_cache(maxsize=None)
def typical_depth_m(category: str | None) -> float | None:
    """Median front-to-back depth (metres) of the catalogue's models of a category."""
    from assistant.world import load_catalogue

    depths = []
    for model in load_catalogue().models.values():
        if model.category == category and model.front_offset_rad is not None:
            along = abs(math.cos(model.front_offset_rad)) > 0.5
            depths.append(model.length_m if along else model.width_m)
    return float(np.median(depths)) if depths else None


def detections_to_entities(detections: list[Detection], grid: GridMap | None = None,
                           id_prefix: str = "seen") -> list[Entity]:
    """Short-term entities (name = category word) from detections; an entity's ``confidence``
    is the detection's :attr:`~Detection.weight` (classifier confidence × view coverage)."""
    from assistant.world.catalogue import category_word

    if not detections:
        return []
    if grid is None:
        allc = np.vstack([d.cells_xy for d in detections])
        grid = GridMap.covering(*allc.min(axis=0), *allc.max(axis=0), resolution_m=0.1, margin_m=0.2)
    out = []
    for i, d in enumerate(detections):
        cells = grid.world_to_cell(d.cells_xy)
        cells = np.unique(cells[grid.contains_cells(cells)], axis=0)
        out.append(Entity(f"{id_prefix}:{i}", category_word(d.category), EntityKind.SHORT_TERM, grid,
                          cells, d.facing, category=d.category, confidence=d.weight,
                          attributes={"subclass": d.subclass, "x": d.x, "y": d.y,
                                      "classifier_confidence": d.confidence, "coverage": d.coverage,
                                      "height_m": d.height_m, "partial": d.partial,
                                      "unsure": d.unsure}))
    return out


def frame_pose_or_none(frame: DepthFrame) -> Pose2D | None:
    return frame.robot_pose

"""Furniture orientation (dissertation 3.6.5): where a chair, couch or bed faces.

Two estimators, both returning the functional front in the floor frame (radians) — or NaN for
a category without a front (tables):

* :class:`LinearOrientationEstimator` — Table 3-3. Features: per (radius, height) bin the mean
  horizontal normal direction q (equation 3-4) and q + π. One weight per feature and subclass,
  initialised to 1/L and updated over the training samples by
  ``w_i ← w_i · normalize(x_i − o)``, ``w ← w / max(w)``, where ``normalize`` turns the angle
  difference (0…π) into a similarity 1 − |Δ|/π (the dissertation's wording leaves this open;
  multiplying by the raw difference would *raise* the weight of unrelated bins, the opposite of
  its stated goal), and an empty bin gets the neutral factor 0.5. The estimate is the
  weighted circular mean of the sample's filled features.
* :class:`PlaneOrientationEstimator` — this product's design, from the height profile. The
  points above 75 % of the item's height are its backrest or headboard; on the floor plan they
  form a line, and the front is perpendicular to it, on the side where the rest of the item
  (seat, mattress, front legs) lies. When nothing but the back is visible, the front faces
  away from the camera. A bed whose headboard is not in view (out of range, or out of the
  image when the robot stands close) gets no estimate (NaN) rather than a guess: the
  environment model takes its orientation from other views. Without a line-like tall part, the
  axis comes from the 4-fold circular mean of the horizontal normals (a rectangular item's
  sides are at 90° to each other) and the front is the direction away from the tall points.
"""

from __future__ import annotations

import math

import numpy as np
from sklearn.base import BaseEstimator
from sklearn.utils.validation import check_is_fitted

from assistant.perception.classifiers import category_of

HAS_FRONT = ("chair", "couch", "bed")


def _has_front(subclass: str) -> bool:
    return category_of(subclass) in HAS_FRONT


def angle_error(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Absolute angle difference in [0, π] (radians)."""
    d = np.asarray(a, dtype=float) - np.asarray(b, dtype=float)
    return np.abs((d + np.pi) % (2 * np.pi) - np.pi)


class LinearOrientationEstimator(BaseEstimator):
    """Table 3-3's linear orientation estimator, one weight vector per subclass."""

    def __init__(self, empty_factor=0.5):
        self.empty_factor = empty_factor

    @staticmethod
    def _expand(Q: np.ndarray) -> np.ndarray:
        """[q, q + π] per bin: (n, 2L)."""
        Q = np.atleast_2d(np.asarray(Q, dtype=float))
        return np.hstack([Q, Q + np.pi])

    def fit(self, Q, subclass, facing):
        """``Q`` (n, L) orientation features, ``subclass`` names, ``facing`` (n,) true fronts."""
        X = self._expand(Q)
        subclass = np.asarray(subclass)
        facing = np.asarray(facing, dtype=float)
        self.weights_ = {}
        for sub in np.unique(subclass):
            if not _has_front(sub):
                continue
            w = np.full(X.shape[1], 1.0 / X.shape[1])
            for t in np.nonzero((subclass == sub) & np.isfinite(facing))[0]:
                x = X[t]
                factor = np.full(len(x), float(self.empty_factor))
                filled = np.isfinite(x)
                factor[filled] = 1.0 - angle_error(x[filled], facing[t]) / np.pi
                w = w * factor
                w = w / max(w.max(), 1e-300)
            self.weights_[sub] = w
        return self

    def predict(self, Q, subclass) -> np.ndarray:
        check_is_fitted(self, "weights_")
        X = self._expand(Q)
        out = np.full(len(X), np.nan)
        for i, sub in enumerate(np.asarray(subclass)):
            w = self.weights_.get(sub)
            if w is None:
                continue
            x = X[i]
            filled = np.isfinite(x)
            if not filled.any() or w[filled].sum() <= 0:
                continue
            out[i] = math.atan2((w[filled] * np.sin(x[filled])).sum(), (w[filled] * np.cos(x[filled])).sum())
        return out


class PlaneOrientationEstimator(BaseEstimator):
    """Front from the item's vertical surfaces and its tall side (see the module docstring).

    ``high_fraction``: points above this share of the item's top height are the backrest or
    headboard; ``vertical_nz``: normals with |nz| below this are vertical surfaces.
    """

    def __init__(self, high_fraction=0.75, vertical_nz=0.3, line_ratio=4.0, back_view_m=0.06,
                 min_headboard_m=0.7):
        self.high_fraction = high_fraction
        self.vertical_nz = vertical_nz
        self.line_ratio = line_ratio
        self.back_view_m = back_view_m
        self.min_headboard_m = min_headboard_m

    def fit(self, samples=None, subclass=None, facing=None):
        """Nothing to learn; kept for the estimator contract."""
        self.fitted_ = True
        return self

    def estimate(self, points: np.ndarray, normals: np.ndarray, subclass: str,
                 camera_xy=(0.0, 0.0)) -> float:
        """The front (radians, floor frame) of one sample, NaN without a front or evidence.

        ``camera_xy`` is the camera's position in the same frame (it settles a view of the
        back alone, where nothing but the backrest is visible).
        """
        check_is_fitted(self, "fitted_")
        if not _has_front(subclass) or len(points) < 10:
            return math.nan
        z = points[:, 2]
        xy = points[:, :2]
        cam = np.asarray(camera_xy, dtype=float)
        to_item = xy.mean(axis=0) - cam
        top = float(np.percentile(z, 99))
        high = z > self.high_fraction * top
        if category_of(subclass) == "bed" and top < self.min_headboard_m:
            return math.nan  # no headboard in view (out of range or of the image): unknown
        if high.sum() < 3:
            return math.nan
        hxy = xy[high]
        centre = hxy.mean(axis=0)
        evals, evecs = np.linalg.eigh(np.cov((hxy - centre).T))
        if evals[1] > self.line_ratio * max(evals[0], 1e-9):
            # the backrest / headboard is a line on the floor plan: the front is across it
            normal = evecs[:, 0]
            low = xy[~high]
            offset = float(np.mean((low - centre) @ normal)) if len(low) else 0.0
            if abs(offset) < self.back_view_m:
                # only the back is visible: the front faces away from the camera
                sign = 1.0 if normal @ to_item > 0 else -1.0
            else:
                sign = 1.0 if offset > 0 else -1.0
            front = sign * normal
            return float(math.atan2(front[1], front[0]))
        axis = self._normal_axis(normals)
        if math.isnan(axis):
            return math.nan
        best, best_score = math.nan, -math.inf
        for k in range(4):
            a = axis + k * math.pi / 2
            u = np.array([math.cos(a), math.sin(a)])
            along = xy @ u
            lo, hi = np.percentile(along, 2), np.percentile(along, 98)
            half = max((hi - lo) / 2, 1e-3)
            # the tall part lies towards the back: the far end from the front direction
            score = ((lo + hi) / 2 - float(np.mean(along[high]))) / half
            if score > best_score:
                best, best_score = a, score
        return float(math.atan2(math.sin(best), math.cos(best)))

    def _normal_axis(self, normals: np.ndarray) -> float:
        """The item's axis (mod 90°) from the 4-fold circular mean of its vertical surfaces."""
        vertical = np.abs(normals[:, 2]) < self.vertical_nz
        if vertical.sum() < 5:
            return math.nan
        q = np.arctan2(normals[vertical, 1], normals[vertical, 0])
        weight = np.hypot(normals[vertical, 0], normals[vertical, 1])
        return math.atan2((weight * np.sin(4 * q)).sum(), (weight * np.cos(4 * q)).sum()) / 4

    def predict(self, points_list, normals_list, subclass, camera_xy=(0.0, 0.0)) -> np.ndarray:
        return np.array([self.estimate(p, n, s, camera_xy)
                         for p, n, s in zip(points_list, normals_list, subclass)])

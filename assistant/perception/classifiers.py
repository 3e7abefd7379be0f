"""Furniture classifiers on the normal feature histogram (dissertation 3.6.3–3.6.4).

Classes are *subclasses*: a category seen from one side ("chair+front", "couch+side", "bed+front",
"small table"), found by k-means on each category's training features (:func:`view_subclasses`)
and named by the side the robot saw most in each cluster. Three classifiers, all scikit-learn
estimators predicting subclass names:

Features: the normal feature histogram M_h, optionally joined by the shape descriptor
(:class:`FeatureBlocks`).

* ``lsvm``  — linear SVM (``LinearSVC``) on standardised features;
* ``gsvm``  — Gaussian-kernel SVM (``SVC(kernel="rbf")``);
* ``autoencoder`` — :class:`AutoencoderClassifier`: a 512-128-32 encoder pre-trained to
  reconstruct its input (``MLPRegressor``), then fine-tuned with a softmax output
  (``MLPClassifier`` warm-started from the encoder's weights);
* ``forest`` — a random forest (100 trees, balanced class weights) on the raw features (not
  in the dissertation; its errors differ from the SVM's);
* ``vote`` — the soft vote (mean class probability) of the Gaussian SVM, its probabilities
  calibrated by cross-validation (``CalibratedClassifierCV``), and the forest. Measured, not
  the default: ``gsvm`` is (``models.DEFAULT_METHOD``; the tables of docs/perception.md,
  ``assistant eval perception``).

:func:`category_of` maps a subclass back to its category.
"""

from __future__ import annotations

import math

import numpy as np
from sklearn.base import BaseEstimator, ClassifierMixin, TransformerMixin, clone
from sklearn.ensemble import RandomForestClassifier
from sklearn.utils.validation import check_is_fitted

#: number of view subclasses per category (Table 3-2)
SUBCLASS_COUNTS = {"chair": 2, "couch": 3, "bed": 2, "small table": 1, "large table": 1, "other": 1}
CLASSIFIERS = ("lsvm", "gsvm", "autoencoder", "forest", "vote")


def category_of(subclass: str) -> str:
    """"couch+side" → "couch"; "small table" → "small table"."""
    return subclass.split("+", 1)[0]


def view_subclasses(X: np.ndarray, category: np.ndarray, alpha: np.ndarray,
                    seed: int = 0) -> np.ndarray:
    """Subclass name of each training sample: k-means (``SUBCLASS_COUNTS`` clusters) on each
    category's features, each cluster named front / back / side by the mean angle ``alpha``
    between the item's front and the direction to the camera of its members (0 = seen from
    the front). Categories with one subclass keep their name."""
    from sklearn.cluster import KMeans

    out = np.array(category, dtype=object)
    for cat, k in SUBCLASS_COUNTS.items():
        idx = np.nonzero(np.asarray(category) == cat)[0]
        if k == 1 or len(idx) < k:
            continue
        km = KMeans(n_clusters=k, n_init=10, random_state=seed).fit(X[idx])
        names = _name_clusters(km.labels_, np.asarray(alpha)[idx], k)
        out[idx] = [f"{cat}+{names[c]}" for c in km.labels_]
    return out.astype(str)


def _name_clusters(labels: np.ndarray, alpha: np.ndarray, k: int) -> dict[int, str]:
    """front / back / side for each cluster, each name used once (most typical cluster first)."""
    stats = {}
    for c in range(k):
        a = alpha[labels == c]
        a = a[np.isfinite(a)]
        cos = float(np.mean(np.cos(a))) if len(a) else 0.0
        side = float(np.mean(np.abs(np.sin(a)))) if len(a) else 0.0
        stats[c] = {"front": cos, "back": -cos, "side": side - abs(cos)}
    wanted = ["front", "back", "side"][:k]
    names: dict[int, str] = {}
    # greedy assignment: the strongest (cluster, name) score first
    pairs = sorted(((stats[c][n], c, n) for c in range(k) for n in wanted), reverse=True)
    for _, c, n in pairs:
        if c not in names and n not in names.values():
            names[c] = n
    return names


class AutoencoderClassifier(ClassifierMixin, BaseEstimator):
    """The autoencoder network of 3.6.4, with scikit-learn's MLPs.

    Step 1: an ``encoder`` (default 512-128-32) + mirrored decoder trained to reconstruct the
    features (unsupervised). Step 2: the encoder's weights initialise an ``MLPClassifier`` of
    the same hidden layers with a softmax output, trained with cross-entropy. ``activation``
    "identity" is the dissertation's *purelin*; "relu" is offered because it measures better.
    """

    def __init__(self, encoder=(512, 128, 32), activation="relu", pretrain_iter=60,
                 finetune_iter=200, alpha=1e-4, random_state=0):
        self.encoder = encoder
        self.activation = activation
        self.pretrain_iter = pretrain_iter
        self.finetune_iter = finetune_iter
        self.alpha = alpha
        self.random_state = random_state

    def fit(self, X, y):
        import warnings

        from sklearn.exceptions import ConvergenceWarning
        from sklearn.neural_network import MLPClassifier, MLPRegressor
        from sklearn.preprocessing import StandardScaler

        X = np.asarray(X, dtype=float)
        self.scaler_ = StandardScaler().fit(X)
        Z = self.scaler_.transform(X)
        layers = tuple(self.encoder)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", ConvergenceWarning)
            ae = MLPRegressor(hidden_layer_sizes=layers + layers[-2::-1], activation=self.activation,
                              alpha=self.alpha, max_iter=self.pretrain_iter,
                              random_state=self.random_state, early_stopping=False)
            ae.fit(Z, Z)
            clf = MLPClassifier(hidden_layer_sizes=layers, activation=self.activation,
                                alpha=self.alpha, max_iter=1, warm_start=True,
                                random_state=self.random_state)
            clf.fit(Z, y)  # builds the layers; then the encoder's weights replace them
            for i in range(len(layers)):
                clf.coefs_[i] = ae.coefs_[i].copy()
                clf.intercepts_[i] = ae.intercepts_[i].copy()
            clf.set_params(max_iter=self.finetune_iter)
            clf.fit(Z, y)
        self.autoencoder_loss_ = float(ae.loss_)
        self.network_ = clf
        self.classes_ = clf.classes_
        return self

    def predict_proba(self, X):
        check_is_fitted(self, "network_")
        return self.network_.predict_proba(self.scaler_.transform(np.asarray(X, dtype=float)))

    def predict(self, X):
        proba = self.predict_proba(X)
        return self.classes_[np.argmax(proba, axis=1)]


class FeatureBlocks(TransformerMixin, BaseEstimator):
    """Standardise the features and pick the blocks a classifier sees.

    The input is ``[M_h | shape descriptor]`` (``mh_length`` + the rest). ``features="mh"`` keeps
    the dissertation's normal feature histogram alone; ``"mh+shape"`` adds the shape
    descriptor without its last ``cue_columns`` (the side cues of issue 20), its standardised
    columns multiplied by ``shape_weight`` so 49 columns can count against 800 in a kernel's
    distance; ``"mh+shape+cues"`` (the verifier's) keeps the side cues too, multiplied by
    ``cue_weight`` more.
    """

    def __init__(self, features="mh+shape", shape_weight=4.0, mh_length=800, cue_columns=2,
                 cue_weight=3.0):
        self.features = features
        self.shape_weight = shape_weight
        self.mh_length = mh_length
        self.cue_columns = cue_columns
        self.cue_weight = cue_weight

    def _select(self, X):
        X = np.asarray(X, dtype=float)
        if self.features == "mh":
            return X[:, :self.mh_length]
        if self.features == "mh+shape":
            return X[:, :X.shape[1] - self.cue_columns]
        if self.features == "mh+shape+cues":
            return X
        raise ValueError(f"features must be 'mh', 'mh+shape' or 'mh+shape+cues', got {self.features!r}")

    def fit(self, X, y=None):
        Z = self._select(X)
        self.mean_ = Z.mean(axis=0)
        self.scale_ = Z.std(axis=0)
        self.scale_[self.scale_ < 1e-9] = 1.0
        return self

    def transform(self, X):
        check_is_fitted(self, "mean_")
        Z = (self._select(X) - self.mean_) / self.scale_
        if self.features != "mh":
            Z[:, self.mh_length:] *= self.shape_weight
        if self.features == "mh+shape+cues":
            Z[:, -self.cue_columns:] *= self.cue_weight
        return Z


def make_classifier(name: str, features: str = "mh+shape", random_state: int = 0):
    """A fresh estimator by name (``lsvm``, ``gsvm``, ``autoencoder``) on ``features``."""
    from sklearn.pipeline import make_pipeline
    from sklearn.svm import SVC, LinearSVC

    from assistant.errors import UnknownNameError

    blocks = FeatureBlocks(features)
    if name == "lsvm":
        return make_pipeline(blocks, LinearSVC(C=0.05, max_iter=5000, class_weight="balanced",
                                               random_state=random_state))
    if name == "gsvm":
        return make_pipeline(blocks, SVC(kernel="rbf", C=1.0, gamma="scale", class_weight="balanced"))
    if name == "autoencoder":
        return make_pipeline(blocks, AutoencoderClassifier(random_state=random_state))
    if name == "forest":
        return _forest(features, random_state)
    if name == "vote":
        from sklearn.calibration import CalibratedClassifierCV
        from sklearn.ensemble import VotingClassifier

        svm = make_pipeline(blocks, CalibratedClassifierCV(
            SVC(kernel="rbf", C=1.0, gamma="scale", class_weight="balanced"), ensemble=False))
        return VotingClassifier([("gsvm", svm), ("forest", _forest(features, random_state))],
                                voting="soft")
    raise UnknownNameError("classifier", name, CLASSIFIERS)


def _forest(features: str, random_state: int, n_estimators: int = 100):
    """A random forest on the selected feature blocks (trees need no standardising)."""
    from sklearn.pipeline import make_pipeline

    return make_pipeline(FeatureBlocks(features, shape_weight=1.0),
                         QuickForest(n_estimators=n_estimators, class_weight="balanced",
                                     random_state=random_state, n_jobs=1))


class QuickForest(RandomForestClassifier):
    """``RandomForestClassifier`` whose ``predict_proba`` walks the trees in a plain loop: for
    the one to five samples of a frame that avoids the threaded version's per-call start-up
    (the same trees, the same probabilities; ``assistant eval perception`` prints the
    prediction time per sample of each classifier)."""

    def predict_proba(self, X):
        check_is_fitted(self, "estimators_")
        X = self._validate_X_predict(X)
        proba = self.estimators_[0].predict_proba(X, check_input=False)
        for tree in self.estimators_[1:]:
            proba = proba + tree.predict_proba(X, check_input=False)
        return proba / len(self.estimators_)


class FurnitureClassifier(ClassifierMixin, BaseEstimator):
    """Subclass classifier + confidence: ``predict`` gives subclass names, ``predict_category``
    categories, ``scores`` class probabilities (the estimator's own — calibrated for ``vote`` —
    or, for the SVMs, a softmax of the decision values)."""

    def __init__(self, method="gsvm", features="mh+shape", random_state=0):
        self.method = method
        self.features = features
        self.random_state = random_state

    def fit(self, X, y):
        self.estimator_ = clone(make_classifier(self.method, self.features, self.random_state)).fit(X, y)
        self.classes_ = np.asarray(self.estimator_.classes_)
        for cached in ("_rbf_decision", "_categories"):  # made from the previous fit
            self.__dict__.pop(cached, None)
        return self

    def predict(self, X):
        check_is_fitted(self, "estimator_")
        return np.asarray(self.estimator_.predict(X))

    def predict_category(self, X) -> np.ndarray:
        return np.array([category_of(s) for s in self.predict(X)])

    def scores(self, X) -> np.ndarray:
        """(n, classes) probabilities (softmax of SVM decision values; a Gaussian SVM's values
        through :class:`RBFDecision`)."""
        check_is_fitted(self, "estimator_")
        if hasattr(self.estimator_, "predict_proba"):
            return self.estimator_.predict_proba(X)
        fast = self.__dict__.get("_rbf_decision")
        if fast is None:
            fast = self.__dict__["_rbf_decision"] = RBFDecision.of(self.estimator_) or False
        d = fast(X) if fast else np.asarray(self.estimator_.decision_function(X), dtype=float)
        if d.ndim == 1:
            d = np.stack([-d, d], axis=1)
        e = np.exp(2.0 * (d - d.max(axis=1, keepdims=True)))
        return e / e.sum(axis=1, keepdims=True)

    def predict_with_confidence(self, X) -> tuple[np.ndarray, np.ndarray]:
        """Subclass per sample and the summed probability of its category (0–1)."""
        sub, conf, _ = self.predict_with_categories(X)
        return sub, conf

    def predict_with_categories(self, X) -> tuple[np.ndarray, np.ndarray, dict[str, np.ndarray]]:
        """Subclass per sample, the summed probability of its category (0–1), and each
        category's summed probability per sample ({category: (n,)})."""
        p = self.scores(X)
        best = np.argmax(p, axis=1)
        cats = self.__dict__.get("_categories")  # each class's category, once per fit
        if cats is None:
            cats = self.__dict__["_categories"] = np.array([category_of(c) for c in self.classes_])
        per_category = {c: p[:, cats == c].sum(axis=1) for c in dict.fromkeys(cats)}
        conf = np.array([per_category[cats[k]][i] for i, k in enumerate(best)])
        return self.classes_[best], conf, per_category


class RBFDecision:
    """The one-vs-rest decision values of a fitted ``FeatureBlocks`` → ``SVC(kernel="rbf")``
    pipeline with three or more classes — the values ``decision_function`` gives, to a few
    millionths — from one matrix product per call: the kernel between the rows and every support
    vector (``‖x‖² + ‖s‖² − 2 x·s``, the product ``x·s`` in single precision: it streams the
    support vectors, 5–11 MB in double, from memory at every call, and half of that is half
    the time), then each class pair's dual coefficients as one (support vectors × pairs)
    matrix, then the votes and confidences scikit-learn sums for "ovr". libsvm works out the
    kernel one support vector at a time (a frame's three rows cost 6–9 ms of the detector's
    ~800 and ~1600 support vectors under load; this 0.4–1 ms), and the pipeline validates its
    input at every step. Measured on the 2729 training rows: decision values within 4e-6 of
    scikit-learn's, no row's class changed. :meth:`of` gives None for anything else.

    Why not scikit-learn's own call: measured on the trained models (808 and 1627 support
    vectors, three rows, one thread), ``decision_function`` took 2.6 and 5.1 ms, and 2.4 and
    4.1 ms under ``sklearn.config_context(assume_finite=True, skip_parameter_validation=True)``
    (the time is libsvm's kernel loop, not the checks); this takes 0.6 and 1.2 ms. It reads
    scikit-learn's private ``SVC._gamma`` (what ``gamma="scale"`` became at fit time): when a
    version has no such float, :meth:`of` gives None and scikit-learn's call is used, and
    ``tests/perception/test_classifiers.py`` pins the values to ``decision_function`` on the
    installed version."""

    def __init__(self, blocks, svc):
        self.blocks = blocks
        sv = np.asarray(svc.support_vectors_, dtype=float)
        self.sv_sq = np.einsum("ij,ij->i", sv, sv)
        self.sv_t = np.ascontiguousarray(sv.T, dtype=np.float32)  # (features, support vectors)
        self.gamma = float(svc._gamma)  # the value "scale" stood for at fit time (checked by :meth:`of`)
        n = len(svc.classes_)
        starts = np.concatenate([[0], np.cumsum(svc.n_support_)])
        pairs = [(i, j) for i in range(n) for j in range(i + 1, n)]
        coef = np.asarray(svc.dual_coef_, dtype=float)
        self.weights = np.zeros((len(sv), len(pairs)))
        self.sides = np.zeros((len(pairs), n))  # +1 for the pair's first class, −1 for its second
        self.first = np.zeros((len(pairs), n))
        self.second = np.zeros((len(pairs), n))
        for p, (i, j) in enumerate(pairs):
            si, sj = slice(starts[i], starts[i + 1]), slice(starts[j], starts[j + 1])
            self.weights[si, p] = coef[j - 1, si]
            self.weights[sj, p] = coef[i, sj]
            self.sides[p, i], self.sides[p, j] = 1.0, -1.0
            self.first[p, i] = self.second[p, j] = 1.0
        self.intercept = np.asarray(svc.intercept_, dtype=float)

    @classmethod
    def of(cls, estimator) -> "RBFDecision | None":
        from sklearn.pipeline import Pipeline
        from sklearn.svm import SVC

        steps = estimator.steps if isinstance(estimator, Pipeline) else []
        if (len(steps) != 2 or not isinstance(steps[0][1], FeatureBlocks) or not isinstance(steps[1][1], SVC)
                or steps[1][1].kernel != "rbf" or len(steps[1][1].classes_) < 3
                or steps[1][1].decision_function_shape != "ovr"
                or not isinstance(getattr(steps[1][1], "_gamma", None), float)):
            return None  # scikit-learn's own decision function (also if its private gamma moves)
        return cls(steps[0][1], steps[1][1])

    def __call__(self, X) -> np.ndarray:
        Z = self.blocks.transform(X)
        cross = (Z.astype(np.float32) @ self.sv_t).astype(float)
        dist = np.einsum("ij,ij->i", Z, Z)[:, None] + self.sv_sq[None, :] - 2.0 * cross
        kernel = np.exp(-self.gamma * np.maximum(dist, 0.0))
        dec = kernel @ self.weights + self.intercept  # libsvm's one-vs-one values
        confidence = dec @ self.sides
        votes = (dec >= 0) @ self.first + (dec < 0) @ self.second
        return votes + confidence / (3.0 * (np.abs(confidence) + 1.0))


#: the verifier's say (:func:`verified_category`): the least share of open bearings (knee space
#: seen under the top) for a bed or couch to become a table, and of closed ones (a box's
#: side) for it to become a night stand (small table) or ``other``
KNEE_SPACE_SHARE = 0.3
CLOSED_SIDE_SHARE = 0.5


def verified_category(category: str, verifier_category: str, solid: float, open_: float) -> str:
    """The detector's category of a sample the main classifier calls ``category``, given the
    verifier's call and the side cues (``features.side_cues``): a bed or couch stays one unless
    the verifier — trained on desks, night stands, store beds, benches and dressers too — calls
    it a table and knee space is seen under its top (``open_`` ≥ :data:`KNEE_SPACE_SHARE`), or
    a small table or ``other`` and its near side is closed (``solid`` ≥
    :data:`CLOSED_SIDE_SHARE`). Other categories are the main classifier's."""
    if category not in ("bed", "couch"):
        return category
    if verifier_category == "large table" and open_ >= KNEE_SPACE_SHARE:
        return verifier_category
    if verifier_category in ("small table", "other") and solid >= CLOSED_SIDE_SHARE:
        return verifier_category
    return category


def circular_mean(angles: np.ndarray) -> float:
    a = np.asarray(angles, dtype=float)
    a = a[np.isfinite(a)]
    return math.atan2(np.sin(a).sum(), np.cos(a).sum()) if len(a) else math.nan

"""``assistant eval perception``: Tables 3-6 to 3-9 of the dissertation, on this product.

* Table 3-6 — category accuracy of the three classifiers on held-out simulated views of the
  study models (the grid views of 3.7.2 plus random views, none used in training);
* Table 3-7 — the same classifiers, trained on the study models, on the *other* instances;
* Table 3-8 — orientation error (mean/std, degrees) per subclass, both estimators;
* Table 3-9 — the 16 scenes: position error, orientation error, spatial relations;
* real frames (``--realdata PATH``, e.g. ``../shared/realdata``), reported separately.
"""

from __future__ import annotations

import math
import time

import numpy as np

from assistant.eval.progress import Progress, no_progress

CATEGORY_ORDER = ("small table", "chair", "large table", "couch", "bed")
TEST_PLAN_ARGS = dict(grid=True, random_per_item=16, seed=2)
OTHER_PLAN_ARGS = dict(grid=True, seed=3)
#: the classifiers compared by default: the dissertation's three, the random forest and the vote
DEFAULT_CLASSIFIERS = ("lsvm", "gsvm", "autoencoder", "forest", "vote")
#: the dissertation's Tables 3-6 and 3-7: category accuracy per classifier (its "deep network"
#: is the autoencoder here); Table 3-7's data set had no beds
DISSERTATION_TABLES = {
    "table_3_6": {"lsvm": {"small table": 0.99, "chair": 0.77, "large table": 0.875, "couch": 0.50, "bed": 0.625,
                           "all": 0.83},
                  "gsvm": {"small table": 0.98, "chair": 0.958, "large table": 0.935, "couch": 0.80, "bed": 0.875,
                           "all": 0.93},
                  "autoencoder": {"small table": 0.935, "chair": 0.938, "large table": 0.935, "couch": 1.0, "bed": 0.90,
                                  "all": 0.93}},
    "table_3_7": {"lsvm": {"small table": 1.0, "chair": 0.74, "large table": 0.71, "couch": 0.0, "all": 0.616},
                  "gsvm": {"small table": 1.0, "chair": 1.0, "large table": 0.952, "couch": 0.909, "all": 0.964},
                  "autoencoder": {"small table": 1.0, "chair": 1.0, "large table": 1.0, "couch": 1.0, "all": 1.0}},
}


def frame_params(range_m: float | None):
    """The detector's frame parameters, with the sample range (points kept, floor grid) set to
    ``range_m`` metres ahead when given."""
    import dataclasses

    from assistant.perception.frame import FrameParams

    params = FrameParams()
    if range_m is None:
        return params
    if not 1.0 <= range_m <= 8.0:
        from assistant.errors import AssistantError

        raise AssistantError(f"--range-m must be 1 to 8 metres, got {range_m:g}")
    return dataclasses.replace(params, samples=dataclasses.replace(
        params.samples, max_forward_m=range_m, x_range_m=(params.samples.x_range_m[0], range_m)))


def evaluate_perception(realdata=None, *, skip=(), classifiers=DEFAULT_CLASSIFIERS,
                        train_plans: int | None = None, range_m: float | None = None,
                        coverage: bool = True, variants: bool = True,
                        progress: Progress = no_progress) -> dict:
    """Tables 3-6 to 3-9 and, with ``realdata`` (a folder of real frames), the real-frame checks.

    ``skip``: parts left out (``classify``, ``orientation``, ``scenes``, ``real``);
    ``classifiers``: the methods of Tables 3-6/3-7; ``train_plans``: train on the first K
    training view plans only; ``range_m``: how far ahead the detector keeps points;
    ``coverage``: weigh detections by view coverage when fusing; ``variants``: the detector
    with the verifier trained on the training variants (False: issue 6's detector). Returns
    the JSON report."""
    from assistant.perception.models import TRAINING_PLANS

    skip = set(skip)
    report: dict = {}
    t0 = time.perf_counter()
    if train_plans is not None and not 1 <= train_plans <= len(TRAINING_PLANS):
        from assistant.errors import AssistantError

        raise AssistantError(f"--train-plans must be 1 to {len(TRAINING_PLANS)}, got {train_plans}")
    plans = TRAINING_PLANS[:train_plans] if train_plans else TRAINING_PLANS
    params = frame_params(range_m)  # a bad range is reported before any work
    report["settings"] = {"training_plans": len(plans), "coverage_weighting": coverage,
                          "training_variants": variants,
                          "range_m": params.samples.max_forward_m}
    detector = None
    if "scenes" not in skip or (realdata and "real" not in skip):
        from assistant.perception.detector import FurnitureDetector
        from assistant.perception.models import trained_models

        progress("training (or loading) the detector's models")
        t = time.perf_counter()
        detector = FurnitureDetector(trained_models(plans=plans, variants=variants),
                                     weigh_coverage=coverage, params=params)
        report["settings"]["detector_ready_seconds"] = round(time.perf_counter() - t, 1)
    if not {"classify", "orientation"} <= skip:
        progress("rendering (or loading) the view databases")
        train, test, other = databases(plans)
        report["databases"] = {"train": len(train), "test": len(test), "other": len(other),
                               "missed_views": {"test": test.missed, "other": other.missed},
                               "seconds": round(time.perf_counter() - t0, 1)}
        if "classify" not in skip:
            progress("Tables 3-6 and 3-7: classifiers")
            verifier = None
            if variants:
                from assistant.perception.models import trained_models

                verifier = trained_models(plans=plans).verifier
            report["table_3_6"], report["table_3_7"] = classification_tables(train, test, other,
                                                                             classifiers, verifier)
        if "orientation" not in skip:
            progress("Table 3-8: orientation")
            report["table_3_8"] = orientation_table(train, test, other)
    if "scenes" not in skip:
        report["table_3_9"] = scene_table(detector, progress)
    if realdata and "real" not in skip:
        from assistant.perception.realdata import evaluate_realdata

        progress(f"real frames in {realdata}")
        report["realdata"] = evaluate_realdata(realdata, detector)
    report["seconds"] = round(time.perf_counter() - t0, 1)
    return report


def databases(plans=None):
    """(training, held-out study views, other instances) — cached renders."""
    from assistant.perception.database import ViewPlan, cached_database, other_items, study_items
    from assistant.perception.models import TRAINING_PLANS, training_database

    train = training_database(plans or TRAINING_PLANS, variants=False)
    test = cached_database("test", study_items(), ViewPlan(**TEST_PLAN_ARGS))
    other = cached_database("other", other_items(), ViewPlan(**OTHER_PLAN_ARGS))
    return train, test, other


def _per_category(pred: np.ndarray, truth: np.ndarray) -> dict:
    out = {}
    for c in CATEGORY_ORDER:
        m = truth == c
        if m.any():
            out[c] = {"n": int(m.sum()), "accuracy": round(float((pred[m] == c).mean()), 4)}
    out["all"] = {"n": int(len(truth)), "accuracy": round(float((pred == truth).mean()), 4)}
    return out


def classification_tables(train, test, other, methods=DEFAULT_CLASSIFIERS, verifier=None):
    """Tables 3-6 and 3-7: per-category accuracy per classifier (and feature set); with a
    ``verifier`` (the trained models') also the detector's categories: the default GSVM with
    the verifier's say on beds and couches."""
    from assistant.perception.models import classifier_input, fit_models

    t36, t37 = {}, {}
    variants = [(m, "mh+shape") for m in methods] + [("gsvm", "mh")]
    for method, features in variants:
        t = time.perf_counter()
        models = fit_models(train, method, features)
        fit_s = time.perf_counter() - t
        name = f"{method} ({features})"
        for table, db in ((t36, test), (t37, other)):
            t = time.perf_counter()
            pred = models.classifier.predict_category(classifier_input(db))
            table[name] = _per_category(pred, db.category)
            table[name]["fit_seconds"] = round(fit_s, 2)
            table[name]["predict_ms_per_sample"] = round((time.perf_counter() - t) * 1e3 / max(1, len(db)), 3)
        if (method, features) == ("gsvm", "mh+shape") and verifier is not None:
            for table, db in ((t36, test), (t37, other)):
                table["gsvm + verifier (detector)"] = _per_category(
                    verified_categories(models.classifier, verifier, classifier_input(db)), db.category)
    return t36, t37


def verified_categories(classifier, verifier, X: np.ndarray) -> np.ndarray:
    """The detector's category of each row: the classifier's, with the verifier's say on beds
    and couches (``classifiers.verified_category``; "other" counts as wrong)."""
    from assistant.perception.classifiers import verified_category

    main = classifier.predict_category(X)
    checked = verifier.predict_category(X)
    return np.array([verified_category(m, v, x[-2], x[-1]) for m, v, x in zip(main, checked, X)])


def view_subclass(category: str, alpha: float) -> str:
    """The subclass a view belongs to by its true angle α between front and camera:
    front |α| ≤ 60°, back |α| ≥ 120°, side otherwise (chairs and beds: front/back at 90°)."""
    if category not in ("chair", "couch", "bed") or not math.isfinite(alpha):
        return category
    a = abs(math.degrees(alpha))
    if category == "couch":
        return "couch+front" if a <= 60 else "couch+back" if a >= 120 else "couch+side"
    return f"{category}+front" if a <= 90 else f"{category}+back"


def orientation_table(train, test, other) -> dict:
    """Table 3-8: error mean/std (degrees) per subclass; linear (Table 3-3) vs plane estimator.

    Subclass of a view by its true angle (:func:`view_subclass`); the linear estimator uses the
    subclass the classifier predicts (as the detector does). Views with no estimate are counted.
    """
    from assistant.perception.models import classifier_input, fit_models
    from assistant.perception.orientation import angle_error

    models = fit_models(train)
    out = {}
    for name, db in (("study", test), ("other", other)):
        has = np.isfinite(db.facing)
        pred_sub = models.classifier.predict(classifier_input(db))
        lin = models.linear_orientation.predict(db.Q, pred_sub)
        rows = {}
        true_sub = np.array([view_subclass(c, a) for c, a in zip(db.category, db.alpha)])
        plane = np.array([models.plane_orientation.estimate(p, n, s) for (p, n), s
                          in zip(db.points, db.category)])
        for sub in sorted(set(true_sub[has])):
            m = true_sub == sub
            row = {"n": int(m.sum())}
            for est_name, est in (("linear", lin), ("plane", plane)):
                e = np.degrees(angle_error(est[m], db.facing[m]))
                ok = np.isfinite(e)
                row[est_name] = {"mean": round(float(e[ok].mean()), 1) if ok.any() else None,
                                 "std": round(float(e[ok].std()), 1) if ok.any() else None,
                                 "median": round(float(np.median(e[ok])), 1) if ok.any() else None,
                                 "no_estimate": int((~ok).sum())}
            rows[sub] = row
        for cat in ("chair", "couch", "bed"):
            m = db.category == cat
            if m.any():
                e = np.degrees(angle_error(plane[m], db.facing[m]))
                ok = np.isfinite(e)
                rows[f"{cat} (all views)"] = {"n": int(m.sum()), "plane": {
                    "mean": round(float(e[ok].mean()), 1), "std": round(float(e[ok].std()), 1),
                    "median": round(float(np.median(e[ok])), 1), "no_estimate": int((~ok).sum())}}
        out[name] = rows
    return out


def scene_table(detector=None, progress: Progress = no_progress) -> dict:
    """Table 3-9 over the 16 scenes, with summary figures."""
    from assistant.perception.detector import FurnitureDetector
    from assistant.eval.perception_scenes import SCENES, evaluate_scene

    detector = detector or FurnitureDetector()
    rows = []
    for number, (world, ids) in enumerate(SCENES, start=1):
        progress("Table 3-9: scenes", number - 1, len(SCENES))
        row = evaluate_scene(world, ids, detector)
        row["scene"] = number
        rows.append(row)
    pe = [i["position_error_m"] for r in rows for i in r["items"] if "position_error_m" in i]
    oe = [i["orientation_error_rad"] for r in rows for i in r["items"] if "orientation_error_rad" in i]
    found = sum(1 for r in rows for i in r["items"] if i.get("detected") is not None)
    total = sum(len(r["items"]) for r in rows)
    return {"scenes": rows, "summary": {
        "items_found": f"{found}/{total}",
        "position_error_mean_m": round(float(np.mean(pe)), 3) if pe else None,
        "position_error_max_m": round(float(np.max(pe)), 3) if pe else None,
        "orientation_error_mean_rad": round(float(np.mean(oe)), 3) if oe else None,
        "words_right": sum(1 for r in rows for i in r["items"] if i.get("word_right")),
        "sr_match": f"{sum(1 for r in rows if r['sr_match'])}/{len(rows)}"}}

import numpy as np
import pytest
from sklearn.exceptions import NotFittedError

from assistant.perception.classifiers import (
    AutoencoderClassifier,
    FurnitureClassifier,
    category_of,
    view_subclasses,
)


def toy(seed=0, n=30):
    rng = np.random.default_rng(seed)
    X = np.vstack([rng.normal(0, 1, (n, 848)), rng.normal(3, 1, (n, 848))])
    y = np.array(["chair+front"] * n + ["small table"] * n)
    return X, y


def test_subclasses_are_named_by_the_side_seen():
    rng = np.random.default_rng(1)
    X = np.vstack([rng.normal(0, 0.1, (20, 5)), rng.normal(5, 0.1, (20, 5)), rng.normal(0, 1, (10, 5))])
    category = np.array(["chair"] * 40 + ["small table"] * 10)
    alpha = np.concatenate([rng.normal(0, 0.2, 20), rng.normal(np.pi, 0.2, 20), np.full(10, np.nan)])
    sub = view_subclasses(X, category, alpha)
    assert set(sub[:20]) == {"chair+front"} and set(sub[20:40]) == {"chair+back"}
    assert set(sub[40:]) == {"small table"}
    assert category_of("couch+side") == "couch" and category_of("small table") == "small table"


@pytest.mark.parametrize("method", ["lsvm", "gsvm"])
def test_svm_classifiers_follow_the_estimator_contract(method):
    X, y = toy()
    clf = FurnitureClassifier(method)
    with pytest.raises(NotFittedError):
        clf.predict(X)
    assert clf.fit(X, y) is clf
    assert (clf.predict(X) == y).mean() > 0.95
    sub, conf = clf.predict_with_confidence(X[:3])
    assert np.all((conf > 0) & (conf <= 1))
    assert set(clf.predict_category(X)) <= {"chair", "small table"}


def test_autoencoder_pretrains_then_classifies():
    X, y = toy(n=20)
    ae = AutoencoderClassifier(encoder=(32, 16, 8), pretrain_iter=20, finetune_iter=50)
    with pytest.raises(NotFittedError):
        ae.predict(X)
    ae.fit(X, y)
    assert ae.autoencoder_loss_ > 0
    assert (ae.predict(X) == y).mean() > 0.9
    assert ae.predict_proba(X).shape == (40, 2)


def test_feature_choice_is_checked():
    X, y = toy(n=5)
    with pytest.raises(ValueError):
        FurnitureClassifier("gsvm", features="colour").fit(X, y)


@pytest.mark.parametrize("method", ["forest", "vote"])
def test_forest_and_vote_give_probabilities(method):
    X, y = toy(n=15)
    clf = FurnitureClassifier(method).fit(X, y)
    assert (clf.predict(X) == y).mean() > 0.95
    p = clf.scores(X[:4])
    assert p.shape == (4, 2) and np.allclose(p.sum(axis=1), 1.0)


def test_quick_forest_matches_the_threaded_forest():
    from sklearn.ensemble import RandomForestClassifier

    from assistant.perception.classifiers import QuickForest

    X, y = toy(n=15)
    quick = QuickForest(n_estimators=20, random_state=3).fit(X, y)
    plain = RandomForestClassifier(n_estimators=20, random_state=3).fit(X, y)
    assert np.allclose(quick.predict_proba(X[:5]), plain.predict_proba(X[:5]))
    with pytest.raises(NotFittedError):
        QuickForest().predict_proba(X)


def test_unknown_classifier_is_named():
    from assistant.errors import UnknownNameError

    with pytest.raises(UnknownNameError, match="gsvm"):
        FurnitureClassifier("knn").fit(*toy(n=5))


def test_the_verifier_overrules_a_bed_or_couch_only_with_the_side_cue_agreeing():
    from assistant.perception.classifiers import verified_category

    assert verified_category("bed", "large table", solid=0.3, open_=0.42) == "large table"  # knee space
    assert verified_category("couch", "large table", solid=0.5, open_=0.23) == "couch"  # no knee space seen
    assert verified_category("couch", "other", solid=0.9, open_=0.0) == "other"  # a closed box: a bench
    assert verified_category("bed", "other", solid=0.0, open_=1.0) == "bed"  # not closed: keep the bed
    assert verified_category("couch", "small table", solid=0.86, open_=0.07) == "small table"
    assert verified_category("chair", "other", solid=1.0, open_=0.0) == "chair"  # only beds and couches
    assert verified_category("bed", "couch", solid=1.0, open_=0.0) == "bed"


def test_the_gaussian_svms_decision_values_come_from_one_matrix_product_as_scikit_learn_gives_them(
        tiny_models, tiny_database):
    """Issue 20 (speed): ``RBFDecision`` gives the one-vs-rest values of the pipeline's
    ``decision_function`` (to single precision's rounding) from the support vectors in one
    product, with the same classes; the classifier's scores go through it."""
    from assistant.perception.classifiers import RBFDecision
    from assistant.perception.models import classifier_input

    clf = tiny_models.classifier
    X = classifier_input(tiny_database)
    fast = RBFDecision.of(clf.estimator_)
    assert fast is not None
    reference = clf.estimator_.decision_function(X)
    assert np.allclose(fast(X), reference, rtol=0, atol=1e-4)
    assert np.array_equal(clf.classes_[np.argmax(reference, axis=1)], clf.predict_with_confidence(X)[0])
    assert isinstance(clf.__dict__.get("_rbf_decision"), RBFDecision)  # the scores went through it
    assert RBFDecision.of(FurnitureClassifier("lsvm").fit(*toy(n=5)).estimator_) is None
    two = FurnitureClassifier("gsvm").fit(*toy(n=5))
    assert RBFDecision.of(two.estimator_) is None  # two classes: scikit-learn's own values
    import copy

    moved = copy.deepcopy(clf.estimator_)
    del moved.steps[1][1]._gamma  # a scikit-learn without the private gamma: its own values
    assert RBFDecision.of(moved) is None

"""One contract suite, run on both grounders (STYLE.md item 15)."""

from __future__ import annotations

import pickle

import pytest

from assistant.grounding import (
    COMMAND,
    CombinedGrounder,
    FIELDS,
    ChunkGrounding,
    ChunkRecord,
    GrounderNotFittedError,
    LearnedGrounder,
    ScoredGrounder,
)
from assistant.grounding.labels import read_chunk_groundings, with_world

GROUNDERS = [ScoredGrounder, LearnedGrounder, CombinedGrounder]


def record(label: str, content: str) -> ChunkRecord:
    parts = content.split()
    return ChunkRecord(label, tuple(parts[1::2]), tuple(parts[0::2]))


def fitted(cls, commands):
    return cls().fit([r for c in commands for r in c.records], [g for c in commands for g in c.groundings])


@pytest.fixture(params=GROUNDERS, ids=lambda c: c.__name__)
def grounder_cls(request):
    return request.param


def test_ground_before_fit_says_what_to_do(grounder_cls):
    with pytest.raises(GrounderNotFittedError, match="not fitted yet; call fit"):
        grounder_cls().ground([record("IRMRP", "VB turn DIR left")])


def test_fit_returns_self_and_sets_learned_attributes(grounder_cls, small_labels):
    grounder = grounder_cls()
    records = [r for c in small_labels for r in c.records]
    assert grounder.fit(records, [g for c in small_labels for g in c.groundings]) is grounder
    assert grounder.fitted_ and "turn" in grounder.vocabulary_
    assert set(grounder.get_params()) and repr(grounder).startswith(grounder_cls.__name__)


def test_fit_rejects_mismatched_or_empty_input(grounder_cls):
    with pytest.raises(ValueError, match="records but"):
        grounder_cls().fit([record("IRMRP", "VB turn DIR left")], [])
    with pytest.raises(ValueError, match="no chunks"):
        grounder_cls().fit([], [])


def test_training_chunks_ground_to_their_labels(grounder_cls, small_labels):
    grounder = fitted(grounder_cls, small_labels)
    accuracy = grounder.accuracy(small_labels)
    assert set(accuracy) == {*FIELDS, COMMAND}
    assert accuracy[COMMAND] == 1.0


@pytest.mark.parametrize("label, content, expected", [
    # synonyms and paraphrases not in the training chunks
    ("FURRP", "IN in NN front IN of DT the NN sofa", ChunkGrounding(reference="couch", direction="front")),
    ("FURTP", "ON on DT the FUR desk", ChunkGrounding(target="table")),
    ("FURTP", "ON on DT the NN night NN stand", ChunkGrounding(target="table")),
    ("IRMRP", "VB make DT a DIR left", ChunkGrounding(reference="move", direction="left")),
    ("ORMTP", "VB head TO to DT the RM bedroom", ChunkGrounding(room="bedroom")),
])
def test_paraphrases_ground(grounder_cls, small_labels, label, content, expected):
    grounder = fitted(grounder_cls, small_labels)
    assert grounder.ground_one(record(label, content)) == expected


def test_odd_chunks_never_raise(grounder_cls, small_labels):
    grounder = fitted(grounder_cls, small_labels)
    empty = grounder.ground_one(ChunkRecord("IRMRP", (), ()))
    assert empty == ChunkGrounding()
    odd = grounder.ground([record("CONF", "NN blorp NN zzyzx"), record("OBTP", "UH um UH uh"),
                           ChunkRecord("XYZ", ("ok",), ("UH",))])
    assert len(odd) == 3 and all(isinstance(g, ChunkGrounding) for g in odd)
    assert grounder.ground([]) == []


def test_deterministic_and_picklable(grounder_cls, small_labels):
    a, b = fitted(grounder_cls, small_labels), fitted(grounder_cls, small_labels)
    probe = [record("FURRP", "IN by DT the FUR bed"), record("IRMRP", "VB go RB straight")]
    assert a.ground(probe) == b.ground(probe)
    assert pickle.loads(pickle.dumps(a)).ground(probe) == a.ground(probe)


def test_world_picks_the_room_that_direction_means(grounder_cls):
    """"Turn right" into the living room in one home, into the office in another."""
    rows, labels = [], []
    for world, room in (("home-a", "living room"), ("home-b", "office")):
        for content in ("VB turn DIR right", "TO to DT the DIR right", "ON on PRP your DIR right"):
            rows.append(ChunkRecord("ORMRP", *_split(content), world=world))
            labels.append(ChunkGrounding(room=room))
    grounder = grounder_cls().fit(rows, labels)
    probe = _split("VB take DT a DIR right")
    assert grounder.ground_one(ChunkRecord("ORMRP", *probe, world="home-a")).room == "living room"
    assert grounder.ground_one(ChunkRecord("ORMRP", *probe, world="home-b")).room == "office"


def _split(content: str):
    parts = content.split()
    return tuple(parts[1::2]), tuple(parts[0::2])


# --- on the real data -----------------------------------------------------------------------
@pytest.fixture(scope="module")
def corpus_grounders(corpus_labels):
    return {cls: cls().fit(corpus_labels.records, corpus_labels.groundings) for cls in GROUNDERS}


#: compositions the nearest-template scorer gets wrong (docs/grounding.md, "scored grounder")
SCORED_MISSES = {
    ("FURRP", "TO to DT the DIR left IN of DT the NN sofa"):
        "nearest template is another reference's 'to the left of' phrase",
    ("FURRP", "IN behind DT the FUR bed"):
        "P(beside | FURRP) outweighs the closer 'behind the couch' template",
}


@pytest.mark.parametrize("label, content, expected", [
    ("FURRP", "TO to DT the DIR left IN of DT the NN sofa", ChunkGrounding(reference="couch", direction="left")),
    ("FURRP", "IN behind DT the FUR bed", ChunkGrounding(reference="bed", direction="back")),
    ("FURTP", "ON on DT the NN night NN stand", ChunkGrounding(target="table")),
    ("IRMRP", "VB make DT a DIR right", ChunkGrounding(reference="move", direction="right")),
    ("IRMRP", "VB head RB forward", ChunkGrounding(reference="move", direction="front")),
    ("OBTP", "DT the NN mug VBZ is", ChunkGrounding(object="mug")),
])
def test_corpus_trained_grounders_compose(grounder_cls, corpus_grounders, label, content, expected, request):
    got = corpus_grounders[grounder_cls].ground_one(record(label, content))
    if got != expected and grounder_cls is ScoredGrounder and (label, content) in SCORED_MISSES:
        # a known miss of the nearest-template scorer; which corpus wordings fix it changes with
        # the corpus, so getting it right is welcome, not a failure
        pytest.xfail(SCORED_MISSES[(label, content)])
    assert got == expected


def test_corpus_trained_grounder_on_csisl_templates(grounder_cls, corpus_grounders, shared_dir):
    """Trained on our corpus only, tested on the CSISL template chunk labels."""
    test = read_chunk_groundings(shared_dir / "realdata/csisl/csisl_templates149_chunk_groundings.csv")
    commands = [with_world(c, "apartment") for c in test.commands]
    accuracy = corpus_grounders[grounder_cls].accuracy(commands)
    if grounder_cls is not ScoredGrounder:  # the default (combined) and the learned one meet the targets
        assert accuracy[COMMAND] >= 0.95
        assert min(accuracy[f] for f in FIELDS) >= 0.98
    else:  # the dissertation's scorer is measured, not required to reach them
        assert accuracy[COMMAND] >= 0.70
        assert min(accuracy[f] for f in FIELDS) >= 0.95


def test_learned_fast_prediction_equals_scikit_learn_predict(small_labels):
    from assistant.grounding.base import normalise
    from assistant.grounding.learned import _predict

    grounder = fitted(LearnedGrounder, small_labels)
    chunks = [normalise(r) for c in small_labels for r in c.records] + [normalise(record("IRMRP", "VB go DIR left"))]
    X = grounder._features(chunks)
    for estimator in grounder.estimators_.values():
        assert _predict(estimator, X) == list(estimator.predict(X))


def test_params_follow_the_estimator_convention(grounder_cls):
    grounder = grounder_cls()
    params = grounder.get_params()
    assert grounder.set_params(**params) is grounder and grounder.get_params() == params
    with pytest.raises(ValueError, match="unknown parameter"):
        grounder.set_params(nonsense=1)


def test_learned_grounder_model_choice(small_labels):
    mlp = LearnedGrounder(model="mlp", hidden=32)
    records = [r for c in small_labels for r in c.records]
    mlp.fit(records, [g for c in small_labels for g in c.groundings])
    assert mlp.accuracy(small_labels)[COMMAND] == 1.0
    with pytest.raises(ValueError, match="unknown model 'svm'; known: logistic, mlp"):
        LearnedGrounder(model="svm").fit(records, [g for c in small_labels for g in c.groundings])

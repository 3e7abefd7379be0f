import pytest
from assistant.errors import NotFittedError

from assistant.language.postag import SemanticPosTagger, load_lexicon

TRAIN = [
    [("go", "VB"), ("to", "TO"), ("the", "DT"), ("table", "FUR")],
    [("the", "DT"), ("mug", "NN"), ("is", "VBZ"), ("on", "ON"), ("the", "DT"), ("table", "FUR")],
    [("turn", "VB"), ("left", "DIR"), ("and", "CC"), ("walk", "VB"), ("into", "IN"), ("the", "DT"),
     ("bedroom", "RM")],
    [("uh", "IGN"), ("the", "DT"), ("keys", "NNS"), ("are", "VBP"), ("on", "ON"), ("the", "DT"),
     ("couch", "FUR")],
] * 3


@pytest.fixture(scope="module")
def tagger():
    return SemanticPosTagger(max_rules=20).fit(TRAIN)


def test_tags_training_words_and_scores_with_the_nltk_interface(tagger):
    assert tagger.tag(["the", "mug", "is", "on", "the", "couch"]) == [
        ("the", "DT"), ("mug", "NN"), ("is", "VBZ"), ("on", "ON"), ("the", "DT"), ("couch", "FUR")]
    assert tagger.accuracy(TRAIN) == 1.0


def test_typos_are_resolved_against_the_vocabulary(tagger):
    tags, corrections, unknown = tagger.analyse(["go", "to", "the", "tabel", "in", "the", "bedrom"])
    assert corrections == {"tabel": "table", "bedrom": "bedroom"}
    assert tags[3] == "FUR" and tags[6] == "RM"
    assert unknown == []


def test_unknown_words_are_tagged_and_reported_not_dropped(tagger):
    tags, corrections, unknown = tagger.analyse(["the", "zorblax", "is", "running", "42"])
    assert len(tags) == 5 and tags[4] == "CD" and tags[3] == "VBG"
    assert unknown == ["zorblax", "running"] and corrections == {}


def test_lexicon_covers_words_the_corpus_never_showed(tagger):
    # not in TRAIN: the domain lexicon and closed classes tag them
    assert dict(tagger.tag(["sofa", "kitchen", "his", "doorway"])) == {
        "sofa": "FUR", "kitchen": "RM", "his": "PRP", "doorway": "STR"}
    assert load_lexicon()["on"] == "ON"


def test_inflections_and_other_first_letters_are_not_corrected(tagger):
    assert tagger.resolve("walks") is None  # an inflection of "walk"
    assert tagger.resolve("light") is None  # "right" starts with another letter
    assert tagger.resolve("keyz") is None  # short words only towards domain words


def test_empty_and_untrained():
    with pytest.raises(NotFittedError):
        SemanticPosTagger().tag(["go"])
    with pytest.raises(ValueError, match="no tagged sentences"):
        SemanticPosTagger().fit([])


def test_training_is_deterministic():
    a = SemanticPosTagger(max_rules=20).fit(TRAIN)
    b = SemanticPosTagger(max_rules=20).fit(TRAIN)
    assert a.rules == b.rules

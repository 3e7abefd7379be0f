"""The generation model: what it learns from a corpus, deterministically."""

from __future__ import annotations

import pickle

import pytest

from assistant.generation.model import (GenerationModel, GenerationModelNotFittedError,
                                        load_generation_model, template_from_chunk)


def test_template_slots_replace_object_furniture_and_room_words():
    t = template_from_chunk("furniture-front", ("in", "front", "of", "the", "sofa"),
                            ("IN", "DIR", "IN", "DT", "FUR"))
    assert [w for w, _ in t] == ["in", "front", "of", "the", "{ref}"]
    t = template_from_chunk("room", ("in", "the", "living", "room"), ("IN", "DT", "NN", "RM"))
    assert [w for w, _ in t] == ["in", "the", "{room}"]
    t = template_from_chunk("object", ("the", "glasses", "case", "is"), ("DT", "NNS", "NN", "VBZ"),
                            "glasses case")
    assert [w for w, _ in t] == ["the", "{object}", "is"]
    # a support chunk that names no furniture cannot be generalised
    assert template_from_chunk("support", ("over", "there"), ("IN", "RB")) is None


def test_fit_counts_texts_cooccurrence_and_relations(tiny_corpus):
    model = load_generation_model(tiny_corpus, use_cache=False)
    texts = {k: [" ".join(w for w, _ in t) for _, _, t in model.texts(k)] for k in model.templates_}
    assert texts["furniture-front"] == ["in front of the {ref}"]
    assert texts["wall-left"] == ["against the left wall"]
    assert texts["enter"] == ["go into the {room}"]
    assert "in the {room}" in texts["room"]
    # room and support appear together in both static descriptions
    assert model.cooccurrence("room", "support") == pytest.approx(1.0)
    # couch-front and wall-left never appear together
    assert model.cooccurrence("furniture-front", "wall-left") == 0.0
    # FURRP nests after the words of FURTP in the static tree; ORMTP follows OBTP's words
    assert model.relation("FURRP", "FURTP", "static")[0] == "CR"
    assert model.relation("FURTP", "FURRP", "static")[0] == "PR"
    assert model.relation("ORMTP", "OBTP", "static")[0] == "CR"
    # in the dynamic description the route comes first, as neighbours
    assert model.relation("ORMTP", "OBTP", "dynamic")[0] == "NL"


def test_fit_is_deterministic_and_cached(tiny_corpus, tmp_path, monkeypatch):
    monkeypatch.setenv("ASSISTANT_CACHE", str(tmp_path / "cache"))
    a = load_generation_model(tiny_corpus, use_cache=False)
    b = load_generation_model(tiny_corpus, use_cache=False)
    assert pickle.dumps(a.templates_) == pickle.dumps(b.templates_)
    assert a.pair_counts_ == b.pair_counts_
    assert not list((tmp_path / "cache").glob("generation-*.pkl"))  # use_cache=False writes nothing
    c = load_generation_model(tiny_corpus)          # writes the cache
    assert len(list((tmp_path / "cache").glob("generation-*.pkl"))) == 1

    def refit(self, *args, **kwargs):
        raise AssertionError("fitted again instead of reading the cache")

    monkeypatch.setattr(GenerationModel, "fit", refit)
    d = load_generation_model(tiny_corpus)          # reads it (fitting would raise)
    assert d is not c and d.templates_ == c.templates_ and d.pair_counts_ == c.pair_counts_


def test_unfitted_model_says_so():
    with pytest.raises(GenerationModelNotFittedError):
        GenerationModel().texts("room")


def test_repository_corpus_teaches_the_common_phrasings(generation_model):
    best = lambda key: " ".join(w for w, _ in generation_model.texts(key)[0][2])  # noqa: E731
    assert best("furniture-front") == "in front of the {ref}"
    assert best("room") == "in the {room}"
    assert generation_model.relation("FURRP", "FURTP", "static")[0] == "CR"

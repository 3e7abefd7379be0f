"""The repository corpus has the constructions real speakers use (short commands, several
object sentences, a named addressee) and the chunker trained on it reads them."""

from collections import Counter

import pytest

from assistant.language.consistency import conventions
from assistant.language.corpus import default_corpus_paths, read_corpora


@pytest.fixture(scope="module")
def corpus():
    import os

    os.environ.pop("ASSISTANT_CORPUS", None)
    paths = default_corpus_paths()
    if not paths:
        pytest.skip("the repository's corpus/*.xml is empty")
    return read_corpora(paths).descriptions


def test_corpus_has_descriptions_without_and_with_several_object_phrases(corpus):
    trees = [d.tree for d in corpus]
    per = conventions(trees)["object phrases per description"]
    n = len(trees)
    assert per.get("0", 0) / n >= 0.08          # route only, route + furniture, room + furniture
    assert (per.get("2", 0) + per.get("3+", 0)) / n >= 0.04   # "[OBTP it's in the room …] … [OBTP it's on the table]"
    kinds = Counter(d.attributes.get("kind") for d in corpus)
    assert kinds["partial"] > 0 and kinds["twostep"] > 0


def test_corpus_says_the_addressee_by_name_and_in_the_third_person(corpus):
    words = Counter((w, p) for d in corpus for w, p in zip(d.tree.words, d.tree.pos_tags))
    assert words[("brian", "WHO")] >= 20 and words[("robot", "WHO")] >= 20
    assert words[("he", "PRP")] > 0


def test_leading_motion_follows_the_majority_of_real_speech(corpus):
    """Real CSISL puts a description's leading "go forward (and)" inside the room phrase more
    often than outside (≈55 % vs 41 %); so do we (and the templates, always)."""
    c = conventions([d.tree for d in corpus])["leading motion verb: outermost label"]
    assert c["ORMTP"] > c["O"] > 0


def test_short_commands_are_not_read_as_object_phrases(small_model):
    """The room is a room phrase, with or without the verb (real CSISL splits evenly on
    that), and nothing is an object phrase. (A model trained on the 150-description cut of
    the corpus: the full one reads more.)"""
    for text in ("go to the bedroom", "go into the living room"):
        a = small_model.analyse(text)
        assert not any(label.startswith("OBTP") for label in a.chunk_labels), a.tree.bracketed()
        assert a.chunk_labels[-1] == "ORMTP" and a.chunk_labels[-2] == "ORMTP", a.tree.bracketed()

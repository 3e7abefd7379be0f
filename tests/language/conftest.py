"""A small training corpus cut from the repository's corpus, so the language tests train in
seconds (the full corpus is trained by `assistant eval tagging` and the benchmark)."""

import pytest

from assistant.language.corpus import default_corpus_paths, read_corpora, write_corpus


@pytest.fixture(scope="session")
def small_corpus(tmp_path_factory):
    import os

    os.environ.pop("ASSISTANT_CORPUS", None)
    paths = default_corpus_paths()
    if not paths:
        pytest.skip("the repository's corpus/*.xml is empty")
    descriptions = read_corpora(paths).descriptions
    if len(descriptions) < 50:
        pytest.skip("the repository's corpus has fewer than 50 descriptions")
    step = max(1, len(descriptions) // 150)  # every k-th: all families of the corpus
    chosen = descriptions[::step][:150]
    return write_corpus(chosen, tmp_path_factory.mktemp("corpus") / "small.xml")


@pytest.fixture(scope="session")
def small_model(small_corpus):
    from assistant.language.pipeline import LanguageModel

    return LanguageModel.load([small_corpus])


@pytest.fixture(scope="session")
def tiny_corpus(small_corpus, tmp_path_factory):
    """60 descriptions: enough for the evaluation command's plumbing, trained in a second."""
    from assistant.language.corpus import read_corpus

    descriptions = read_corpus(small_corpus).descriptions[::2][:60]
    return write_corpus(descriptions, tmp_path_factory.mktemp("tiny") / "tiny.xml")

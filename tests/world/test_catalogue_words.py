"""The word tables live in catalogue.yaml: loaded, validated, read by every layer."""

import pytest

from assistant.errors import DataFileError
from assistant.world import load_catalogue
from assistant.world.catalogue import parse_words


def test_furniture_words_name_catalogue_categories():
    catalogue = load_catalogue()
    assert catalogue.categories_of("Desk") == ("large table",)
    assert catalogue.categories_of("table") == ("small table", "large table")
    assert catalogue.suggested_category("end table") == "small table"
    assert catalogue.suggested_category("table") is None
    assert catalogue.categories_of("wallet") == ()


def test_grounding_vocabulary_reads_the_catalogue():
    from assistant.grounding.vocabulary import FURNITURE_WORDS, PHRASES, SYNONYMS

    words = load_catalogue().words
    assert SYNONYMS is words.synonyms and PHRASES is words.phrases
    assert FURNITURE_WORDS["nightstand"] == "table" and FURNITURE_WORDS["couch"] == "couch"
    assert PHRASES[("night", "stand")] == "nightstand"


@pytest.mark.parametrize("bad, key", [
    ({"furniture": {"desk": ["big table"]}}, "words.furniture.desk"),
    ({"furniture": {}, "phrases": {"one": "x"}}, "words.phrases.one"),
    ({"furniture": {}, "phrases": {}, "sizes": {"small": "tiny table"}}, "words.sizes.small"),
    ("not a mapping", "words"),
])
def test_a_broken_word_table_names_its_key(bad, key):
    if isinstance(bad, dict):
        bad = {"furniture": {}, "phrases": {}, "sizes": {}, "support_names": {}, "synonyms": {},
               "descriptors": {}, **bad}
    with pytest.raises(DataFileError, match=key.replace(".", r"\.")):
        parse_words(bad, "catalogue.yaml")

"""The object words' small grammar: the indefinite article."""

import pytest

from assistant.grounding.objects import article


@pytest.mark.parametrize("word, said", [("envelope", "an"), ("mug", "a"), ("unicorn", "a"), ("umbrella", "an"),
                                        ("usb stick", "a"), ("hour", "an"), ("hat", "a"), ("one", "a")])
def test_the_indefinite_article_follows_the_sound(word, said):
    assert article(word) == said

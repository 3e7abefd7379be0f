from assistant.language.tokenize import tokenize


def test_lowercase_punctuation_and_contractions_split_as_the_corpus_writes_them():
    assert tokenize("You'll find it, it's on the TABLE!") == [
        "you", "'ll", "find", "it", "it", "'s", "on", "the", "table"]
    assert tokenize("can't won't don't I'm they're I've I'd") == [
        "ca", "n't", "wo", "n't", "do", "n't", "i", "'m", "they", "'re", "i", "'ve", "i", "'d"]
    assert tokenize("you're gonna see it") == ["you", "'re", "gon", "na", "see", "it"]


def test_numbers_hyphens_and_curly_apostrophes_are_kept():
    assert tokenize("turn 90 degrees, walk 2.5 metres") == ["turn", "90", "degrees", "walk", "2.5", "metres"]
    assert tokenize("make a u-turn, forty-five degrees") == ["make", "a", "u-turn", "forty-five", "degrees"]
    assert tokenize("it\u2019s there") == ["it", "'s", "there"]


def test_already_split_clitics_stay_as_they_are():
    assert tokenize("you 'll find it 's there") == ["you", "'ll", "find", "it", "'s", "there"]


def test_odd_input():
    assert tokenize("") == []
    assert tokenize("   ...!!! ,,, ") == []
    assert tokenize("ça va, très bien ☃ 45°") == ["ça", "va", "très", "bien", "45"]
    assert tokenize("'quoted' words'") == ["quoted", "words"]

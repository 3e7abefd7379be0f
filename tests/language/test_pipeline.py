import json
import os
import time

from assistant.fileio import cache_dir
from assistant.language.pipeline import Analysis, LanguageModel, corpus_key


def test_analyse_gives_tokens_tags_labels_and_a_tree(small_model):
    a = small_model.analyse("Go to the bedroom, the mug is on the table.")
    assert isinstance(a, Analysis)
    assert a.tokens == ["go", "to", "the", "bedroom", "the", "mug", "is", "on", "the", "table"]
    assert len(a.pos) == len(a.chunk_labels) == len(a.tokens)
    assert a.pos[3] == "RM" and a.pos[-1] == "FUR"
    assert a.tree.words == a.tokens and a.tree.nested_labels() == a.chunk_labels
    assert a.chunk_labels[-1].startswith("OBTP") and "FURTP" in a.chunk_labels[-1]
    d = json.loads(json.dumps(a.to_dict()))
    assert {"tokens", "pos", "chunk_labels", "tree", "bracketed", "unknown", "corrections"} <= set(d)
    assert d["bracketed"] == a.tree.bracketed()


def test_bad_input_never_fails(small_model):
    empty = small_model.analyse("")
    assert empty.tokens == [] and empty.chunk_labels == [] and empty.tree.items == []
    assert small_model.analyse("   ?!  ").tokens == []
    fillers = small_model.analyse("um uh okay")
    assert fillers.pos == ["IGN", "IGN", "IGN"] and fillers.unknown == []
    odd = small_model.analyse("geh zum Tisch ☃ très")
    assert odd.tokens == ["geh", "zum", "tisch", "très"] and len(odd.pos) == 4
    assert "très" in odd.unknown
    ramble = " ".join(["go forward and then turn left and the mug is on the table"] * 42)[:3000]
    started = time.perf_counter()
    long = small_model.analyse(ramble)
    assert len(long.tokens) >= 500 and len(long.chunk_labels) == len(long.tokens)
    assert time.perf_counter() - started < 5


def test_typos_are_corrected_and_reported(small_model):
    a = small_model.analyse("the mug is on the tabel in the bedrom")
    assert a.corrections == {"tabel": "table", "bedrom": "bedroom"}
    assert a.tokens[5] == "tabel" and a.pos[5] == "FUR"


def test_model_is_cached_by_corpus_content_and_retrained_when_it_changes(small_corpus, small_model, tmp_path):
    key = corpus_key([small_corpus])
    cached = cache_dir() / f"language-{key}.pickle"
    assert cached.exists()
    started = time.perf_counter()
    again = LanguageModel.load([small_corpus])
    assert time.perf_counter() - started < 2
    text = "turn left and the keys are on the couch"
    assert again.analyse(text).to_dict() == small_model.analyse(text).to_dict()
    changed = tmp_path / "changed.xml"
    changed.write_bytes(small_corpus.read_bytes().replace(b"</ALL>", b"<!-- edit --></ALL>"))
    assert corpus_key([changed]) != key


def test_a_truncated_cache_is_retrained(small_corpus, small_model):
    cached = cache_dir() / f"language-{corpus_key([small_corpus])}.pickle"
    data = cached.read_bytes()
    cached.write_bytes(data[: len(data) // 3])
    model = LanguageModel.load([small_corpus])
    assert model.analyse("go left").tokens == ["go", "left"]
    assert cached.stat().st_size == len(data)  # written again, whole


def test_no_corpus_is_a_clear_error(tmp_path, monkeypatch):
    import pytest

    from assistant.errors import AssistantError

    monkeypatch.setenv("ASSISTANT_CORPUS", str(tmp_path))  # an empty folder
    with pytest.raises(AssistantError, match="corpus"):
        LanguageModel.load()
    (tmp_path / "bad.xml").write_text("<ALL><S></S>", encoding="utf-8")
    with pytest.raises(AssistantError, match="no readable descriptions"):
        LanguageModel.load()
    assert os.environ["ASSISTANT_CORPUS"] == str(tmp_path)

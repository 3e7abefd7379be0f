"""Training from label files, the grounder cache, and corpus path handling."""

from __future__ import annotations

import pytest

from assistant.errors import AssistantError, UnknownNameError
from assistant.grounding import ChunkRecord, CombinedGrounder, LearnedGrounder, ScoredGrounder, train_grounder
from assistant.grounding.training import make_grounder, split_corpus_paths

HEADER = "CMD#,Chunk Name,Chunk Content,target room,target object,reference,direction,target\n"
ROWS = ("1,IRMRP,VB turn DIR left,N/A,N/A,move,left,N/A\n"
        "1,OBTP,DT the NN mug VBZ is,N/A,mug,N/A,N/A,N/A\n"
        "2,IRMRP,VB turn DIR right,N/A,N/A,move,right,N/A\n"
        "2,FURTP,ON on DT the FUR table,N/A,N/A,N/A,N/A,table\n")


@pytest.fixture
def corpus_dir(tmp_path, monkeypatch):
    monkeypatch.setenv("ASSISTANT_CACHE", str(tmp_path / "cache"))
    folder = tmp_path / "corpus"
    folder.mkdir()
    (folder / "labels.csv").write_text(HEADER + ROWS, encoding="utf-8")
    return folder


@pytest.mark.parametrize("name, cls", [("scored", ScoredGrounder), ("learned", LearnedGrounder),
                                       ("combined", CombinedGrounder)])
def test_trained_grounders_are_cached_by_content(corpus_dir, tmp_path, monkeypatch, name, cls):
    first = train_grounder(name, [corpus_dir])
    assert isinstance(first, cls) and first.training_files_ == [str(corpus_dir / "labels.csv")]
    cached = list((tmp_path / "cache").glob(f"grounder-{name}-*.pickle"))
    assert len(cached) == 1
    monkeypatch.setattr(cls, "fit", _no_training)
    again = train_grounder(name, [corpus_dir])  # loaded from the cache: an equal, separate object
    probe = [ChunkRecord("IRMRP", ("turn", "left"), ("VB", "DIR"))]
    assert again is not first and again.ground(probe) == first.ground(probe)
    # a changed file is a new key: retrained, a second cache entry
    monkeypatch.undo()
    monkeypatch.setenv("ASSISTANT_CACHE", str(tmp_path / "cache"))
    (corpus_dir / "labels.csv").write_text(HEADER + ROWS + "3,IRMRP,VB go RB forward,N/A,N/A,move,front,N/A\n",
                                           encoding="utf-8")
    train_grounder(name, [corpus_dir])
    assert len(list((tmp_path / "cache").glob(f"grounder-{name}-*.pickle"))) == 2


def _no_training(self, *args, **kwargs):
    raise AssertionError("should have been loaded from the cache")


def test_a_stale_cache_file_is_retrained(corpus_dir, tmp_path):
    train_grounder("learned", [corpus_dir])
    (cache_file,) = (tmp_path / "cache").glob("grounder-learned-*.pickle")
    cache_file.write_bytes(b"not a pickle")
    assert isinstance(train_grounder("learned", [corpus_dir]), LearnedGrounder)


def test_corpus_paths_are_split_and_checked(corpus_dir, tmp_path):
    (corpus_dir / "descriptions.xml").write_text("<ALL></ALL>", encoding="utf-8")
    csvs, xmls = split_corpus_paths([corpus_dir])
    assert [p.name for p in csvs] == ["labels.csv"] and [p.name for p in xmls] == ["descriptions.xml"]
    with pytest.raises(AssistantError, match="does not exist"):
        split_corpus_paths([tmp_path / "nothing.csv"])
    other = tmp_path / "notes.txt"
    other.write_text("x", encoding="utf-8")
    with pytest.raises(AssistantError, match="neither .csv"):
        split_corpus_paths([other])
    empty = tmp_path / "empty"
    empty.mkdir()
    with pytest.raises(AssistantError, match="no chunk-grounding labels"):
        train_grounder("scored", [empty])


def test_unknown_grounder_names_the_known_ones():
    with pytest.raises(UnknownNameError, match="known: combined, learned, scored"):
        make_grounder("lstm")

import pytest

from assistant.errors import AssistantError
from assistant.language.corpus import (Description, default_corpus_paths, parse_corpus_text,
                                       read_corpora, read_corpus, repo_root, write_corpus)

GOOD = """<?xml version="1.0" encoding="utf-8"?>
<ALL>
  <S id="a1">
    <OBTP>
      <DT>the</DT>
      <NN>mug</NN>
      <VBZ>is</VBZ>
      <FURTP>
        <ON>on</ON>
        <DT>the</DT>
        <FUR> Table </FUR>
      </FURTP>
    </OBTP>
  </S>
  <S>
    <ORMTP><VB>go</VB><TO>to</TO><DT>the</DT><RM>bedroom</RM></ORMTP>
  </S>
</ALL>
"""


def test_reads_a_good_file_with_bom_and_crlf(tmp_path):
    path = tmp_path / "c.xml"
    path.write_bytes(b"\xef\xbb\xbf" + GOOD.replace("\n", "\r\n").encode())
    result = read_corpus(path)
    assert result.problems == []
    first, second = result.descriptions
    assert first.number == 1 and first.attributes == {"id": "a1"} and first.source == str(path)
    assert first.tree.bracketed() == "[OBTP the mug is [FURTP on the table]]"
    assert first.tree.nested_labels()[-1] == "OBTP-FURTP"
    assert second.number == 2 and second.tree.pos_tags == ["VB", "TO", "DT", "RM"]


def test_empty_elements_punctuation_and_misspelt_tags_are_reported_not_fatal():
    text = GOOD.replace("<NN>mug</NN>", "<NN></NN><NNN>mug</NNN><COMMA>,</COMMA>").replace(
        "<FURTP>", "<FURPT>").replace("</FURTP>", "</FURPT>").replace("<DT>the</DT>\n      <NN>", "<DT>the</DT><DT/>\n      <NN>")
    result = parse_corpus_text(text, "x.xml")
    assert len(result.descriptions) == 2
    tree = result.descriptions[0].tree
    assert tree.bracketed() == "[OBTP the mug is [FURTP on the table]]"
    assert tree.pos_tags[1] == "NN"
    joined = "\n".join(result.problems)
    assert "x.xml: description 1: empty element <NN>" in joined
    assert "unknown tag <NNN> for 'mug', read as NN" in joined
    assert "unknown chunk tag <FURPT>, read as FURTP" in joined
    assert "punctuation ','" in joined


def test_unknown_chunk_tag_far_from_every_label_keeps_its_words():
    text = "<ALL><S><BANANA><VB>go</VB><DIR>left</DIR></BANANA></S></ALL>"
    result = parse_corpus_text(text, "y.xml")
    assert result.descriptions[0].tree.bracketed() == "go left"
    assert "unknown chunk tag <BANANA>" in result.problems[0]


def test_broken_xml_recovers_the_other_descriptions(tmp_path):
    broken = GOOD.replace("<NN>mug</NN>", "<NN>mug</VB>")  # description 1 is not well-formed
    broken += "<S><IRMRP><VB>turn</VB><DIR>left</DIR></IRMRP"  # and the file ends mid-tag
    path = tmp_path / "broken.xml"
    path.write_text(broken, encoding="utf-8")
    result = read_corpus(path)
    assert any("broken XML" in p and str(path) in p and "line" in p for p in result.problems)
    texts = [d.tree.text for d in result.descriptions]
    assert "go to the bedroom" in texts  # description 2 is untouched
    assert [d.number for d in result.descriptions][:2] == [1, 2]
    assert result.descriptions[0].tree.words[:2] == ["the", "mug"]  # read tolerantly
    assert any("description 1" in p for p in result.problems)


def test_a_description_without_words_is_skipped_and_reported():
    result = parse_corpus_text("<ALL><S><OBTP></OBTP></S><S><VB>go</VB></S></ALL>", "z.xml")
    assert [d.number for d in result.descriptions] == [2]
    assert any("description 1" in p for p in result.problems)


def test_missing_file_is_a_clear_error(tmp_path):
    with pytest.raises(AssistantError, match="cannot read corpus file"):
        read_corpus(tmp_path / "nope.xml")


def test_write_then_read_gives_the_same_trees(tmp_path):
    original = parse_corpus_text(GOOD, "g.xml").descriptions
    path = write_corpus(original, tmp_path / "out.xml")
    again = read_corpus(path)
    assert again.problems == []
    assert [d.tree.bracketed() for d in again.descriptions] == [d.tree.bracketed() for d in original]
    assert [d.tree.pos_tags for d in again.descriptions] == [d.tree.pos_tags for d in original]
    assert again.descriptions[0].attributes == {"id": "a1"}


def test_default_corpus_paths_are_the_repo_corpus_or_the_environment(tmp_path, monkeypatch):
    monkeypatch.delenv("ASSISTANT_CORPUS", raising=False)
    assert all(p.parent == repo_root() / "corpus" and p.suffix == ".xml" for p in default_corpus_paths())
    (tmp_path / "a.xml").write_text(GOOD, encoding="utf-8")
    monkeypatch.setenv("ASSISTANT_CORPUS", str(tmp_path))
    assert default_corpus_paths() == [tmp_path / "a.xml"]
    assert len(read_corpora(default_corpus_paths()).descriptions) == 2
    assert isinstance(read_corpora([tmp_path]).descriptions[0], Description)


def test_reads_the_real_csisl_files(shared_dir):
    folder = shared_dir / "realdata" / "csisl"
    real = read_corpus(folder / "csisl_real_descriptions_annotated.xml")
    templates = read_corpus(folder / "csisl_templates149_annotated.xml")
    assert len(real.descriptions) == 1063 and len(templates.descriptions) == 149
    assert templates.problems == []
    assert any("<OBPT>" in p for p in real.problems)
    assert any("empty element <VBP>" in p for p in real.problems)

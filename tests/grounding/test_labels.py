"""Reading chunk-grounding files: the CSISL CSV format, problems reported, trees attached."""

from __future__ import annotations

import pytest

from assistant.errors import DataFileError
from assistant.grounding import ChunkGrounding, parse_content, read_chunk_groundings
from assistant.grounding.labels import attach_structure, records_from_tree, with_world
from assistant.grounding.vocabulary import canonical_tokens, canonical_value
from assistant.language.tree import Chunk, ChunkTree, Token

HEADER = "CMD#,Chunk Name,Chunk Content,target room,target object,reference,direction,target\n"


def write(tmp_path, text: str):
    path = tmp_path / "labels.csv"
    path.write_text(text, encoding="utf-8")
    return path


def test_reads_rows_grouped_by_command_with_canonical_values(tmp_path):
    path = write(tmp_path, HEADER
                 + "1,ORMRP,VB turn DIR right,Living Room,N/A,N/A,N/A,N/A\n"
                 + "1,FURTP,ON on DT the FUR nightstand,N/A,N/A,N/A,N/A,nightstand\n"
                 + "2,FURRP,IN behind DT the NN sofa,,,sofa,back,\n")
    labels = read_chunk_groundings(path)
    assert [c.number for c in labels.commands] == ["1", "2"] and not labels.problems
    first = labels.commands[0]
    assert first.records[0].words == ("turn", "right") and first.records[0].pos == ("VB", "DIR")
    assert first.groundings == (ChunkGrounding(room="living room"), ChunkGrounding(target="table"))
    assert labels.commands[1].groundings[0] == ChunkGrounding(reference="couch", direction="back")
    assert len(labels.records) == len(labels.groundings) == 3


def test_bad_rows_are_reported_and_skipped(tmp_path):
    path = write(tmp_path, HEADER + "1,IRMRP,VB turn DIR,N/A,N/A,move,left,N/A\n"
                 + ",IRMRP,VB turn DIR left,N/A,N/A,move,left,N/A\n"
                 + "2,,VB turn DIR left,N/A,N/A,move,left,N/A\n"
                 + "3,IRMRP,VB turn DIR left,N/A,N/A,move,left,N/A\n")
    labels = read_chunk_groundings(path)
    assert [c.number for c in labels.commands] == ["3"]
    assert len(labels.problems) == 3 and "row 2: chunk content must alternate TAG word" in labels.problems[0]


def test_a_file_without_the_header_names_the_missing_columns(tmp_path):
    path = write(tmp_path, "CMD#,Chunk Name\n1,IRMRP\n")
    with pytest.raises(DataFileError, match="labels.csv: header: missing column"):
        read_chunk_groundings(path)
    with pytest.raises(DataFileError, match="cannot read"):
        read_chunk_groundings(tmp_path / "absent.csv")


def test_content_parsing():
    assert parse_content("DT the FUR table") == (("the", "table"), ("DT", "FUR"))
    assert parse_content("") == ((), ())
    with pytest.raises(ValueError):
        parse_content("DT the FUR")


def test_tree_structure_and_world_attach_in_pre_order(tmp_path):
    tree = ChunkTree([Chunk("OBTP", [Token("the", "DT"), Token("mug", "NN"),
                                     Chunk("FURTP", [Token("on", "ON"), Token("the", "DT"), Token("table", "FUR")])])])
    records = records_from_tree(tree, "apartment")
    assert [(r.label, r.parent, r.children, r.world) for r in records] == [
        ("OBTP", "S", ("FURTP",), "apartment"), ("FURTP", "OBTP", (), "apartment")]
    path = write(tmp_path, HEADER + "1,OBTP,DT the NN mug,N/A,mug,N/A,N/A,N/A\n"
                 + "1,FURTP,ON on DT the FUR table,N/A,N/A,N/A,N/A,table\n")
    command = read_chunk_groundings(path).commands[0]
    attached = attach_structure(command, tree, "apartment")
    assert attached.records[1].parent == "OBTP" and attached.records[0].world == "apartment"
    other = ChunkTree([Chunk("IRMRP", [Token("turn", "VB")])])
    assert attach_structure(command, other) is command  # labels differ: unchanged
    assert with_world(command, "hk-studio").records[0].world == "hk-studio"


def test_canonical_words_and_values():
    assert canonical_tokens(["Sofa"], ["NN"]) == (["couch"], ["NN"])
    assert canonical_tokens(["the", "night", "stand"], ["DT", "NN", "NN"]) == (["the", "nightstand"], ["DT", "FUR"])
    assert canonical_tokens(["head", "to"], ["VB", "TO"])[0] == ["go", "to"]
    assert canonical_value("target", "desk") == "table" and canonical_value("reference", "sofa") == "couch"
    assert canonical_value("direction", "centre") == "center" and canonical_value("target", None) is None

"""``relations()`` on the study homes and the ``assistant relations`` command."""

import json

import pytest

from assistant.cli import main
from assistant.spatial import DIR_LABELS, DIST_LABELS, relations


def test_table_in_front_of_the_apartment_couch(apartment):
    rel = relations(apartment, "original", resolution_m=0.1, reference="couch_1")
    by_desc = {r["described"]: r for r in rel}
    table = by_desc["coffeetable_1"]
    assert table["frame"] == "intrinsic"
    assert table["direction"] == "front" and table["dir"]["front"] > 0.6
    assert table["distance"] == "near"
    assert by_desc["roundtable_1"]["direction"] == "back"  # the round table is behind the couch
    assert all(r["room"] == "living room" for r in rel)


def test_every_room_pair_is_listed_with_the_contract_fields(apartment):
    rel = relations(apartment, "original", resolution_m=0.1)
    scene = apartment.scene("original")
    rooms = {}
    for item in scene.furniture:
        rooms.setdefault(item.room, []).append(item.id)
    assert len(rel) == sum(len(ids) * (len(ids) - 1) for ids in rooms.values())
    for r in rel:
        assert tuple(r["dir"]) == DIR_LABELS and tuple(r["dist"]) == DIST_LABELS
        assert sum(r["dir"].values()) == pytest.approx(1.0)
        assert sum(r["dist"].values()) == pytest.approx(1.0)
        assert r["reference"] != r["described"]
        # tables have no front: they are read from the viewer (the robot's start pose)
        assert r["frame"] == ("viewer" if r["reference_word"] == "table" else "intrinsic")


def test_viewer_heading_sets_the_table_frame(apartment):
    # seen from the south (looking north) the couch is in front of the coffee table;
    # seen from the north it is behind it
    north = relations(apartment, viewer_heading_rad=1.5708, resolution_m=0.1, reference="coffeetable_1")
    south = relations(apartment, viewer_heading_rad=-1.5708, resolution_m=0.1, reference="coffeetable_1")
    couch_n = next(r for r in north if r["described"] == "couch_1")
    couch_s = next(r for r in south if r["described"] == "couch_1")
    assert couch_n["direction"] == "front" and couch_s["direction"] == "back"


def test_cli_json_and_table(capsys):
    assert main(["relations", "--world", "apartment", "--reference", "couch", "--resolution", "0.1", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["world"] == "apartment" and data["relations"]
    assert {"reference", "described", "dir", "dist"} <= set(data["relations"][0])
    assert main(["relations", "--world", "apartment", "--reference", "couch_1", "--resolution", "0.1"]) == 0
    out = capsys.readouterr().out
    assert "living room" in out and "coffeetable_1" in out and "in front" in out


def test_cli_bad_input_is_one_line(capsys):
    assert main(["relations", "--world", "apartment", "--reference", "sofa"]) == 2
    err = capsys.readouterr().err
    assert "unknown furniture 'sofa'" in err and "couch" in err
    assert main(["relations"]) == 2
    assert "--world" in capsys.readouterr().err


def test_cli_batch(tmp_path, capsys):
    batch = tmp_path / "requests.jsonl"
    batch.write_text('{"world": "apartment", "reference": "bed", "resolution": 0.1}\n'
                     '{"world": "atlantis"}\nnot json\n')
    assert main(["relations", "--batch", str(batch)]) == 0
    lines = [json.loads(line) for line in capsys.readouterr().out.splitlines()]
    assert len(lines) == 3
    assert lines[0]["relations"] and all(r["reference"] == "bed_1" for r in lines[0]["relations"])
    assert "unknown world" in lines[1]["error"] and "not JSON" in lines[2]["error"]

"""The product's own corpus (corpus/): format, annotation vocabulary, coverage, groundings,
reproducibility from tools/corpus/generate.py, and no copies of CSISL sentences."""

from __future__ import annotations

import csv
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from collections import Counter, defaultdict
from pathlib import Path

import pytest

from assistant.world.catalogue import load_catalogue

REPO = Path(__file__).resolve().parents[2]
CORPUS = REPO / "corpus"
XML = CORPUS / "descriptions.xml"
CSV = CORPUS / "chunk_groundings.csv"

CHUNK_LABELS = {"ORMTP", "ORMRP", "IRMTP", "IRMRP", "FURTP", "FURRP", "OBTP", "OBRP", "PERS", "CONF"}
WORD_TAGS = {
    "DT", "VB", "NN", "IN", "RB", "DIR", "PRP", "FUR", "CC", "ON", "TO", "RM", "VBZ", "JJ",
    "IGN", "VBP", "NNS", "MD", "WHO", "STR", "EX", "CD", "VBD", "VBG", "WRB", "WDT", "VBN",
    "VBR", "RP", "POS", "JJR", "RBR", "WP", "JJS",
}
#: any object of the catalogue (the study's six and everyday things: keys, wallet, cell phone …)
OBJECTS = set(load_catalogue().objects)
ROOMS = {"living room", "bedroom", "studio", "office", "meeting room", "hallway"}
VOCAB = {
    "target room": ROOMS | {"N/A"},
    "target object": OBJECTS | {"N/A"},
    "reference": {"move", "room", "door", "wall", "robot", "stop", "table", "chair", "couch", "bed", "N/A"},
    "direction": {"front", "back", "left", "right", "center", "beside", "between", "N/A"},
    "target": {"table", "chair", "couch", "bed", "N/A"},
}


def _sentences():
    return ET.parse(XML).getroot().findall("S")


def _words(s):
    """(word, tag) of every word element, in order."""
    out = []

    def visit(el):
        for c in el:
            if c.tag in CHUNK_LABELS:
                visit(c)
            else:
                out.append(((c.text or "").strip(), c.tag))
    visit(s)
    return out


def _chunks(s):
    """Pre-order (label, own words as 'TAG word …')."""
    out = []

    def visit(el):
        for c in el:
            if c.tag in CHUNK_LABELS:
                own = " ".join(f"{g.tag} {(g.text or '').strip()}" for g in c if g.tag not in CHUNK_LABELS)
                out.append((c.tag, own))
                visit(c)
    visit(s)
    return out


@pytest.fixture(scope="module")
def sentences():
    return _sentences()


@pytest.fixture(scope="module")
def rows():
    with CSV.open(encoding="utf-8", newline="") as f:
        return list(csv.DictReader(f))


def test_xml_parses_and_is_large_enough(sentences):
    assert ET.parse(XML).getroot().tag == "ALL"
    assert len(sentences) >= 400


def test_every_word_has_a_known_tag_and_text(sentences):
    bad = Counter()
    for s in sentences:
        for el in s.iter():
            if el is s or el.tag in CHUNK_LABELS:
                continue
            assert len(el) == 0, f"word element <{el.tag}> has children in {s.get('id')}"
            if el.tag not in WORD_TAGS or not (el.text or "").strip() or " " in el.text.strip():
                bad[(el.tag, el.text)] += 1
    assert not bad, f"bad word elements: {bad.most_common(5)}"


def test_chunk_labels_are_table_4_1_and_not_empty(sentences):
    for s in sentences:
        for el in s.iter():
            if el.tag in CHUNK_LABELS:
                assert len(el) > 0, f"empty chunk <{el.tag}> in {s.get('id')}"
        tags = {el.tag for el in s.iter()} - {"S"}
        assert tags <= CHUNK_LABELS | WORD_TAGS


def test_no_duplicate_descriptions(sentences):
    texts = Counter(" ".join(w for w, _ in _words(s)).lower() for s in sentences)
    dup = [t for t, c in texts.items() if c > 1]
    assert not dup, dup[:3]


def test_coverage_of_objects_rooms_furniture_and_speech(sentences, rows):
    text = " \n ".join(" ".join(w for w, _ in _words(s)).lower() for s in sentences)
    for phrase in ["fork", "glasses case", "laptop", "monitor", "mug", "statue",
                   "living room", "bedroom", "studio", "office", "meeting room", "hallway",
                   "table", "nightstand", "night stand", "desk", "coffee table", "dinner table",
                   "chair", "couch", "sofa", "bed",
                   "go forward", "turn left", "until you hit the wall", "about halfway in",
                   "in front of the couch", "to the left of the bed", "by the chairs",
                   "at the back", "ahead to your left", "on your left", "from the door",
                   "i think", "um", "should be"]:
        assert re.search(rf"\b{re.escape(phrase)}\b", text), f"corpus never says {phrase!r}"
    assert {r["target object"] for r in rows} >= OBJECTS
    assert {r["target room"] for r in rows} >= ROOMS - {"hallway"}
    tags = Counter(t for s in sentences for _, t in _words(s))
    for t in ("FUR", "RM", "DIR", "STR", "ON", "IGN", "WHO", "MD"):
        assert tags[t] > 0, t
    labels = Counter(el.tag for s in sentences for el in s.iter() if el.tag in CHUNK_LABELS)
    for lab in ("ORMTP", "ORMRP", "IRMRP", "FURTP", "FURRP", "OBTP", "OBRP", "PERS", "CONF"):
        assert labels[lab] > 0, lab


def test_families_cover_how_where_and_landmark_types(sentences):
    kinds = Counter(s.get("kind") for s in sentences)
    marks = Counter(s.get("landmark") for s in sentences)
    worlds = Counter(s.get("world") for s in sentences)
    assert {"dynamic", "static", "mixed"} <= set(kinds)
    assert {"none", "goal", "path"} <= set(marks)
    assert set(worlds) == {"apartment", "hk-studio", "one-bedroom-house", "two-bedrooms-house"}


def test_grounding_rows_match_chunks_in_preorder(sentences, rows):
    by_cmd = defaultdict(list)
    for r in rows:
        by_cmd[int(r["CMD#"])].append(r)
    assert set(by_cmd) <= set(range(1, len(sentences) + 1))
    for i, s in enumerate(sentences, 1):
        chunks = _chunks(s)
        got = [(r["Chunk Name"], r["Chunk Content"]) for r in by_cmd[i]]
        assert got == chunks, f"CMD {i} ({s.get('id')}): rows {got} != chunks {chunks}"


def test_grounding_values_and_which_chunk_carries_what(sentences, rows):
    for r in rows:
        for field, allowed in VOCAB.items():
            if field == "reference" and r["Chunk Name"] == "OBRP":
                # an object as a landmark: the object the phrase names, any object
                assert r[field] == "N/A" or r[field].split()[-1] in r["Chunk Content"].split(), r
                continue
            assert r[field] in allowed, (r["CMD#"], field, r[field])
        lab = r["Chunk Name"]
        if lab == "OBTP" and any(w in r["Chunk Content"].split() for w in ("fork", "mug", "laptop", "statue", "monitor")):
            assert r["target object"] in OBJECTS
        if lab == "ORMRP":
            assert r["target room"] in ROOMS
        if lab in ("IRMRP", "FURRP"):
            assert r["reference"] != "N/A" and (r["direction"] != "N/A" or r["reference"] == "stop"), r
        if lab == "FURTP":
            assert r["target"] != "N/A"
    # an OBTP that grounds an object grounds that description's object
    obj_of = {i: s.get("object") for i, s in enumerate(sentences, 1)}
    for r in rows:
        if r["Chunk Name"] == "OBTP" and r["target object"] != "N/A":
            assert r["target object"] == obj_of[int(r["CMD#"])]


def test_generator_reproduces_committed_files(tmp_path):
    out = tmp_path / "corpus"
    subprocess.run([sys.executable, str(REPO / "tools" / "corpus" / "generate.py"), "--out", str(out)],
                   check=True, capture_output=True, text=True, timeout=120)
    assert (out / "descriptions.xml").read_bytes() == XML.read_bytes()
    assert (out / "chunk_groundings.csv").read_bytes() == CSV.read_bytes()


def _csisl_texts(csisl: Path) -> set[str]:
    out = set()
    for name in ("csisl_templates149_annotated.xml", "csisl_real_descriptions_annotated.xml"):
        raw = (csisl / name).read_bytes().decode("utf-8-sig")
        raw = re.sub(r"<\?xml[^>]*\?>", "", raw)
        for s in ET.fromstring(raw).iter("S"):
            words = [(e.text or "").strip().lower() for e in s.iter() if len(e) == 0 and e is not s]
            out.add(" ".join(w for w in words if w))
    return out


def test_no_description_copies_a_csisl_sentence(shared_dir, sentences):
    csisl = shared_dir / "realdata" / "csisl"
    if not csisl.exists():
        pytest.skip("CSISL files not present")
    real = _csisl_texts(csisl)
    ours = {" ".join(w for w, _ in _words(s)).lower() for s in sentences}
    copies = ours & real
    assert not copies, sorted(copies)[:5]

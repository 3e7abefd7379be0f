"""Fixtures of the grounding tests: a small hand-written label set and trained grounders."""

from __future__ import annotations

import pytest

from assistant.grounding import ChunkGrounding, ChunkRecord, LabelledCommand

#: (label, "TAG word TAG word", (room, object, reference, direction, target))
_COMMANDS = [
    [("ORMTP", "VB go TO to DT the NN living RM room", ("living room", None, None, None, None)),
     ("IRMRP", "VB turn DIR left", (None, None, "move", "left", None)),
     ("OBTP", "DT the NN mug VBZ is", (None, "mug", None, None, None)),
     ("FURTP", "ON on DT the FUR table", (None, None, None, None, "table")),
     ("FURRP", "IN in NN front IN of DT the FUR couch", (None, None, "couch", "front", None))],
    [("ORMTP", "VB go TO to DT the RM bedroom", ("bedroom", None, None, None, None)),
     ("IRMRP", "VB walk IN about NN halfway IN in", (None, None, "room", "center", None)),
     ("IRMRP", "VB turn DIR right", (None, None, "move", "right", None)),
     ("OBTP", "PRP you MD will VB find DT the NN statue", (None, "statue", None, None, None)),
     ("FURTP", "ON on DT the FUR nightstand", (None, None, None, None, "table")),
     ("FURRP", "TO to DT the DIR left IN of DT the FUR bed", (None, None, "bed", "left", None))],
    [("ORMTP", "VB enter DT the NN living RM room", ("living room", None, None, None, None)),
     ("IRMRP", "VB go RB forward", (None, None, "move", "front", None)),
     ("OBTP", "DT the NN fork VBZ is", (None, "fork", None, None, None)),
     ("IRMRP", "TO to PRP your DIR right", (None, None, "robot", "right", None))],
    [("ORMTP", "VB go IN into DT the RM bedroom", ("bedroom", None, None, None, None)),
     ("IRMRP", "VB go RB forward IN until PRP you VBP reach DT the STR wall", (None, None, "wall", "beside", None)),
     ("OBTP", "DT the NN laptop VBZ is", (None, "laptop", None, None, None)),
     ("FURTP", "ON on DT the FUR table", (None, None, None, None, "table")),
     ("FURRP", "IN behind DT the FUR couch", (None, None, "couch", "back", None))],
    [("ORMTP", "VB head TO to DT the NN living RM room", ("living room", None, None, None, None)),
     ("OBTP", "DT the NN mug VBZ is", (None, "mug", None, None, None)),
     ("FURTP", "ON on DT the FUR table", (None, None, None, None, "table")),
     ("FURRP", "IN beside DT the FUR chair", (None, None, "chair", "beside", None))],
    [("ORMTP", "VB walk TO to DT the RM room", (None, None, None, None, None)),
     ("IRMRP", "VB turn DIR left", (None, None, "move", "left", None)),
     ("OBTP", "DT the NN statue VBZ is", (None, "statue", None, None, None)),
     ("FURTP", "ON on DT the FUR table", (None, None, None, None, "table")),
     ("FURRP", "TO to DT the DIR right IN of DT the FUR bed", (None, None, "bed", "right", None))],
]


def _command(number: int, rows) -> LabelledCommand:
    records, groundings = [], []
    for label, content, values in rows:
        parts = content.split()
        records.append(ChunkRecord(label, tuple(parts[1::2]), tuple(parts[0::2])))
        groundings.append(ChunkGrounding(*values))
    return LabelledCommand(str(number), tuple(records), tuple(groundings))


@pytest.fixture(scope="session")
def small_labels() -> list[LabelledCommand]:
    return [_command(i, rows) for i, rows in enumerate(_COMMANDS, start=1)]


@pytest.fixture(scope="session")
def corpus_labels():
    """Our corpus's chunk-grounding labels (skips when the corpus has none yet)."""
    from assistant.grounding.training import load_labels, split_corpus_paths

    csvs, xmls = split_corpus_paths(None)
    if not csvs:
        pytest.skip("corpus/ has no chunk-grounding CSV yet")
    return load_labels(csvs, xmls)

"""Reading chunk-grounding label files (the CSISL CSV format) and tying rows to chunk trees.

A file has the header ``CMD#,Chunk Name,Chunk Content,target room,target object,reference,
direction,target``; one row per chunk, rows of one command in the pre-order of the
description's chunks. ``Chunk Content`` is the chunk's *own* words (nested chunks excluded) as
``TAG word TAG word …``; a field that does not apply is ``N/A`` (or empty). Values are read in
canonical form (:func:`~assistant.grounding.vocabulary.canonical_value`: a ``nightstand``
target is the ``table`` category), so files that spell them differently compare equal.

The reader is forgiving like the corpus reader: a row it cannot read is reported in
:attr:`ChunkGroundingFile.problems` (``file: row 12: …``) and skipped; only a file with no
usable header raises :class:`~assistant.errors.DataFileError`.
"""

from __future__ import annotations

import csv
import io
import os
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path

from assistant.errors import DataFileError
from assistant.grounding.types import FIELDS, ROOT, ChunkGrounding, ChunkRecord, LabelledCommand
from assistant.grounding.objects import object_kind
from assistant.grounding.spoken import STOP
from assistant.grounding.vocabulary import FURNITURE_CATEGORIES, STRUCTURE_REFERENCES, canonical_value

#: reference values that are not objects
KNOWN_REFERENCES = frozenset({*STRUCTURE_REFERENCES, *FURNITURE_CATEGORIES, STOP})

NUMBER_COLUMN = "CMD#"
LABEL_COLUMN = "Chunk Name"
CONTENT_COLUMN = "Chunk Content"
COLUMNS = (NUMBER_COLUMN, LABEL_COLUMN, CONTENT_COLUMN, *FIELDS)
NOT_APPLICABLE = frozenset({"", "n/a", "na", "none", "-"})


@dataclass
class ChunkGroundingFile:
    """The commands read from one or more label files, and what could not be read."""

    commands: list[LabelledCommand] = field(default_factory=list)
    problems: list[str] = field(default_factory=list)

    @property
    def records(self) -> list[ChunkRecord]:
        return [r for c in self.commands for r in c.records]

    @property
    def groundings(self) -> list[ChunkGrounding]:
        return [g for c in self.commands for g in c.groundings]

    def __len__(self) -> int:
        return len(self.commands)


def parse_content(content: str) -> tuple[tuple[str, ...], tuple[str, ...]]:
    """``"DT the FUR table"`` → ``(("the", "table"), ("DT", "FUR"))``.

    Raises ValueError when the content does not alternate tag and word.
    """
    parts = content.split()
    if len(parts) % 2:
        raise ValueError(f"chunk content must alternate TAG word, got {content!r}")
    return tuple(parts[1::2]), tuple(parts[0::2])


def label_value(field_name: str, value: str | None) -> str | None:
    """A label value as the grounders give it: canonical words (:func:`canonical_value`), and an
    object — the target object, or an object used as a reference — by the catalogue's name for
    it, so annotation variants score alike ("glass case" and "glasses case", "key" and "keys",
    "computer" and "laptop"; :func:`~assistant.grounding.objects.object_kind`)."""
    value = canonical_value(field_name, value)
    if value is None:
        return None
    if field_name == "target object" or (field_name == "reference" and value not in KNOWN_REFERENCES):
        return object_kind(value)
    return value


def _value(raw: str | None) -> str | None:
    text = (raw or "").strip()
    return None if text.lower() in NOT_APPLICABLE else text.lower()


def read_chunk_groundings(paths: str | os.PathLike | Iterable[str | os.PathLike]) -> ChunkGroundingFile:
    """Read one label file, or several (commands are numbered ``file:number`` when several)."""
    if isinstance(paths, (str, os.PathLike)):
        paths = [paths]
    paths = [Path(p) for p in paths]
    out = ChunkGroundingFile()
    for path in paths:
        prefix = f"{path.stem}:" if len(paths) > 1 else ""
        _read_one(path, prefix, out)
    return out


def _read_one(path: Path, prefix: str, out: ChunkGroundingFile) -> None:
    try:
        text = path.read_text(encoding="utf-8-sig")
    except OSError as error:
        raise DataFileError(str(path), "", f"cannot read chunk-grounding file: {error.strerror}") from error
    except UnicodeDecodeError as error:
        raise DataFileError(str(path), "", f"not UTF-8 text ({error.reason})") from error
    reader = csv.DictReader(io.StringIO(text))
    header = [h.strip() for h in (reader.fieldnames or [])]
    missing = [c for c in COLUMNS if c not in header]
    if missing:
        raise DataFileError(str(path), "header", f"missing column(s) {', '.join(missing)}; "
                            f"expected {','.join(COLUMNS)}")
    reader.fieldnames = header
    order: list[str] = []
    rows: dict[str, list[tuple[ChunkRecord, ChunkGrounding]]] = {}
    for line_number, row in enumerate(reader, start=2):
        where = f"row {line_number}"
        number = (row.get(NUMBER_COLUMN) or "").strip()
        label = (row.get(LABEL_COLUMN) or "").strip().upper()
        if not number:
            out.problems.append(f"{path}: {where}: no command number; row skipped")
            continue
        if not label:
            out.problems.append(f"{path}: {where}: no chunk name; row skipped")
            continue
        try:
            words, pos = parse_content(row.get(CONTENT_COLUMN) or "")
        except ValueError as error:
            out.problems.append(f"{path}: {where}: {error}; row skipped")
            continue
        grounding = ChunkGrounding.from_fields({f: label_value(f, _value(row.get(f))) for f in FIELDS})
        key = prefix + number
        if key not in rows:
            rows[key] = []
            order.append(key)
        rows[key].append((ChunkRecord(label, words, pos), grounding))
    for key in order:
        records, groundings = zip(*rows[key])
        out.commands.append(LabelledCommand(key, tuple(records), tuple(groundings), str(path)))


def records_from_tree(tree, world: str | None = None) -> list[ChunkRecord]:
    """The chunk records of a :class:`~assistant.language.ChunkTree`, in pre-order."""
    out = []
    for chunk, parent, _depth in tree.chunks():
        own = chunk.own_tokens
        out.append(ChunkRecord(
            chunk.label,
            tuple(t.text for t in own),
            tuple(t.pos for t in own),
            parent.label if parent is not None else ROOT,
            tuple(c.label for c in chunk.children),
            world,
        ))
    return out


def attach_structure(command: LabelledCommand, tree, world: str | None = None) -> LabelledCommand:
    """Give a command's rows the parent and child labels of its chunk tree (and the world).

    Rows and tree chunks are matched in pre-order; when the label sequences differ (the label
    file was cut differently from the tree) only the world is attached.
    """
    tree_records = records_from_tree(tree, world)
    if [r.label for r in tree_records] != [r.label for r in command.records]:
        if world is None:
            return command
        return with_world(command, world)
    records = tuple(replace(r, parent=t.parent, children=t.children, world=world or r.world)
                    for r, t in zip(command.records, tree_records))
    return replace(command, records=records)


def with_world(command: LabelledCommand, world: str | None) -> LabelledCommand:
    """The command with every row's ``world`` set."""
    return replace(command, records=tuple(replace(r, world=world) for r in command.records))


def attach_structures(commands: Sequence[LabelledCommand], trees: dict[str, object],
                      worlds: dict[str, str] | None = None) -> tuple[list[LabelledCommand], int]:
    """:func:`attach_structure` for every command whose number is a key of ``trees``.

    Returns the commands and how many got their structure.
    """
    out, matched = [], 0
    worlds = worlds or {}
    for command in commands:
        key = command.number if command.number in trees else command.number.split(":")[-1]
        tree = trees.get(key)
        new = attach_structure(command, tree, worlds.get(key)) if tree is not None else command
        matched += new is not command
        out.append(new)
    return out, matched

"""Reading annotated spatial-language corpora in the CSISL XML format (dissertation 4.2.2).

Each description is one ``<S>`` element. Inside, chunk elements nest (``OBTP``, ``FURTP``…,
see :data:`~assistant.language.tree.CHUNK_LABELS`) and every word is an element named by its
POS tag (``<FUR>table</FUR>``). Real files are untidy, so the reader reads what it can and
reports the rest, naming the file and the description number, and never stops on one bad
description:

* a byte-order mark, CRLF line ends and stray whitespace are ignored;
* empty elements and punctuation-only words are skipped (and reported);
* a misspelt tag is mapped to the nearest known tag (``<OBPT>`` → ``OBTP``) and reported;
* broken XML is reported with its position, then each ``<S>…</S>`` is parsed on its own,
  and a description that still does not parse is read by a tolerant tag scanner.

Descriptions are numbered from 1 in file order (the numbering of the CSISL chunk-grounding
CSV); the attributes of ``<S>`` are kept as they are.
"""

from __future__ import annotations

import os
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

from rapidfuzz.distance import OSA

from assistant.errors import AssistantError
from assistant.language.tokenize import CLITICS, tokenize
from assistant.language.tree import CHUNK_LABELS, Chunk, ChunkTree, Token

__all__ = [
    "CHUNK_TAGS", "POS_TAGS", "PUNCTUATION_TAGS", "CorpusReadResult", "Description",
    "default_corpus_paths", "read_corpora", "read_corpus", "repo_root", "parse_corpus_text",
    "description_xml", "write_corpus",
]

#: chunk labels (dissertation Table 4-1, plus IRMTP which the CSISL files also use)
CHUNK_TAGS = tuple(dict.fromkeys((*CHUNK_LABELS, "IRMTP")))

#: word tags: Penn Treebank plus the CSISL semantic tags — FUR furniture, RM room, DIR
#: direction, STR structure (wall, door), ON "on", IGN filler (uh, ok), WHO addressee,
#: VBR the split "gon na". Ordered roughly by frequency: ties in a fuzzy match go to the first.
POS_TAGS = (
    "DT", "VB", "NN", "IN", "RB", "DIR", "PRP", "FUR", "CC", "ON", "TO", "RM", "VBZ", "JJ",
    "IGN", "VBP", "NNS", "MD", "WHO", "STR", "EX", "CD", "VBD", "VBG", "WRB", "WDT", "VBN",
    "VBR", "RP", "POS", "JJR", "RBR", "WP", "JJS", "RBS", "UH", "NNP", "NNPS", "PDT", "FW",
    "LS", "SYM", "PRPS", "WPS",
)

#: punctuation word tags: their words are dropped (speech has no punctuation)
PUNCTUATION_TAGS = ("COMMA", "QUOTE", "BRACKETS", "CHAR", "PERIOD", "COLON", "DASH", "PUNCT")

_ENV_CORPUS = "ASSISTANT_CORPUS"


@dataclass
class Description:
    """One annotated description: its number in the file (from 1), tree, attributes, file."""

    number: int
    tree: ChunkTree
    attributes: dict = field(default_factory=dict)
    source: str = ""

    @property
    def text(self) -> str:
        return self.tree.text

    def tagged_words(self) -> list[tuple[str, str]]:
        return [(t.text, t.pos) for t in self.tree.tokens()]


@dataclass
class CorpusReadResult:
    """What was read (``descriptions``) and what was not (``problems``, one line each)."""

    descriptions: list[Description] = field(default_factory=list)
    problems: list[str] = field(default_factory=list)
    files: list[str] = field(default_factory=list)

    def extend(self, other: "CorpusReadResult") -> None:
        self.descriptions.extend(other.descriptions)
        self.problems.extend(other.problems)
        self.files.extend(other.files)

    def trees(self) -> list[ChunkTree]:
        return [d.tree for d in self.descriptions]


# --------------------------------------------------------------------------------------------
# locating corpora

def repo_root() -> Path:
    """The checkout: the parent of the ``assistant`` package folder."""
    return Path(__file__).resolve().parents[2]


def default_corpus_paths() -> list[Path]:
    """The training corpus: ``$ASSISTANT_CORPUS`` (files or folders, ``os.pathsep``-separated)
    if set, else the repository's ``corpus/*.xml``."""
    env = os.environ.get(_ENV_CORPUS)
    if env:
        return _expand([Path(p) for p in env.split(os.pathsep) if p.strip()])
    return sorted((repo_root() / "corpus").glob("*.xml"))


def _expand(paths) -> list[Path]:
    out: list[Path] = []
    for path in paths:
        path = Path(path)
        out.extend(sorted(path.glob("*.xml")) if path.is_dir() else [path])
    return out


def read_corpora(paths) -> CorpusReadResult:
    """Read several corpus files (folders stand for their ``*.xml``), in the order given."""
    result = CorpusReadResult()
    for path in _expand(paths):
        result.extend(read_corpus(path))
    return result


def read_corpus(path) -> CorpusReadResult:
    """Read one corpus file (or every ``*.xml`` of a folder).

    Raises :class:`AssistantError` only when the file cannot be opened at all; everything
    else is reported in ``problems`` ("file: description 17: …") and reading goes on.
    """
    path = Path(path)
    if path.is_dir():
        return read_corpora([path])
    try:
        data = path.read_bytes()
    except OSError as error:
        raise AssistantError(
            f"cannot read corpus file {path}: {error.strerror or error}; "
            "give an existing CSISL-format XML file or folder"
        ) from error
    return parse_corpus_bytes(data, str(path))


def parse_corpus_bytes(data: bytes, source: str) -> CorpusReadResult:
    problems: list[str] = []
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        problems.append(f"{source}: byte {error.start}: not UTF-8; undecodable bytes replaced")
        text = data.decode("utf-8-sig", errors="replace")
    result = parse_corpus_text(text, source)
    result.problems[:0] = problems
    return result


_DECLARATION = re.compile(r"^\s*<\?xml[^>]*\?>", re.S)
_S_BLOCK = re.compile(r"<S(?:\s[^>]*)?>.*?(?:</S\s*>|(?=<S[\s>])|\Z)", re.S)


def parse_corpus_text(text: str, source: str = "<text>") -> CorpusReadResult:
    """Read corpus XML already decoded to text (see :func:`read_corpus`)."""
    result = CorpusReadResult(files=[source])
    text = _DECLARATION.sub("", text.lstrip("\ufeff"), count=1)
    try:
        root = ET.fromstring(text)
        elements = [el for el in root.iter("S")] if root.tag != "S" else [root]
    except ET.ParseError as error:
        line, column = error.position
        result.problems.append(
            f"{source}: line {line}, column {column + 1}: broken XML ({_reason(error)}); "
            "reading each <S>…</S> on its own"
        )
        elements = None
    if elements is not None:
        for number, element in enumerate(elements, start=1):
            _add(result, element, number, source)
        if not elements:
            result.problems.append(f"{source}: no <S> descriptions found")
        return result
    blocks = _S_BLOCK.findall(text)
    if not blocks:
        result.problems.append(f"{source}: no <S> descriptions found")
    for number, block in enumerate(blocks, start=1):
        try:
            element = ET.fromstring(block)
        except ET.ParseError as error:
            result.problems.append(
                f"{source}: description {number}: broken XML ({_reason(error)}); read tolerantly"
            )
            element = _tolerant_parse(block, lambda msg: result.problems.append(
                f"{source}: description {number}: {msg}"))
        _add(result, element, number, source)
    return result


def _reason(error: ET.ParseError) -> str:
    return str(error).split(":")[0]


def _add(result: CorpusReadResult, element: ET.Element, number: int, source: str) -> None:
    def report(message: str) -> None:
        result.problems.append(f"{source}: description {number}: {message}")

    try:
        items = _read_items(element, None, report)
    except RecursionError:
        report("nested too deeply; skipped")
        return
    tree = ChunkTree(items)
    if not tree.tokens():
        report("no words; skipped")
        return
    attributes = {k: v.strip() for k, v in element.attrib.items()}
    result.descriptions.append(Description(number, tree, attributes, source))


# --------------------------------------------------------------------------------------------
# writing (what is read can be written back: read → write → read gives the same trees)

def description_xml(description: Description, indent: str = "  ") -> str:
    """One ``<S>`` element in the corpus format, one word per line."""
    from xml.sax.saxutils import escape, quoteattr

    attrs = "".join(f" {k}={quoteattr(str(v))}" for k, v in description.attributes.items())
    lines = [f"{indent}<S{attrs}>"]

    def emit(items, depth):
        pad = indent * depth
        for item in items:
            if isinstance(item, Chunk):
                lines.append(f"{pad}<{item.label}>")
                emit(item.items, depth + 1)
                lines.append(f"{pad}</{item.label}>")
            else:
                lines.append(f"{pad}<{item.pos}>{escape(item.text)}</{item.pos}>")

    emit(description.tree.items, 2)
    lines.append(f"{indent}</S>")
    return "\n".join(lines)


def write_corpus(descriptions, path) -> Path:
    """Write descriptions to ``path`` atomically, in the format :func:`read_corpus` reads."""
    from assistant.fileio import atomic_write_text

    body = "\n".join(description_xml(d) for d in descriptions)
    text = f'<?xml version="1.0" encoding="utf-8"?>\n<ALL>\n{body}\n</ALL>\n'
    return atomic_write_text(path, text)


# --------------------------------------------------------------------------------------------
# element → tree

def _read_items(element: ET.Element, parent_label: str | None, report) -> list:
    items: list = []
    if element.text and element.text.strip():
        _stray_text(element.text, element.tag, report)
    for child in element:
        if not isinstance(child.tag, str):  # comments, processing instructions
            pass
        elif len(child):  # has elements inside: a chunk
            label = _chunk_label(child.tag, parent_label, report)
            inner = _read_items(child, label or parent_label, report)
            if label is None:
                items.extend(inner)
            elif not inner:
                report(f"empty chunk <{child.tag}>; skipped")
            else:
                items.append(Chunk(label, inner))
        else:
            items.extend(_read_word(child, parent_label, report))
        if child.tail and child.tail.strip():
            _stray_text(child.tail, element.tag, report)
    return items


def _stray_text(text: str, tag: str, report) -> None:
    report(f"text {text.strip()[:40]!r} outside a word element in <{tag}>; skipped")


def _read_word(element: ET.Element, parent_label: str | None, report) -> list[Token]:
    tag = element.tag.strip()
    raw = (element.text or "").strip()
    if tag in CHUNK_TAGS or tag == "S":
        if raw:
            report(f"word {raw!r} tagged with chunk label <{tag}>; skipped")
        else:
            report(f"empty chunk <{tag}>; skipped")
        return []
    if not raw:
        report(f"empty element <{tag}>; skipped")
        return []
    word = raw.lower()
    words = [word] if word in CLITICS else tokenize(word)
    if tag.upper() in PUNCTUATION_TAGS or not words:
        report(f"punctuation {raw!r} <{tag}> dropped")
        return []
    if words != [word]:
        report(f"word {raw!r} read as {len(words)} words: {' '.join(words)}")
    pos = tag if tag in POS_TAGS else _nearest(tag, POS_TAGS)
    if pos != tag:
        report(f"unknown tag <{tag}> for {raw!r}, read as {pos}")
    return [Token(w, pos) for w in words]


def _chunk_label(tag: str, parent_label: str | None, report) -> str | None:
    tag = tag.strip()
    if tag in CHUNK_TAGS:
        return tag
    upper = tag.upper()
    if upper in CHUNK_TAGS:
        report(f"chunk tag <{tag}> read as {upper}")
        return upper
    distances = {label: OSA.distance(upper, label) for label in CHUNK_TAGS}
    best = min(distances.values())
    if best > 2 or best >= len(upper):
        report(f"unknown chunk tag <{tag}>; its words kept in the enclosing chunk")
        return None
    candidates = [label for label in CHUNK_TAGS if distances[label] == best]
    # a target phrase is the parent of reference phrases: inside FURTP, prefer FURRP to FURTP
    if len(candidates) > 1 and parent_label in candidates:
        candidates.remove(parent_label)
    label = candidates[0]
    report(f"unknown chunk tag <{tag}>, read as {label}")
    return label


def _nearest(tag: str, known) -> str:
    upper = tag.upper()
    if upper in known:
        return upper
    return min(known, key=lambda k: (OSA.distance(upper, k), known.index(k)))


# --------------------------------------------------------------------------------------------
# tolerant scanner for a description that is not well-formed XML

_SCAN = re.compile(r"<(/?)\s*([^\s<>/]+)[^<>]*?(/?)>|([^<]+)|<")


def _tolerant_parse(block: str, report) -> ET.Element:
    """Build an element tree from a description that is not well-formed XML.

    A word element never holds other elements, so a word left open is closed by the next
    tag; a closing tag of an element that is not open is ignored; chunks left open are
    closed at the end (each reported).
    """
    root = ET.Element("S")
    stack = [root]

    def close_open_word(reason: str) -> None:
        if len(stack) > 1 and _is_word_tag(stack[-1].tag):
            report(f"<{stack[-1].tag}> not closed before {reason}")
            stack.pop()

    for match in _SCAN.finditer(block):
        closing, name, selfclosing, text = match.groups()
        if text is not None or name is None:
            chunk = text if text is not None else match.group(0)
            target = stack[-1]
            if len(target):
                target[-1].tail = (target[-1].tail or "") + chunk
            else:
                target.text = (target.text or "") + chunk
            continue
        if name == "S" and not closing:
            root.attrib.update(_attributes(match.group(0)))
            continue
        if closing:
            names = [el.tag for el in stack]
            if name in names[1:]:
                while stack[-1].tag != name:
                    report(f"<{stack[-1].tag}> not closed; closed at </{name}>")
                    stack.pop()
                stack.pop()
            elif len(stack) > 1 and _is_word_tag(stack[-1].tag):
                report(f"<{stack[-1].tag}> closed by </{name}>")
                stack.pop()
            elif name != "S":
                report(f"</{name}> without a matching start tag; ignored")
            continue
        close_open_word(f"<{name}>")
        element = ET.SubElement(stack[-1], name)
        if not selfclosing:
            stack.append(element)
    for element in stack[1:]:
        report(f"<{element.tag}> not closed")
    return root


def _is_word_tag(tag: str) -> bool:
    upper = tag.upper()
    if upper in POS_TAGS or upper in PUNCTUATION_TAGS:
        return True
    if upper in CHUNK_TAGS or upper == "S":
        return False
    return min(OSA.distance(upper, label) for label in CHUNK_TAGS) > 1


def _attributes(start_tag: str) -> dict:
    return dict(re.findall(r'(\w+)\s*=\s*"([^"]*)"', start_tag))

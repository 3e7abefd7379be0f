"""Chunk trees: the nested semantic chunks of one description (dissertation 4.2).

A :class:`ChunkTree` is a sequence of items, each a :class:`Token` (a word with its POS tag) or
a :class:`Chunk` (a label such as ``OBTP`` with its own items). The *nested chunk label* of a
word is the path of chunk labels from the sentence down to it, outermost first, joined with
``-`` (``OBTP-FURTP-ORMTP``); ``O`` for a word outside every chunk (dissertation 4.2.3).

Paths alone cannot tell two adjacent sibling chunks of the same label apart (two ``IRMRP`` in a
row read as one); :meth:`ChunkTree.from_labels` therefore accepts an optional boundary flag per
word that starts a new chunk at the innermost level.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field

OUTSIDE = "O"

#: chunk labels of the CSISL annotation (dissertation Table 4-1)
CHUNK_LABELS = ("ORMTP", "ORMRP", "IRMTP", "IRMRP", "FURTP", "FURRP", "OBTP", "OBRP", "PERS", "CONF")


@dataclass(frozen=True)
class Token:
    """A word and its part-of-speech tag (Penn Treebank plus FUR, RM, DIR, STR, ON…)."""

    text: str
    pos: str


@dataclass
class Chunk:
    """A semantic chunk: a label and its items (tokens and nested chunks), in order."""

    label: str
    items: list["Chunk | Token"] = field(default_factory=list)

    def tokens(self) -> list[Token]:
        out: list[Token] = []
        for item in self.items:
            out.extend(item.tokens() if isinstance(item, Chunk) else [item])
        return out

    @property
    def text(self) -> str:
        """All the words of the chunk, nested chunks included."""
        return " ".join(t.text for t in self.tokens())

    @property
    def own_tokens(self) -> list[Token]:
        """The words directly in this chunk (not inside a nested chunk)."""
        return [item for item in self.items if isinstance(item, Token)]

    @property
    def children(self) -> list["Chunk"]:
        return [item for item in self.items if isinstance(item, Chunk)]

    def walk(self) -> Iterator[tuple["Chunk", "Chunk | None", int]]:
        """Pre-order: ``(chunk, parent, depth)`` for this chunk and every nested one."""
        yield from _walk(self, None, 0)

    def to_dict(self) -> dict:
        return {"label": self.label, "items": [
            i.to_dict() if isinstance(i, Chunk) else {"text": i.text, "pos": i.pos} for i in self.items
        ]}


def _walk(chunk: Chunk, parent: Chunk | None, depth: int):
    yield chunk, parent, depth
    for child in chunk.children:
        yield from _walk(child, chunk, depth + 1)


@dataclass
class ChunkTree:
    """One description: top-level items (tokens outside any chunk, and chunks)."""

    items: list[Chunk | Token] = field(default_factory=list)

    # --- views ----------------------------------------------------------------------------
    def tokens(self) -> list[Token]:
        return Chunk("S", self.items).tokens()

    @property
    def words(self) -> list[str]:
        return [t.text for t in self.tokens()]

    @property
    def pos_tags(self) -> list[str]:
        return [t.pos for t in self.tokens()]

    @property
    def text(self) -> str:
        return " ".join(self.words)

    def chunks(self) -> list[tuple[Chunk, Chunk | None, int]]:
        """Every chunk in pre-order as ``(chunk, parent or None, depth)``."""
        out = []
        for item in self.items:
            if isinstance(item, Chunk):
                out.extend(item.walk())
        return out

    def nested_labels(self) -> list[str]:
        """The nested chunk label of every word, in order (``O`` outside any chunk)."""
        return [label for label, _, _ in self._labelled()]

    def boundaries(self) -> list[bool]:
        """Per word: whether it is the first word of the innermost chunk that holds it."""
        return [start for _, start, _ in self._labelled()]

    def start_depths(self) -> list[int]:
        """Per word: the depth (0 = outermost) of the outermost chunk that opens at this word,
        or -1 when no chunk opens there. Unlike :meth:`boundaries` this also tells where an
        outer chunk restarts (``[ORMTP go left] [ORMTP [ORMRP take a right]]``)."""
        return [depth for _, _, depth in self._labelled()]

    def _labelled(self) -> list[tuple[str, bool, int]]:
        out: list[tuple[str, bool, int]] = []
        pending = [-1]  # depth of the outermost chunk opened since the last word

        def visit(items, path: tuple[str, ...]):
            if pending[0] < 0:
                pending[0] = len(path) - 1
            first = True
            for item in items:
                if isinstance(item, Chunk):
                    visit(item.items, path + (item.label,))
                    first = False  # a word after a nested chunk continues this one
                else:
                    out.append(("-".join(path) if path else OUTSIDE, first and bool(path), pending[0]))
                    pending[0] = -1
                    first = False

        for item in self.items:
            if isinstance(item, Chunk):
                visit(item.items, (item.label,))
            else:
                out.append((OUTSIDE, False, -1))
                pending[0] = -1
        return out

    def bracketed(self) -> str:
        """A one-line bracketed form: ``[OBTP the mug is [FURTP on the table]]``."""

        def show(item) -> str:
            if isinstance(item, Chunk):
                return "[" + item.label + " " + " ".join(show(i) for i in item.items) + "]"
            return item.text

        return " ".join(show(i) for i in self.items)

    def to_dict(self) -> dict:
        return {"items": [i.to_dict() if isinstance(i, Chunk) else {"text": i.text, "pos": i.pos}
                          for i in self.items]}

    # --- decoding ---------------------------------------------------------------------------
    @classmethod
    def from_labels(cls, words: Sequence[str], pos: Sequence[str], labels: Sequence[str],
                    boundaries: Sequence[bool] | None = None,
                    start_depths: Sequence[int] | None = None) -> "ChunkTree":
        """Rebuild the tree from nested labels (outermost first), e.g. ``OBTP-FURTP``.

        Consecutive words sharing a path prefix share those chunks. A ``True`` boundary starts
        a new innermost chunk even when the previous word had the same path. A start depth
        ``d >= 0`` (see :meth:`start_depths`) closes every open chunk from depth ``d`` down and
        opens new ones. Every label sequence decodes to *some* tree, so a tagger's output is
        always usable.
        """
        if not (len(words) == len(pos) == len(labels)):
            raise ValueError("words, pos and labels must have the same length")
        root = Chunk("S")
        open_chunks: list[Chunk] = []  # the currently open path below the root
        for i, (word, tag, label) in enumerate(zip(words, pos, labels)):
            path = [] if label in (OUTSIDE, "", None) else label.split("-")
            start_new = bool(boundaries[i]) if boundaries is not None else False
            # how much of the open path can be kept
            keep = 0
            while keep < min(len(path), len(open_chunks)) and open_chunks[keep].label == path[keep]:
                keep += 1
            if start_new and path and keep == len(path):
                keep = len(path) - 1
            if start_depths is not None and 0 <= start_depths[i] < len(path):
                keep = min(keep, int(start_depths[i]))
            del open_chunks[keep:]
            for label_part in path[keep:]:
                chunk = Chunk(label_part)
                (open_chunks[-1] if open_chunks else root).items.append(chunk)
                open_chunks.append(chunk)
            (open_chunks[-1] if open_chunks else root).items.append(Token(word, tag))
        return cls(root.items)

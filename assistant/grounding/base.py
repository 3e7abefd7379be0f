"""What every grounder shares: the estimator contract, word normalisation and scoring.

A grounder maps :class:`~assistant.grounding.types.ChunkRecord` objects to
:class:`~assistant.grounding.types.ChunkGrounding` objects. It follows scikit-learn's
estimator conventions: parameters only in ``__init__``, ``fit(records, groundings)`` returns
``self``, learned attributes end in ``_``, and ``ground`` before ``fit`` raises
:class:`GrounderNotFittedError`. ``accuracy(gold)`` scores any grounder the same way
(dissertation Tables 4-3/4-4): per grounding field over chunks, and per whole command (every
chunk of the command right).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

from assistant.errors import AssistantError, NotFittedError
from assistant.grounding.spoken import spoken_groundings
from assistant.grounding.types import FIELDS, ChunkGrounding, ChunkRecord, LabelledCommand
from assistant.grounding.vocabulary import canonical_tokens, match_token

#: the key of the whole-command accuracy in :meth:`BaseGrounder.accuracy`
COMMAND = "whole command"


#: the one :class:`~assistant.errors.NotFittedError` (this name kept for callers)
GrounderNotFittedError = NotFittedError


@dataclass(frozen=True)
class NormalisedChunk:
    """A chunk's words as grounders compare them: canonical, furniture collapsed to category."""

    label: str
    words: tuple[str, ...]
    pos: tuple[str, ...]
    parent: str | None
    children: tuple[str, ...] | None
    world: str | None = None

    @property
    def children_key(self) -> str | None:
        return None if self.children is None else "+".join(sorted(set(self.children))) or "-"


def normalise(record: ChunkRecord) -> NormalisedChunk:
    words, pos = canonical_tokens(record.words, record.pos)
    return NormalisedChunk(record.label.upper(), tuple(match_token(w) for w in words), tuple(pos),
                           record.parent, record.children, record.world)


class BaseGrounder:
    """Shared behaviour; subclasses implement ``fit`` and ``_ground_one``."""

    def _check_fitted(self) -> None:
        if not getattr(self, "fitted_", False):
            raise GrounderNotFittedError(
                f"this {type(self).__name__} is not fitted yet; call fit(records, groundings) "
                "with chunk-grounding labels first (e.g. from read_chunk_groundings)")

    def _start_fit(self, records: Sequence[ChunkRecord],
                   groundings: Sequence[ChunkGrounding]) -> list[NormalisedChunk]:
        """Check the training data, set ``vocabulary_`` and return the normalised chunks."""
        if len(records) != len(groundings):
            raise ValueError(f"{len(records)} records but {len(groundings)} groundings")
        if not records:
            raise ValueError("cannot fit a grounder on no chunks; the label file is empty")
        chunks = [normalise(r) for r in records]
        self.vocabulary_ = frozenset(w for c in chunks for w in c.words)
        return chunks

    def ground(self, records: Sequence[ChunkRecord]) -> list[ChunkGrounding]:
        """The grounding of each chunk record.

        Two checks keep a guess from standing in for words that were never said: a chunk with
        no word the grounder was trained on grounds to nothing, and a target object must be
        named in the chunk (its word, or a synonym of it). Then the words decide what they
        plainly say (:func:`~assistant.grounding.spoken.spoken_groundings`: the object phrase
        names any object, object landmarks, the listener's side, stop, turns, halfway …).
        """
        self._check_fitted()
        chunks = [normalise(r) for r in records]
        if not chunks:
            return []
        out = []
        known = [any(w in self.vocabulary_ for w in chunk.words) for chunk in chunks]
        for chunk, grounding, seen in zip(chunks, self._ground_chunks(chunks), known):
            if not seen:
                grounding = ChunkGrounding()
            elif grounding.object and not set(grounding.object.split()) & set(chunk.words):
                grounding = replace(grounding, object=None)
            out.append(grounding)
        # the families of real phrasing the words decide: any object, object landmarks, stop …
        return spoken_groundings(records, out, known)

    def _ground_chunks(self, chunks: Sequence[NormalisedChunk]) -> list[ChunkGrounding]:
        return [self._ground_one(c) for c in chunks]

    def ground_one(self, record: ChunkRecord) -> ChunkGrounding:
        return self.ground([record])[0]

    def accuracy(self, gold: Sequence[LabelledCommand]) -> dict[str, float]:
        """Fraction right per grounding field (over chunks) and per whole command."""
        return grounding_accuracy(self, gold)

    def get_params(self, deep: bool = True) -> dict:
        import inspect

        names = [p for p in inspect.signature(type(self).__init__).parameters if p != "self"]
        return {n: getattr(self, n) for n in names}

    def set_params(self, **params) -> "BaseGrounder":
        known = self.get_params()
        for name, value in params.items():
            if name not in known:
                raise ValueError(f"unknown parameter {name!r} of {type(self).__name__}; known: {', '.join(known)}")
            setattr(self, name, value)
        return self

    def __repr__(self) -> str:
        params = ", ".join(f"{k}={v!r}" for k, v in self.get_params().items())
        return f"{type(self).__name__}({params})"


def grounding_accuracy(grounder, gold: Sequence[LabelledCommand]) -> dict[str, float]:
    """Accuracy of ``grounder`` on labelled commands (see :meth:`BaseGrounder.accuracy`). Each
    command is grounded on its own, as the parser grounds one: what one command said (a room
    named) must not carry into the next."""
    right = dict.fromkeys(FIELDS, 0)
    chunks = commands_right = 0
    for command in gold:
        all_right = True
        for truth, guess in zip(command.groundings, grounder.ground(command.records)):
            chunks += 1
            for f in FIELDS:
                ok = guess.get(f) == truth.get(f)
                right[f] += ok
                all_right &= ok
        commands_right += all_right
    out = {f: right[f] / chunks if chunks else 0.0 for f in FIELDS}
    out[COMMAND] = commands_right / len(gold) if gold else 0.0
    return out


def command_errors(grounder, gold: Sequence[LabelledCommand]) -> list[tuple[str, ChunkRecord, ChunkGrounding, ChunkGrounding]]:
    """Every chunk the grounder gets wrong: (command number, record, truth, guess)."""
    out = []
    for command in gold:
        for record, truth, guess in zip(command.records, command.groundings, grounder.ground(command.records)):
            if guess != truth:
                out.append((command.number, record, truth, guess))
    return out

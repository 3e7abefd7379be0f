"""Text to plan: the language layer's chunk tree, grounded chunk by chunk, assembled.

:class:`CommandParser` holds a trained :class:`~assistant.language.LanguageModel` and a fitted
grounder; :meth:`CommandParser.parse` never raises on odd input — empty text, nonsense, only
fillers or unknown words give a plan whose ``unused`` and ``flags`` say what went wrong.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from assistant.errors import AssistantError
from assistant.grounding.labels import records_from_tree
from assistant.grounding.plan import assemble_plan, finish_flags, unused_words
from assistant.grounding.destination import said_destination
from assistant.grounding.motion import read_motion
from assistant.grounding.rooms import (first_named_room, identified_room, named_room_groundings, room_names_of,
                                       side_room_groundings)
from assistant.grounding.said import said_reference_groundings
from assistant.rdt import NO_TARGET
from assistant.grounding.types import ChunkGrounding, ChunkRecord, GroundingPlan
from assistant.language.retractions import without_retractions
from assistant.language.shorthand import expand_shorthand


#: longest command accepted, in words (a spoken fetch command has a few dozen)
MAX_WORDS = 200
#: longest command accepted, in characters, checked before any work (a pasted page would take
#: the tokenizer and tagger tens of seconds before the word count refused it)
MAX_CHARS = 2000


@dataclass
class ParseResult:
    """One parsed command: the language analysis, each chunk's grounding, and the plan."""

    analysis: object
    records: list[ChunkRecord]
    groundings: list[ChunkGrounding]
    plan: GroundingPlan

    def to_dict(self) -> dict:
        """The ``assistant parse --json`` fields (see DESIGN.md, command-line contract)."""
        a = self.analysis
        return {
            "text": a.text,
            "tokens": list(a.tokens),
            "pos": list(a.pos),
            "chunk_labels": list(a.chunk_labels),
            "tree": a.tree.to_dict(),
            "bracketed": a.tree.bracketed(),
            "plan": self.plan.to_dict(),
            "unused": list(self.plan.unused),
            "flags": list(self.plan.flags),
            "chunks": [{"label": r.label, "words": list(r.words), **g.to_dict()}
                       for r, g in zip(self.records, self.groundings)],
        }


class CommandParser:
    """Language model + grounder (+ optionally a world, to count same-word furniture)."""

    def __init__(self, language, grounder, world=None):
        self.language = language
        self.grounder = grounder
        self.world = world

    @classmethod
    def load(cls, grounder: str | None = None, corpus_paths=None, world=None) -> "CommandParser":
        """Train (or load from the cache) both layers from the corpus."""
        from assistant.grounding.training import DEFAULT_GROUNDER, split_corpus_paths, train_grounder
        try:
            from assistant.language import LanguageModel
        except ImportError:  # the package does not re-export it (yet)
            from assistant.language.pipeline import LanguageModel

        _, xmls = split_corpus_paths(corpus_paths)
        # descriptions given with --corpus train the tagger and chunker too; labels alone do not
        language = LanguageModel.load(xmls if corpus_paths is not None and xmls else None)
        return cls(language, train_grounder(grounder or DEFAULT_GROUNDER, corpus_paths), world)

    def ground_tree(self, tree, corrections: dict[str, str] | None = None
                    ) -> tuple[list[ChunkRecord], list[ChunkGrounding], GroundingPlan]:
        """Ground a chunk tree; ``corrections`` (typo → word, from the tagger) apply first."""
        records = records_from_tree(tree, getattr(self.world, "name", None))
        if corrections:
            records = [replace(r, words=tuple(corrections.get(w, w) for w in r.words)) for r in records]
        groundings = self.grounder.ground(records) if records else []
        # a room the home has, named in so many words, beats the grounder's guess among trained rooms
        groundings = named_room_groundings(records, groundings, self.world)
        # "the room on your right": the floor plan says which room that is in this home
        groundings = side_room_groundings(records, groundings, self.world)
        # a furniture reference no word names ("just ahead of you" → couch) is the listener
        groundings = said_reference_groundings(records, groundings)
        plan = assemble_plan(tree, groundings)
        if plan.room is None:  # "the laptop is on the table in the middle of the meeting room"
            plan.room = first_named_room(records, self.world)
        return records, groundings, plan

    def parse(self, text: str) -> ParseResult:
        """Parse and ground one command. Odd words never raise (they are listed in ``unused``);
        only a command longer than :data:`MAX_WORDS` words or :data:`MAX_CHARS` characters is
        refused."""
        if len(text or "") > MAX_CHARS:
            raise AssistantError(f"the command has {len(text)} characters, more than {MAX_CHARS}; "
                                 "say it as several shorter commands")
        # "go thru the livng rm": shorthand written out; "the bedroom, no wait, the office": the correction
        analysis = self.language.analyse(without_retractions(expand_shorthand(text or "")))
        if len(analysis.tokens) > MAX_WORDS:
            raise AssistantError(f"the command has {len(analysis.tokens)} words, more than {MAX_WORDS}; "
                                 "say it as several shorter commands")
        corrections = dict(getattr(analysis, "corrections", {}) or {})
        records, groundings, plan = self.ground_tree(analysis.tree, corrections)
        words = [corrections.get(str(t), str(t)) for t in analysis.tokens]
        moves = read_motion(words)
        if moves is not None:  # "turn left", "back up a little": the robot's own moves, nothing else
            plan = GroundingPlan(nodes=moves, kind="dynamic", flags=["motion"])
            return ParseResult(analysis, records, groundings, finish_flags(plan, words=len(analysis.tokens)))
        if plan.object is None:  # "go to the couch (by the table)": the furniture is the place
            said = said_destination(words, room_names_of(self.world))
            last = plan.nodes[-1] if plan.nodes else None
            if said is not None and (last is None or last.target == NO_TARGET or (said.referenced and (
                    last.target != said.target or not last.referenced))):
                plan.nodes, plan.support, plan.kind = [said], said.support, "static"
        if (named := identified_room(analysis.text, self.world)) is not None:  # "…, that's the office, …"
            plan.room = named
        plan.unused = unused_words(analysis.tree, getattr(self.grounder, "vocabulary_", frozenset()),
                                   analysis.unknown, corrections, plan)
        finish_flags(plan, words=len(analysis.tokens), world=self.world)
        return ParseResult(analysis, records, groundings, plan)

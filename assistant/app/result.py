"""The one outcome of every use case: a :class:`Result` with one :class:`Status` and a message.

A fetch, a "where is" and a teaching session all end in a :class:`Result`: ``status`` (the
executor's :class:`~assistant.executor.outcome.ExecutionStatus`, the product's one status
enum: ``success``, ``not_found``, ``no_room``, ``timeout``…), ``message`` (a sentence a person
can read), ``data`` (the command line's JSON fields for the use case, see the DESIGN's
command-line contract) and the typed values callers build on (the task's own report, the
description, what the robot saw and perceived).
"""

from __future__ import annotations

from dataclasses import dataclass, field

from assistant.executor.outcome import ExecutionStatus

__all__ = ["Result", "Status"]

#: the product's one status enum (the executor's, shared by every use case)
Status = ExecutionStatus


@dataclass
class Result:
    """What a use case did (module docstring).

    ``kind``: ``fetch``, ``where`` or ``teach``; ``status`` / ``message``: how it ended, in
    values and in words; ``data``: the JSON fields of ``assistant fetch|where|teach --json``;
    ``task``: the executor's :class:`~assistant.executor.reports.FetchResult` or
    :class:`~assistant.executor.search.SearchResult` (None when no robot task ran);
    ``description``: the :class:`~assistant.generation.types.GeneratedDescription` of a "where
    is"; ``seen``: the placed :class:`~assistant.perception.objects.Sighting` of every object
    the robot saw (the latest of each); ``furniture``: the furniture it had perceived at the
    end (entities, the environment model); ``object_seen``: whether the robot's own object
    detector saw the object asked about at the end; ``wall_seconds``: computer time.
    """

    kind: str
    status: Status
    message: str
    data: dict = field(default_factory=dict)
    task: object | None = None
    description: object | None = None
    seen: list = field(default_factory=list)
    furniture: list | None = None
    object: str | None = None
    object_seen: bool = False
    wall_seconds: float = 0.0

    @property
    def success(self) -> bool:
        return self.status is Status.SUCCESS

    @property
    def failure(self) -> str | None:
        """None on success, else the status's value (the ``failure`` JSON field)."""
        return None if self.success else self.status.value

    def to_dict(self) -> dict:
        """The command line's JSON object for this result (``data``)."""
        return dict(self.data)

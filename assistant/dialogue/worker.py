"""Running the conversation's robot tasks: one fetch or search at a time, in a worker thread.

A task takes the simulator seconds to minutes, so :meth:`TaskWorker.start` returns at once;
the worker speaks its progress through the conversation's ``say``, records every object the
robot sees into the memory (:class:`~assistant.dialogue.seen.SeenRecorder`), and ends with a
final :class:`~assistant.dialogue.turns.Turn` (composed by :mod:`assistant.dialogue.replies`).
"stop" sets the job's flag: the application layer stops the robot at its next call and the
task ends ``stopped``.
"""

from __future__ import annotations

import threading
import time
from dataclasses import dataclass

from assistant.app import Status, Stopped
from assistant.dialogue.clarify import activity_phrase, progress_sentence
from assistant.dialogue.replies import ReplyContext, fetch_reply, names_furniture, search_reply
from assistant.dialogue.seen import SeenRecorder
from assistant.dialogue.turns import Turn

__all__ = ["Job", "TaskWorker"]


@dataclass
class Job:
    """One task (``fetch`` or ``search``) in its worker thread."""

    stop: threading.Event
    thread: threading.Thread | None = None
    final: Turn | None = None
    kind: str = "fetch"
    #: what the robot is doing now, from the task's events (:func:`activity_phrase`)
    doing: str = ""
    started: float = 0.0  # time.monotonic() when the job started
    object: str | None = None  # the thing fetched or searched for
    quiet: bool = False  # replaced by another task: its end is not said (its final turn is still kept)
    #: what started it (``TaskWorker.start``'s arguments), so a stopped task can be carried on
    args: tuple = ()
    what: str = ""  # what it set out to do ("fetching the mug"), said when it is carried on
    said: str = ""  # the person's words that asked for it ("can you bring it to me?")


class TaskWorker:
    """Runs the tasks of ``conversation`` (a :class:`~assistant.dialogue.DialogueManager`:
    its ``world``, ``scene``, ``services``, ``memory``, ``say``, ``on_event``, ``on_pose`` and
    ``on_finish``; final turns go to its ``history`` and questions they leave to ``pending``)."""

    def __init__(self, conversation):
        self.conversation = conversation
        self.unreachable_said: set[str] = set()  # rooms already said to be out of reach
        self.job: Job | None = None

    @property
    def searching_for(self) -> str | None:
        """The thing the running task searches for, or None (no task, or a fetch)."""
        job = self.job
        return job.object if self.busy and job is not None and job.kind == "search" else None

    @property
    def busy(self) -> bool:
        """A task is running and has not been asked to stop."""
        job = self.job
        return job is not None and job.thread.is_alive() and not job.stop.is_set()

    @property
    def activity(self) -> tuple[str, float] | None:
        """While a task runs: what it is doing now and for how many seconds it has run (a front
        end's status line, see :class:`~assistant.dialogue.statusline.StatusLine`); else None."""
        job = self.job
        if job is None or not self.busy or job.final is not None:  # (final: its reply is being said)
            return None
        return job.doing, time.monotonic() - job.started

    def stop(self, quiet: bool = False) -> bool:
        """Ask the running task to stop; True when one was running. ``quiet``: another task
        replaces it, so its "I've stopped." is not said."""
        if self.busy:
            self.job.quiet = quiet
            self.job.stop.set()
            return True
        return False

    @property
    def stopped(self) -> Job | None:
        """The last task when a person stopped it (not when another task replaced it), else None."""
        job = self.job
        if job is None or self.busy or job.quiet or job.thread.is_alive() or job.final is None:
            return None
        return job if job.final.outcome == "stopped" else None

    def wait(self, timeout: float | None = None) -> Turn | None:
        """The last task's final turn once it has ended (None if none ran or it still runs); an
        errand's next step, started as a task ended, is waited for too."""
        deadline = None if timeout is None else time.monotonic() + timeout
        job = self.job
        while job is not None:
            job.thread.join(None if deadline is None else max(0.0, deadline - time.monotonic()))
            if job.thread.is_alive():
                return None
            if self.job is job:
                return job.final
            job = self.job  # the next step of an errand
        return None

    def close(self, timeout: float = 10.0) -> None:
        if self.job is not None:
            self.job.stop.set()
            self.job.thread.join(timeout)

    def start(self, kind: str, text: str, room: str | None, obj: str | None, style: str = "static",
              said: str = "") -> None:
        """Run a fetch (``text``: the command) or a search (``text``: the object) in a thread;
        ``said``: the person's own words that asked for it."""
        previous = self.job
        doing = f"looking for your {text}" if kind == "search" else (f"fetching the {obj}" if obj else "on my way")
        job = Job(threading.Event(), kind=kind, doing=doing, started=time.monotonic(),
                  object=text if kind == "search" else obj, args=(kind, text, room, obj, style), what=doing,
                  said=said)
        job.thread = threading.Thread(target=self._run, args=(job, previous, text, room, obj, style),
                                      name=f"assistant-{kind}", daemon=True)
        self.job = job
        job.thread.start()

    # ------------------------------------------------------------------ in the thread
    def speak(self, sentence: str) -> None:
        c = self.conversation
        c.last_said = sentence
        try:
            c.say(sentence)
        except Exception:  # a front end's problem must not kill the task
            pass

    def _events(self, job: Job, recorder: SeenRecorder, obj: str | None):
        """The task's event callback: the front end's view, memory, spoken progress; raises
        :class:`~assistant.app.Stopped` once the job is asked to stop."""
        c = self.conversation
        words = {f.id: f.word for f in c.world.scene(c.scene).furniture}
        announced: set[str] = set()

        def on_event(name: str, data: dict) -> None:
            if job.stop.is_set():
                raise Stopped()
            if c.on_event is not None:
                try:
                    c.on_event(name, data)
                except Exception:  # drawing is a courtesy
                    pass
            if name == "objects_seen":
                recorder.on_event(name, data)
                if job.kind == "search" and obj and obj in recorder.latest and obj not in announced:
                    announced.add(obj)
                    room = getattr(recorder.latest[obj][0], "room", None)  # seen through a door: its room
                    self.speak(f"I can see your {obj}" + (f", in the {room}!" if room else "!"))
            job.doing = activity_phrase(name, data) or job.doing
            sentence = progress_sentence(name, data, words)
            if name == "room_skipped":  # said once a conversation: the room will not open up
                if data.get("room") in self.unreachable_said:
                    sentence = None
                self.unreachable_said.add(data.get("room"))
            if name == "entered" and job.kind == "fetch" and not obj and job.args and job.args[2] == data.get("room") \
                    and not names_furniture(job.args[1]):
                sentence = None  # "go to the bedroom": its "Done — I'm in the bedroom." says it
            if sentence:
                self.speak(sentence)
            if job.stop.is_set():
                raise Stopped()

        return on_event

    def _run(self, job: Job, previous: Job | None, text: str, room: str | None, obj: str | None,
             style: str = "static") -> None:
        c = self.conversation
        start = time.perf_counter()
        if previous is not None:  # a stopped task winds down at its robot's next call
            previous.thread.join(30.0)
        recorder = SeenRecorder(c.memory, c.world.name, source=job.kind)
        before = c.memory.recall(c.world.name, obj) if obj else None
        on_event = self._events(job, recorder, obj)
        try:
            here = c.robot_pose  # where the last task left the robot (None: the world's start)
            if job.kind == "search":
                result = c.services.search(text, c.world, c.scene, on_event, stop=job.stop, on_pose=c.pose_listener,
                                           style=style, start=here)
            else:
                result = c.services.fetch(text, c.world.name, c.scene, on_event, stop=job.stop,
                                          on_pose=c.pose_listener, start=here)
        except Stopped:
            final = self._stopped(job, text, recorder, None, start)
        except Exception as error:  # noqa: BLE001 — any failure of the task becomes a reply, the chat goes on
            self._remember_seen(recorder, None)
            final = Turn(text, "command", f"Sorry, I couldn't do that ({error}).", job.kind, "failed",
                         {"command": text}, time.perf_counter() - start)
        else:
            final = self._final(job, text, result, recorder, obj, before, start)
        job.final = final
        c.history.append(final)
        if job.quiet:
            return
        self.speak(final.reply)
        if c.on_finish is not None:
            try:
                c.on_finish(final)
            except Exception:  # a front end's problem must not kill the worker
                pass
        try:
            if (after := getattr(c, "after_task", None)) is not None:
                after(final)  # an errand's next step starts here, in this thread's last moments
        except Exception as error:  # noqa: BLE001 — the next step's failure is said, the chat goes on
            self.speak(f"Sorry, I couldn't go on to the next step ({error}).")

    def _final(self, job: Job, text: str, result, recorder, obj, before, start: float) -> Turn:
        c = self.conversation
        try:
            if job.stop.is_set() or result.status is Status.STOPPED:
                return self._stopped(job, text, recorder, result.furniture, start)
            if job.kind == "search":  # where it was found
                found = getattr(result.task, "sighting", None)
                recorder.add([found] if result.success and found is not None else [])
            else:  # the final view's sightings too
                recorder.add(list(result.seen or []))
            summary = self._remember_seen(recorder, result.furniture)
            ctx = ReplyContext(c.world, c.scene, c.memory, c.services)
            if job.kind == "search":
                return search_reply(ctx, text, result, summary, start)
            turn, pending = fetch_reply(ctx, text, result, obj, start, summary, before, said=job.said)
            if pending is not None:
                c.pending = pending
            return turn
        except Exception as error:  # a bug here must still end the task with a reply
            return Turn(text, "error", f"Sorry, something went wrong inside me after the {job.kind} "
                        f"({type(error).__name__}: {error}).", job.kind, "failed", {"command": text},
                        time.perf_counter() - start)

    def _stopped(self, job: Job, text: str, recorder, furniture, start: float) -> Turn:
        summary = self._remember_seen(recorder, furniture)
        return Turn(text, "command", "I've stopped.", job.kind, "stopped",
                    {"command": text, "seen": summary["seen"]}, time.perf_counter() - start)

    def _remember_seen(self, recorder, furniture) -> dict:
        """Write what the task saw to memory (phrases composed from the perceived furniture)."""
        c = self.conversation
        try:
            return recorder.finish(furniture, c.services.describer, c.world.floorplan)
        except Exception as error:  # memory must not turn a finished task into a crash
            return {"seen": sorted(recorder.latest), "moved": [], "places": {}, "problem": str(error)}

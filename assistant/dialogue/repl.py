"""The terminal front end of ``assistant chat`` (see :mod:`assistant.cli.chat`)."""

from __future__ import annotations

import datetime as _dt
import json
import os
import sys
import threading
import time
from pathlib import Path

from assistant.dialogue.manager import DialogueManager
from assistant.dialogue.turns import Turn
from assistant.dialogue.memory import ObjectMemory, default_data_dir
from assistant.dialogue.services import Services
from assistant.errors import AssistantError
from assistant.fileio import PRIVATE_FILE_MODE, atomic_write_text, private_dir

PROMPT = "you> "


def _typed() -> str:
    """What has been typed at the prompt so far (readline's line; "" without readline)."""
    try:
        import readline
    except ImportError:
        return ""
    return readline.get_line_buffer()


class ChatSession:
    """One terminal conversation: reads lines, prints replies and progress, keeps the
    transcript (``transcripts/<UTC time>.json``, rewritten atomically after every turn)."""

    def __init__(self, args, stdin=None, stdout=None):
        from assistant.world import load_world

        self.stdin = stdin or sys.stdin
        self.out = stdout or sys.stdout
        self._prepared = False
        data = default_data_dir()
        self.world = load_world(args.world)
        self.scene = self.world.scene(args.scene).name
        self.memory = ObjectMemory(args.memory or data / "memory.json")
        stamp = _dt.datetime.now(_dt.timezone.utc).strftime("%Y%m%dT%H%M%S.%fZ")
        self.transcript_path = Path(args.transcripts or data / "transcripts") / f"{stamp}.json"
        if self.transcript_path.parent.exists() and not self.transcript_path.parent.is_dir():
            from assistant.errors import AssistantError

            raise AssistantError(f"the transcripts folder {self.transcript_path.parent} is a file; give a folder "
                                 "with --transcripts (or set ASSISTANT_DATA to a folder)")
        self.history_path = data / "chat_history"
        self.services = Services(perception=args.perception, seed=args.seed,
                                 search=getattr(args, "search", "sensed"), robot=getattr(args, "robot", "sim"))
        self._check_robot()
        self.view = None
        self._print_lock = threading.RLock()
        self._interrupts = 0
        self._interrupt_lock = threading.Lock()
        self._reading = False
        self._reading_since = 0.0
        self._leaving_wait = False  # Ctrl-D came while the robot works: waiting for it to finish
        self._leaving = False
        self.interactive = self.stdin.isatty()
        self.records: list[dict] = []
        # hooks for other front ends (speech): where utterances come from, and who else hears
        # what the robot says; None: the terminal alone
        self.read_line = None  # () -> str, raising EOFError at the end
        self.speak = None  # (sentence) -> None
        self.status = None  # the ticking status line while the robot works (a terminal's prompt only)
        self.manager = DialogueManager(self.world, self.scene, self.services, self.memory, say=self._progress,
                                       on_finish=self._finished)
        if getattr(args, "view", False):
            self._open_view()

    # ----------------------------------------------------------------- output
    def _print(self, text: str, redraw: bool = False) -> None:
        with self._print_lock:
            if redraw and self.interactive and self._reading:
                erase = self.status.erase() if self.status is not None else "\r\033[K"
                self.out.write(erase + text + "\n" + PROMPT + _typed())
            elif self.status is not None and self.status.drawn:  # waiting to leave: no prompt below
                self.out.write(self.status.erase() + text + "\n")
            else:
                self.out.write(text + "\n")
            self.out.flush()

    def _progress(self, sentence: str) -> None:
        self._say(sentence, redraw=True)

    def show(self, text: str) -> None:
        """Print a line of the session (a front end's note, e.g. what speech input heard)."""
        self._print(text, redraw=True)

    def say(self, sentence: str) -> None:
        """The robot says ``sentence``: printed, and passed to the ``speak`` hook."""
        self._say(sentence, redraw=True)

    def _say(self, sentence: str, redraw: bool = False, label: str = "robot: ") -> None:
        """Print what the robot says (and pass it to the ``speak`` hook)."""
        self._print(f"{label}{sentence}", redraw=redraw)
        if self.speak is not None:
            try:
                self.speak(sentence)
            except Exception as error:  # speech out failing must not end the chat
                self.speak = None
                self._print(f"(speech output off: {error})")

    def _finished(self, turn: Turn) -> None:
        self._record(turn)
        if self.view is not None and turn.data.get("final_pose"):
            try:
                self.view.draw_robot(turn.data["final_pose"])
                target = (turn.data.get("target_furniture") or {}).get("id")
                if target:
                    self.view.highlight(target)
            except Exception:
                pass

    def _record(self, turn: Turn) -> None:
        entry = {"time": _dt.datetime.now(_dt.timezone.utc).isoformat(timespec="milliseconds")} | turn.to_dict()
        self.records.append(entry)
        try:
            private_dir(self.transcript_path.parent)
            atomic_write_text(self.transcript_path, json.dumps(
                {"world": self.world.name, "scene": self.scene, "turns": self.records}, indent=1) + "\n",
                mode=PRIVATE_FILE_MODE)
        except OSError as error:
            self._print(f"(could not save the transcript: {error})")

    # ----------------------------------------------------------------- 3D view
    def _open_view(self) -> None:
        try:
            from assistant.viz import SceneView

            self.view = SceneView()
            self.view.draw_world(self.world, self.scene, robot_pose=self.world.start)
            self.view.draw_robot(self.world.start)
            self.manager.on_pose = lambda pose: self.view.draw_robot(pose)
            self._print(f"3D view: {self.view.url}")
        except Exception as error:  # the chat works without the view
            self.view = None
            self._print(f"(no 3D view: {error})")

    # ----------------------------------------------------------------- the loop
    def _setup_readline(self):
        if not self.interactive:
            return None
        try:
            import readline
        except ImportError:
            return None
        try:
            readline.read_history_file(self.history_path)
        except (OSError, FileNotFoundError):
            pass
        readline.set_history_length(1000)
        return readline

    def _save_history(self, readline) -> None:
        if readline is None:
            return
        try:
            private_dir(self.history_path.parent)
            readline.write_history_file(self.history_path)
            os.chmod(self.history_path, PRIVATE_FILE_MODE)
        except OSError:
            pass

    def _read(self) -> str:
        if self.read_line is not None:
            return self.read_line()
        if self.interactive:
            try:
                return input(PROMPT)
            except UnicodeDecodeError:  # bytes that are not UTF-8 typed or pasted
                self._print("(that line was not UTF-8 text; type it again)")
                return ""
        self.out.write(PROMPT)
        self.out.flush()
        buffer = getattr(self.stdin, "buffer", None)  # piped bytes that are not UTF-8 become �, not a crash
        line = self.stdin.readline() if buffer is None else buffer.readline().decode("utf-8", "replace")
        if not line:
            raise EOFError
        return line.rstrip("\n")

    def prepare(self) -> None:
        """Load the parser (every reply needs it; from the cache about a second on an idle
        machine) and start loading the rest in the background, so the first reply does not wait
        for it. :meth:`loop` calls it if the caller has not (the command line does, behind a
        progress line)."""
        if self._prepared:
            return
        self._prepared = True
        try:
            self.services.parser(self.world)
        except AssistantError as error:  # said again when the parser is used
            self._print(f"(language models: {error})")
        self.services.warm_up(self.world, background=True, scene=self.scene)

    def loop(self) -> int:
        self.prepare()
        readline = self._setup_readline()
        self._say(self.manager.greeting(), label="")
        if self.memory.load_problem:
            self._print(f"(memory: {self.memory.load_problem})")
        self._print("(Ctrl-C stops the robot, Ctrl-C twice leaves, Ctrl-D leaves; transcript: "
                    f"{self.transcript_path})")
        from assistant.dialogue.interrupts import InterruptWatcher

        watcher = InterruptWatcher(self._on_interrupt, lambda: self._reading)
        try:
            watcher.start()
            self._start_status()
            while not self._leaving:
                try:
                    self._reading, self._reading_since = True, time.monotonic()
                    if self._leaving:  # a second Ctrl-C came while the last line was handled
                        break
                    line = self._read()
                except KeyboardInterrupt:  # the watcher wants the loop to look at _leaving
                    continue
                except EOFError:
                    self._end_of_input()
                    break
                finally:
                    self._reading = False
                    if self.status is not None:
                        self.status.left_prompt()
                with self._interrupt_lock:
                    self._interrupts = 0
                if not line.strip():
                    continue
                try:
                    if self.scripted and self.manager.busy and not self.manager.about_the_task(line):
                        # a question read from a file or a pipe is about what the task before it
                        # found ("where's my hearing aid?" after "it's on the bed"): as a person
                        # would, it waits for that task; "stop" or "what are you doing?" do not
                        self.manager.wait()
                    turn = self.manager.handle(line)
                    if self.scripted and (turn.outcome == "busy" or (turn.action == "leave" and self.manager.busy)):
                        # lines read from a file or a pipe come faster than the robot moves: a
                        # command (or the goodbye) waits for the task before it, as a person would
                        self.manager.wait()
                        if turn.outcome == "busy":
                            turn = self.manager.handle(line)
                    self._record(turn)
                    if turn.reply:
                        self._say(turn.reply)
                    if self.scripted and turn.outcome == "stopped":  # its "I've stopped." before the next line
                        self.manager.wait(10.0)
                    if turn.action == "teach" and turn.outcome == "started":
                        self._teach(turn)
                    if turn.action == "leave":  # "bye": the reply said goodbye
                        break
                except KeyboardInterrupt:  # Ctrl-C without the watcher (not the main thread)
                    self._on_interrupt()
                    continue
            if self._leaving:
                self._print("\nGoodbye.")
        finally:
            watcher.stop()
            if self.status is not None:
                self.status.stop()
            self.manager.close(timeout=5.0)
            self._save_history(readline)
            if self.view is not None:
                self.view.close()
        return 0

    def _check_robot(self) -> None:
        """A real robot is connected once before the greeting, so that a wrong port or a robot
        switched off is said at once (it had greeted as if all was well and failed the first
        task); each task then connects again."""
        from assistant.robot import parse_robot_spec

        if parse_robot_spec(self.services.robot).scheme != "p3dx":
            return
        from assistant.app import open_robot

        with open_robot(self.services.robot, self.world, self.scene):
            pass

    @property
    def scripted(self) -> bool:
        """Lines come from a file or a pipe, not a person at a terminal or a microphone."""
        return not self.interactive and self.read_line is None

    def _start_status(self) -> None:
        """While the robot works, a ticking line above the typed prompt says what it is doing
        (:mod:`~assistant.dialogue.statusline`): where progress is shown (a terminal), and not
        when another front end (speech) reads the utterances."""
        from assistant.dialogue.statusline import StatusLine
        from assistant.progress import shows_progress

        if self.interactive and self.read_line is None and shows_progress(stream=self.out):
            self.status = StatusLine(self.out, self._print_lock, PROMPT, lambda: self.manager.activity,
                                     self._at_prompt, _typed).start()

    def _at_prompt(self) -> bool:
        """The prompt is on screen, waiting (``input`` draws it just after ``_reading`` is set),
        or the chat waits for the robot before it leaves (the status line then has no prompt)."""
        return self._leaving_wait or (self._reading and time.monotonic() - self._reading_since > 0.2)

    def _on_interrupt(self) -> bool:
        """Ctrl-C (called by the watcher thread the moment it arrives): the first stops the
        robot, a second in a row leaves. True when the loop must leave its read."""
        with self._interrupt_lock:
            self._interrupts += 1
            leaving = self._interrupts >= 2
            if leaving:
                self._leaving = True
        if leaving:
            self.manager.stop()
            return True
        if self.manager.stop():
            self._print("robot: Stopping. (Ctrl-C again to leave)", redraw=True)
        else:
            self._print("(Ctrl-C again to leave)", redraw=True)
        return False

    def _end_of_input(self) -> None:
        self._reading = False  # (called inside the read's except: the robot's sentences now come
        if self.status is not None:  # without a prompt under them)
            self.status.left_prompt()
        if self.manager.busy:
            self._print("\n(waiting for the robot to finish; Ctrl-C stops it)")
            if self.status is not None:  # its status line goes on ticking, with no prompt under it
                self.status.prompt, self._leaving_wait = "", True
            self.manager.wait()
            self._leaving_wait = False
        self._print("\nGoodbye.")

    def _teach(self, turn: Turn) -> None:
        """Record the demonstration (``assistant teach``'s session) right here."""
        try:
            from assistant.policy.teaching import run_teaching

            outcome = run_teaching(turn.data["rdt"], self.world.name, self.scene,
                                   echo=lambda text: self._print(text))
        except Exception as error:
            self._print(f"robot: Sorry, I couldn't record that ({error}).")
            return
        if outcome.saved is None:
            reply = "OK, I didn't save anything."
        else:
            reply = f"Thank you — I've saved that demonstration ({outcome.saved})."
        done = Turn("(demonstration)", "teach", reply, "teach", "success" if outcome.saved else "cancelled",
                    {"rdt": turn.data["rdt"], "saved": None if outcome.saved is None else str(outcome.saved)})
        self.manager.last_said = reply
        self._record(done)
        self._print(f"robot: {reply}")

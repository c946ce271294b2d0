"""A RoboSim JVM this package starts and talks to over one of its MessagePack links: the learning host
(``robosim.rl``) and the simulation host (``robosim.testing``). Where RoboSim is, the process started by its script
with a fresh secret, the first line that says where it listens, its output kept for errors, and its end."""

from __future__ import annotations

import collections
import os
import re
import secrets
import signal
import socket
import subprocess
import sys
import threading
from pathlib import Path
from typing import Any

from robosim.frames import Frames, LinkError

#: How long a host gets to say where it listens (a first use may build RoboSim: ``./mvnw`` once).
START_S = 300.0


class HostError(LinkError):
    """A host could not start, refused what it was asked, or broke."""


def find_home(near: Path | None = None) -> Path:
    """RoboSim's checkout: ``$ROBOSIM_HOME``, else the first folder holding ``scripts/common.sh`` above ``near`` (an
    environment file's folder) or the working directory."""
    given = os.environ.get("ROBOSIM_HOME")
    if given:
        home = Path(given)
        if not (home / "scripts/common.sh").is_file():
            raise HostError(f"ROBOSIM_HOME={given}: no scripts/common.sh there (a RoboSim checkout)")
        return home
    starts = [p for p in (near, Path.cwd()) if p is not None]
    for start in starts:
        for folder in [start.resolve(), *start.resolve().parents]:
            if (folder / "scripts/common.sh").is_file():
                return folder
    raise HostError(
        "cannot find RoboSim (scripts/common.sh) above " + " or ".join(str(s) for s in starts)
        + ": set ROBOSIM_HOME to a RoboSim checkout")


class HostProcess:
    """``scripts/SCRIPT`` of RoboSim started with ``arguments`` and a fresh ``ROBOSIM_LINK_KEY``; ``where`` is the
    match of ``listening`` on its first such line. Its output is kept (its last lines, for errors) and drained."""

    def __init__(self, home: Path, script: str, arguments: list[str], listening: re.Pattern[str], called: str,
                 env: dict[str, str] | None = None) -> None:
        self.key = secrets.token_hex(16)
        self.called = called
        command = ["bash", str(home / "scripts" / script), *arguments]
        environment = dict(os.environ if env is None else env, ROBOSIM_LINK_KEY=self.key)
        self.process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                        stdin=subprocess.DEVNULL, env=environment, text=True, errors="replace",
                                        start_new_session=True)  # (a terminal's Ctrl-C is this process's to handle)
        self._output: collections.deque[str] = collections.deque(maxlen=40)
        self._sock: socket.socket | None = None
        try:
            self.where = self._listening(listening)
        except BaseException:
            self.stop()
            raise
        threading.Thread(target=self._drain, name=f"{script}-output", daemon=True).start()

    def _listening(self, listening: re.Pattern[str]) -> re.Match[str]:
        assert self.process.stdout is not None
        found: list[re.Match[str]] = []
        done = threading.Event()

        def read() -> None:
            assert self.process.stdout is not None
            for line in self.process.stdout:
                m = listening.search(line)
                if m:
                    found.append(m)
                    break
                self._output.append(line.rstrip("\n"))
            done.set()

        reader = threading.Thread(target=read, name=f"{self.called}-start", daemon=True)
        reader.start()
        done.wait(START_S)
        if not found:
            raise HostError(f"the {self.called} did not start" + self.said())
        reader.join()
        return found[0]

    def connect(self, host: str, port: int, timeout_s: float) -> Frames:
        """A connection to the host's link (its reads wait up to ``timeout_s``), as frames."""
        self._sock = socket.create_connection((host, port), timeout=timeout_s)
        self._sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        return Frames(self._sock)

    def _drain(self) -> None:
        """Keeps the host's output for errors, and passes its warnings and errors on to this process's stderr (the
        end of a simulation's parameter warnings among them: a test's output shows them)."""
        assert self.process.stdout is not None
        for line in self.process.stdout:
            kept = line.rstrip("\n")
            self._output.append(kept)
            if " WARN " in kept or " ERROR " in kept:
                print(f"{self.called}: {kept}", file=sys.stderr, flush=True)

    def said(self) -> str:
        """The host's last lines of output, for an error: ``": line | line"``, or nothing."""
        lines = [line for line in self._output if line.strip()]
        return (": " + " | ".join(lines[-8:])) if lines else ""

    def receive(self, frames: Frames) -> Any:
        """The next frame from the host; a HostError (with what it said) once the link broke."""
        try:
            return frames.receive()
        except (OSError, LinkError) as e:
            self.stop()
            raise HostError(f"the {self.called}'s link broke ({e}){self.said()}") from e

    def send(self, frames: Frames, value: Any) -> None:
        try:
            frames.send(value)
        except OSError as e:
            self.stop()
            raise HostError(f"the {self.called}'s link broke ({e}){self.said()}") from e

    @property
    def stopped(self) -> bool:
        """Whether the host has ended (stopped here, or exited on its own: its link is gone)."""
        return self.process.poll() is not None

    def stop(self) -> None:
        """The link closed (the host, reading, sees its end) and the host waited for (killed after 10 s)."""
        if self._sock is not None:
            try:
                # (a close alone leaves the connection open: the Frames file holds it)
                self._sock.shutdown(socket.SHUT_RDWR)
            except OSError:
                pass
            self._sock.close()
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            try:
                os.killpg(self.process.pid, signal.SIGKILL)  # (its own session: the script and the JVM it started)
            except ProcessLookupError:
                pass
            self.process.wait()

"""The learning host: K copies of a world in one JVM (``scripts/learning-host.sh``), started by this package, and the
learning link to it: one exchange a step for every robot of every world, its arrays little-endian binaries that numpy
views in place (``numpy.frombuffer``: no decoding number by number)."""

from __future__ import annotations

import collections
import os
import re
import secrets
import socket
import subprocess
import threading
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from robosim.frames import Frames, LinkError

#: The link's name and version, as the hello says them.
LINK = "robosim-batch-link"
VERSION = 2
#: How long the host gets to say where it listens (a first use may build RoboSim: ``./mvnw`` once).
START_S = 300.0
#: How long a step may take before the link is taken for broken (a step of 1024 worlds of many robots is seconds).
STEP_S = 600.0
_LISTENING = re.compile(r"robosim-batch-link listening on ([0-9.]+):(\d+)(?: viewers=(\d+))?(?: web=(\d+))?")


class HostError(LinkError):
    """The learning host could not start, refused what it was asked, or broke."""


@dataclass(frozen=True)
class Welcome:
    """What the host says of its batch: the worlds, their robots and limits, the arrays' shapes."""

    world: str
    worlds: int
    robots: list[str]
    types: list[str]
    sonars: int
    sonar_angles_deg: list[list[float]]
    sonar_max_mm: list[float]
    max_speed_mm_s: list[float]
    max_turn_deg_s: list[float]
    step_ms: int
    repeat: int
    message_size: int
    metrics: list[str]
    arena_mm: list[float]
    seed: int
    episode_metric: str | None
    #: Whether the world has loop functions: then ``Batch.finished`` says where they ended its experiment.
    loop_functions: bool
    #: Each robot's sensors (its environment file's, with ``sensors=True``), in its file's order: name, offset (its
    #: first column of ``Batch.readings``), type, count, low and high (a list of count bounds: a group's fields, such
    #: as a message's range, bearing and bytes, each have their own), unit.
    sensors: list[list[dict[str, Any]]]
    #: Columns of a robot's row of ``Batch.readings`` (0: no robot has a sensor, no readings array).
    readings: int
    #: Fields of a robot's action: 2 velocities, the message's numbers, then its devices' (``actuators=True``).
    action_fields: int
    #: Each robot's devices it acts through (``actuators=True``): name (``gripper``: above 0.5 grips, below -0.5
    #: lets go; ``leds``: a colour 0xRRGGBB an LED; ``rab``: a message's bytes), offset (its first field in the
    #: robot's action), count, low, high; a value beyond them is held to them, rounded where the device takes whole
    #: numbers.
    actuators: list[list[dict[str, Any]]]


@dataclass(frozen=True)
class Batch:
    """One step's arrays (views of the reply, read-only), world by world, robot by robot."""

    steps: np.ndarray  # int64 (K,): time steps since each world's episode began
    sonar: np.ndarray  # float32 (K, N, S), mm: each robot's sonars, 0 beyond its own
    pose: np.ndarray  # float32 (K, N, 3): x mm, y mm, heading degrees (0 to 360)
    contact: np.ndarray  # uint8 (K, N): 1 if the robot touched something during the action
    metrics: np.ndarray  # float64 (K, M): each world's metrics so far (Welcome.metrics: built-ins, loop metrics)
    messages: np.ndarray | None  # float32 (K, N, N, m): the last message robot i heard from robot j, or zeros
    readings: np.ndarray | None  # float32 (K, N, R): each robot's sensors, a block of columns each (Layout)
    finished: np.ndarray | None  # uint8 (K,): 1 where the world's loop functions ended its experiment (finished, end)


def find_home(near: Path | None = None) -> Path:
    """RoboSim's checkout: ``$ROBOSIM_HOME``, else the first folder holding ``scripts/learning-host.sh`` above
    ``near`` (an environment file) or the working directory."""
    given = os.environ.get("ROBOSIM_HOME")
    if given:
        home = Path(given)
        if not (home / "scripts/learning-host.sh").is_file():
            raise HostError(f"ROBOSIM_HOME={given}: no scripts/learning-host.sh there (a RoboSim checkout)")
        return home
    starts = [p for p in (near, Path.cwd()) if p is not None]
    for start in starts:
        for folder in [start.resolve(), *start.resolve().parents]:
            if (folder / "scripts/learning-host.sh").is_file():
                return folder
    raise HostError(
        "cannot find RoboSim (scripts/learning-host.sh) above " + " or ".join(str(s) for s in starts)
        + ": set ROBOSIM_HOME to a RoboSim checkout")


class LearningHost:
    """A started learning host and the link to it. ``close()`` (or ``with``) says bye and waits for it to end."""

    def __init__(self, path: str | os.PathLike[str], *, worlds: int = 1, repeat: int = 1, message_size: int = 0,
                 sensors: bool = False, actuators: bool = False, random_headings: bool = False,
                 area_cell_m: float | None = None,
                 threads: int | None = None,
                 episode_metric: str | None = None, loop_metrics: Sequence[str] = (), web_port: int | None = None,
                 viewer_port: int | None = None, params: dict[str, str] | None = None,
                 robosim_home: str | os.PathLike[str] | None = None) -> None:
        file = Path(path)
        if not file.is_file():
            raise HostError(f"{file}: no such environment file")
        home = Path(robosim_home) if robosim_home is not None else find_home(file.parent)
        command = ["bash", str(home / "scripts/learning-host.sh"), "--env", str(file.resolve()),
                   "--worlds", str(worlds), "--repeat", str(repeat), "--message-size", str(message_size)]
        if sensors:
            command.append("--sensors")
        if actuators:
            command.append("--actuators")
        if random_headings:
            command.append("--random-headings")
        if area_cell_m is not None:
            command += ["--area-cell-m", str(area_cell_m)]
        if threads is not None:
            command += ["--threads", str(threads)]
        if episode_metric is not None:
            command += ["--episode-metric", episode_metric]
        for name in loop_metrics:
            command += ["--loop-metric", name]
        if web_port is not None:
            command += ["--web-port", str(web_port)]
        if viewer_port is not None:
            command += ["--viewer-port", str(viewer_port)]
        for name, value in (params or {}).items():
            command += ["--param", f"{name}={value}"]
        key = secrets.token_hex(16)
        env = dict(os.environ, ROBOSIM_LINK_KEY=key)
        self._process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                         stdin=subprocess.DEVNULL, env=env, text=True, errors="replace")
        self._output: collections.deque[str] = collections.deque(maxlen=40)
        self._closed = False
        try:
            self._connect(key)
        except BaseException:
            self._stop()
            raise

    def _connect(self, key: str) -> None:
        """Where the host listens (its first line), the hello, the welcome checked: the batch's shapes."""
        where = self._listening()
        host, port = where.group(1), int(where.group(2))
        self.viewer_port = int(where.group(3)) if where.group(3) else None
        self.web_port = int(where.group(4)) if where.group(4) else None
        threading.Thread(target=self._drain, name="learning-host-output", daemon=True).start()
        self._sock = socket.create_connection((host, port), timeout=STEP_S)
        self._sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self._frames = Frames(self._sock)
        self._frames.send({"link": LINK, "version": VERSION, "key": key})
        answer = self._receive()
        if not isinstance(answer, dict) or "error" in answer:
            why = answer.get("error") if isinstance(answer, dict) else answer
            raise HostError(f"the learning host refused the hello: {why!r:.300}")
        fields = list(Welcome.__dataclass_fields__)
        if answer.get("link") != LINK or answer.get("version") != VERSION or any(f not in answer for f in fields):
            raise HostError(f"a welcome that is not a learning link's version {VERSION} (another RoboSim's host?): "
                            f"{sorted(answer)!r:.300}")
        self.welcome = Welcome(**{f: answer[f] for f in fields})
        w = self.welcome
        n = len(w.robots)
        shapes = [("steps", "<i8", (w.worlds,)), ("sonar", "<f4", (w.worlds, n, w.sonars)),
                  ("pose", "<f4", (w.worlds, n, 3)), ("contact", "u1", (w.worlds, n)),
                  ("metrics", "<f8", (w.worlds, len(w.metrics)))]
        if w.message_size:
            shapes.append(("messages", "<f4", (w.worlds, n, n, w.message_size)))
        if w.readings:
            shapes.append(("readings", "<f4", (w.worlds, n, w.readings)))
        if w.loop_functions:
            shapes.append(("finished", "u1", (w.worlds,)))
        #: Each array of a reply: its name, type, shape and size in bytes (Batch's fields, in order).
        self._arrays = [(name, dtype, shape, int(np.prod(shape)) * np.dtype(dtype).itemsize)
                        for name, dtype, shape in shapes]
        self._action_shape = (w.worlds, n, w.action_fields)

    def _listening(self) -> re.Match[str]:
        assert self._process.stdout is not None
        found: list[re.Match[str]] = []
        done = threading.Event()

        def read() -> None:
            assert self._process.stdout is not None
            for line in self._process.stdout:
                m = _LISTENING.search(line)
                if m:
                    found.append(m)
                    break
                self._output.append(line.rstrip("\n"))
            done.set()

        reader = threading.Thread(target=read, name="learning-host-start", daemon=True)
        reader.start()
        done.wait(START_S)
        if not found:
            raise HostError("the learning host did not start" + self._said())
        reader.join()
        return found[0]

    def _drain(self) -> None:
        assert self._process.stdout is not None
        for line in self._process.stdout:
            self._output.append(line.rstrip("\n"))

    def _said(self) -> str:
        lines = [line for line in self._output if line.strip()]
        return (": " + " | ".join(lines[-8:])) if lines else ""

    def _receive(self) -> Any:
        try:
            return self._frames.receive()
        except (OSError, LinkError) as e:
            self._stop()
            raise HostError(f"the learning link broke ({e}){self._said()}") from e

    def _call(self, request: list[Any]) -> Batch:
        if self._closed:
            raise HostError("the learning host is closed")
        try:
            self._frames.send(request)
        except OSError as e:
            self._stop()
            raise HostError(f"the learning link broke ({e}){self._said()}") from e
        answer = self._receive()
        if not isinstance(answer, list) or not answer:
            raise HostError(f"an answer that is not one: {answer!r:.200}")
        if answer[0] == "error":
            raise HostError(f"the learning host refused {request[0]}: {answer[2] if len(answer) > 2 else answer}")
        arrays = answer[1]
        if not isinstance(arrays, dict):
            raise HostError(f"an answer that is not one: {answer!r:.200}")
        views: dict[str, np.ndarray | None] = {"messages": None, "readings": None, "finished": None}
        for name, dtype, shape, size in self._arrays:
            data = arrays.get(name)
            if not isinstance(data, bytes) or len(data) != size:
                raise HostError(f"the host's {name} is not {dtype} {shape}")
            views[name] = np.frombuffer(data, dtype=dtype).reshape(shape)
        return Batch(**views)

    def reset(self, seeds: list[int | None]) -> Batch:
        """World w begins a new episode with ``seeds[w]`` (None: it stays as it is, not stepped); every world's
        arrays."""
        return self._call(["reset", [None if s is None else int(s) for s in seeds]])

    def step(self, actions: np.ndarray, resets: dict[int, int] | None = None) -> Batch:
        """Every robot of every world acts (``actions``: float32 (K, N, Welcome.action_fields): mm/s, deg/s, message,
        devices); the worlds in ``resets`` begin a new episode with the seed given instead."""
        if actions.shape != self._action_shape:
            raise ValueError(f"actions of shape {actions.shape}; this batch takes {self._action_shape}")
        data = actions.astype("<f4", copy=False).tobytes()
        return self._call(["step", data, {int(w): int(s) for w, s in resets.items()} if resets else None])

    def measure(self, worlds: list[int]) -> list[float]:
        """The episode metric (``episode_metric``) over each of ``worlds``' episodes so far, from their recordings."""
        if self._closed:
            raise HostError("the learning host is closed")
        try:
            self._frames.send(["measure", [int(w) for w in worlds]])
        except OSError as e:
            self._stop()
            raise HostError(f"the learning link broke ({e}){self._said()}") from e
        answer = self._receive()
        if not isinstance(answer, list) or not answer or answer[0] != "ok" or len(answer[1]) != len(worlds):
            raise HostError(f"the learning host refused measure: {answer[2] if len(answer) > 2 else answer}")
        return [float(v) for v in answer[1]]

    def close(self) -> None:
        """Says bye and waits for the host to exit."""
        if self._closed:
            return
        self._closed = True
        try:
            self._frames.send(["bye"])
            self._frames.receive()
        except (OSError, LinkError):
            pass
        self._stop()

    def _stop(self) -> None:
        """The link closed (the host, reading, sees its end) and the host waited for (killed after 10 s)."""
        self._closed = True
        sock = getattr(self, "_sock", None)
        if sock is not None:
            try:
                sock.shutdown(socket.SHUT_RDWR)  # (a close alone leaves the connection open: Frames' file holds it)
            except OSError:
                pass
            sock.close()
        try:
            self._process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self._process.kill()
            self._process.wait()

    def __enter__(self) -> LearningHost:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

"""The learning host: K copies of a world in one JVM (``scripts/learning-host.sh``), started by this package, and the
learning link to it: one exchange a step for every robot of every world, its arrays little-endian binaries that numpy
views in place (``numpy.frombuffer``: no decoding number by number)."""

from __future__ import annotations

import os
import re
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from robosim.frames import LinkError
from robosim.hostprocess import HostError, HostProcess, find_home

#: The link's name and version, as the hello says them.
LINK = "robosim-batch-link"
VERSION = 2
#: How long a step may take before the link is taken for broken (a step of 1024 worlds of many robots is seconds).
STEP_S = 600.0
_LISTENING = re.compile(r"robosim-batch-link listening on ([0-9.]+):(\d+)(?: viewers=(\d+))?(?: web=(\d+))?")


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
        command = ["--env", str(file.resolve()), "--worlds", str(worlds), "--repeat", str(repeat),
                   "--message-size", str(message_size)]
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
        self._closed = False
        self._host = HostProcess(home, "learning-host.sh", command, _LISTENING, "learning host")
        try:
            self._connect()
        except BaseException:
            self._stop()
            raise

    def _connect(self) -> None:
        """Where the host listens (its first line), the hello, the welcome checked: the batch's shapes."""
        where = self._host.where
        host, port = where.group(1), int(where.group(2))
        self.viewer_port = int(where.group(3)) if where.group(3) else None
        self.web_port = int(where.group(4)) if where.group(4) else None
        self._frames = self._host.connect(host, port, STEP_S)
        self._frames.send({"link": LINK, "version": VERSION, "key": self._host.key})
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

    def _receive(self) -> Any:
        return self._host.receive(self._frames)

    def _call(self, request: list[Any]) -> Batch:
        if self._closed:
            raise HostError("the learning host is closed")
        self._host.send(self._frames, request)
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
        self._host.send(self._frames, ["measure", [int(w) for w in worlds]])
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
        """The link closed and the host waited for (killed after 10 s)."""
        self._closed = True
        self._host.stop()

    def __enter__(self) -> LearningHost:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

"""Python controllers tested like any Python code: a whole simulation, run and asked from a test, as the Java
testkit (``robosim.testkit.Simulation``) does it. A world file, or a world built in code, runs in a RoboSim JVM this
module starts once (``scripts/simulation-host.sh``, the simulation link), its robots' Python controllers as in any
run; the test steps it and asks where each robot is, what it sensed, received, touched and reported.

    from robosim.testing import Simulation

    def test_the_square_comes_back() -> None:
        with Simulation.of("square.xml").seed(3).start() as sim:
            sim.run(200)
            assert sim.pose("robot1").x_mm > 1000

A robot whose control code raises fails the test: the next ``run`` or ``close`` raises ``ControlFailed`` (an
``AssertionError``) naming the robot and the step, with its traceback, unless the test said it expects it
(``expect_failure``). With pytest, the fixture ``simulation`` (this package's pytest plugin) closes what a test
started."""

from __future__ import annotations

import atexit
import os
import re
import shutil
import sys
import tempfile
import threading
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any
from xml.sax.saxutils import quoteattr

from robosim.frames import Frames
from robosim.hostprocess import HostError, HostProcess, find_home
from robosim.robot import Pose

__all__ = ["Contact", "ControlFailed", "Failure", "HostError", "Pose", "Received", "Simulation", "SimulationBuilder",
           "SimulationHost", "World", "shared_host"]

#: The link's name and version, as the hello says them.
LINK = "robosim-simulation-link"
VERSION = 1
#: How long one request may take before the link is taken for broken (a run of many steps takes long).
CALL_S = 3600.0
_LISTENING = re.compile(r"robosim-simulation-link listening on ([0-9.]+):(\d+)")


@dataclass(frozen=True)
class Received:
    """A message a robot received: the step whose response carried it, who sent it, its text."""

    step: int
    sender: str
    text: str


@dataclass(frozen=True)
class Contact:
    """A robot touched something during ``step``: a wall, an obstacle or a robot, by name."""

    step: int
    touched: str


@dataclass(frozen=True)
class Failure:
    """What a robot's control code raised, at which step (steps completed), and its whole traceback."""

    robot: str
    step: int
    summary: str
    traceback: str


class ControlFailed(AssertionError):
    """Control code of a robot the test did not expect to fail raised: the first failure's robot, step and
    traceback in the message; every one in ``failures``."""

    def __init__(self, failures: list[Failure]) -> None:
        self.failures = failures
        first = failures[0]
        others = f" (and {len(failures) - 1} more: {', '.join(f.robot for f in failures[1:])})" if failures[1:] else ""
        super().__init__(f"robot {first.robot}: its control code failed at step {first.step}: {first.summary}{others}"
                         f"\n{first.traceback}\n(expect_failure(\"{first.robot}\") if the test expects it)")


class SimulationHost:
    """A RoboSim JVM that runs simulations for this process (``scripts/simulation-host.sh``) and the simulation link
    to it. Its robots' Python controllers run with this interpreter (``sys.executable``) unless ``ROBOSIM_PYTHON``
    says otherwise. ``close()`` (or ``with``) says bye and waits for it to end."""

    def __init__(self, robosim_home: str | os.PathLike[str] | None = None, near: Path | None = None) -> None:
        home = Path(robosim_home) if robosim_home is not None else find_home(near)
        env = dict(os.environ)
        env.setdefault("ROBOSIM_PYTHON", sys.executable)
        #: Whose turn it is on the link: one call at a time, the condition held only to take and give back the turn,
        #: never across the link's I/O (a close meanwhile stops the host, which breaks the call off).
        self._turn = threading.Condition()
        self._talking = False
        self._closed = False
        self._ended = threading.Event()  # (set once close has stopped the host: a second close waits for it)
        self._host = HostProcess(home, "simulation-host.sh", [], _LISTENING, "simulation host", env)
        try:
            where = self._host.where
            self._frames: Frames = self._host.connect(where.group(1), int(where.group(2)), CALL_S)
            self._frames.send({"link": LINK, "version": VERSION, "key": self._host.key})
            answer = self._host.receive(self._frames)
            if not isinstance(answer, dict) or answer.get("link") != LINK or answer.get("version") != VERSION:
                raise HostError(f"the simulation host refused the hello, or is not a simulation link's version "
                                f"{VERSION}: {answer!r:.300}")
        except BaseException:
            self._closed = True
            self._host.stop()
            self._ended.set()
            raise

    @property
    def closed(self) -> bool:
        """Whether this host is closed, or has ended (its JVM gone: :func:`shared_host` then starts another)."""
        return self._closed or self._host.stopped

    def call(self, *request: Any, meanwhile: Callable[[], object] | None = None) -> list[Any]:
        """One request and its answer: ``["ok", VALUE]`` or ``["failed", FAILURES, STEPS]``; an ``error`` answer is a
        ValueError with the host's reason. ``meanwhile``, if given, runs once the request is sent, while the host
        works on it (the answer is read after it returns, even if it raises). Calls from several threads take turns."""
        with self._turn:
            while self._talking and not self.closed:
                self._turn.wait()
            if self.closed:
                self._turn.notify_all()  # (the host gone: every waiter is told, not one)
                raise HostError("the simulation host is closed" + self._host.said())
            self._talking = True
        try:
            self._host.send(self._frames, list(request))
            try:
                if meanwhile is not None:
                    meanwhile()
            finally:
                answer = self._host.receive(self._frames)
        finally:
            with self._turn:
                self._talking = False
                closed = self._closed
                self._turn.notify_all()
        if closed:  # (its answer may have come before the stop broke the link off: it counts for nothing)
            raise HostError("the simulation host was closed while the call was under way")
        if not isinstance(answer, list) or not answer or not isinstance(answer[0], str):
            raise HostError(f"an answer that is not one: {answer!r:.200}")
        if answer[0] == "error":
            raise ValueError(str(answer[2]) if len(answer) > 2 else str(answer))
        if answer[0] not in ("ok", "failed"):
            raise HostError(f"an answer that is not one: {answer!r:.200}")
        return answer

    def close(self) -> None:
        """Says bye (every simulation still open ends) and waits for the host to exit. A call another thread has under
        way is broken off (it raises HostError): the host is stopped without waiting for its answer."""
        with self._turn:
            first = not self._closed
            self._closed = True
            talking = self._talking
            self._turn.notify_all()
        if not first:  # (until the first close has said bye and stopped the host; then stopped again, should the
            self._ended.wait()  # first have been interrupted before its stop: a stop is safe to repeat)
            self._host.stop()
            return
        try:
            if not talking:
                try:
                    self._frames.send(["bye"])
                    self._frames.receive()
                except Exception:  # (a link that broke as it ended: the host is stopped below all the same)
                    pass
            self._host.stop()
        finally:
            self._ended.set()

    def __enter__(self) -> SimulationHost:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


class _Starting:
    """A warm host one thread is starting; the others wait for it (an event: no lock held while a JVM starts)."""

    def __init__(self) -> None:
        self.done = threading.Event()


#: This process's warm hosts by number (0: :func:`shared_host`'s; a sweep's workers 1, 2, ...), or the one starting.
_warm: dict[int, SimulationHost | _Starting] = {}
_warm_guard = threading.Lock()  # (the table's alone: looked at and changed under it, a host started outside it)


def _warm_host(index: int, near: Path | None) -> SimulationHost:
    """This process's warm host ``index``, started at its first use and again once closed, closed at the
    interpreter's exit. A second caller while it starts waits for it; if the start fails, the starter raises and
    a waiter tries again itself."""
    while True:
        with _warm_guard:
            entry = _warm.get(index)
            if isinstance(entry, SimulationHost) and not entry.closed:
                return entry
            mine = not isinstance(entry, _Starting)
            starting = _Starting() if mine else entry
            assert isinstance(starting, _Starting)
            _warm[index] = starting
        if not mine:
            starting.done.wait()  # (until the starter has a host or has given up)
            continue
        host: SimulationHost | None = None
        try:  # (whatever ends the start, even an interrupt: the table holds the host or nothing, and waiters go on)
            try:
                host = SimulationHost(near=near)
                atexit.register(host.close)
                with _warm_guard:
                    _warm[index] = host
                return host
            except BaseException:
                with _warm_guard:
                    if _warm.get(index) is starting:
                        del _warm[index]
                if host is not None:
                    host.close()  # (started, not kept: closed, not left running)
                raise
        finally:
            starting.done.set()


def shared_host(near: Path | None = None) -> SimulationHost:
    """This process's simulation host, started at its first use (RoboSim found from ``near`` or the working
    directory, or ``ROBOSIM_HOME``) and closed at the interpreter's exit: one JVM, warm, for every simulation."""
    return _warm_host(0, near)


class World:
    """A world built in code, in an environment file's units (metres, degrees): a rectangular arena with its corner
    at the origin, rectangular obstacles and robots, each with its control code (``python:FILE``, relative to the
    working directory, or a Java class). For more (sensors, objects, loop functions) write an environment file."""

    def __init__(self, width_m: float, height_m: float) -> None:
        self._arena = (float(width_m), float(height_m))
        self._time_step_ms = 100
        self._seed = 1
        self._comm_range_m: float | None = None
        self._params: dict[str, str] = {}
        self._obstacles: list[str] = []
        self._robots: list[str] = []

    @staticmethod
    def arena(width_m: float, height_m: float) -> World:
        """An empty arena ``width_m`` x ``height_m`` metres, 100 ms steps, seed 1."""
        return World(width_m, height_m)

    def time_step_ms(self, ms: int) -> World:
        self._time_step_ms = int(ms)
        return self

    def seed(self, seed: int) -> World:
        self._seed = int(seed)
        return self

    def comm_range_m(self, metres: float) -> World:
        """How far a message carries, centre to centre (default: everywhere)."""
        self._comm_range_m = float(metres)
        return self

    def param(self, name: str, value: object) -> World:
        """A parameter of every robot's control code (``robot.parameter(name, default)``)."""
        self._params[name] = str(value)
        return self

    def obstacle(self, name: str, x: float, y: float, width: float, height: float) -> World:
        """A rectangular obstacle with its lower left corner at (``x``, ``y``), m."""
        self._obstacles.append(f"<rectangle name={quoteattr(name)} x=\"{float(x)!r}\" y=\"{float(y)!r}\" "
                               f"width=\"{float(width)!r}\" height=\"{float(height)!r}\"/>")
        return self

    def robot(self, name: str, type: str, x: float, y: float, heading: float, control: str) -> World:  # noqa: A002
        """A robot of ``type`` (``Scout``, ``foot-bot``, ...: ``scripts/describe.sh robots``) at (``x``, ``y``) m,
        heading ``heading`` degrees, running ``control``: ``python:FILE`` or a Java control class."""
        if control.startswith("python:"):
            control = "python:" + str(Path(control[len("python:"):]).resolve())
        self._robots.append(f"<robot name={quoteattr(name)} type={quoteattr(type)} control={quoteattr(control)} "
                            f"x=\"{float(x)!r}\" y=\"{float(y)!r}\" heading=\"{float(heading)!r}\"/>")
        return self

    def xml(self) -> str:
        """The world as an environment file."""
        comm = f" commRangeM=\"{self._comm_range_m!r}\"" if self._comm_range_m is not None else ""
        params = "".join(f"\n  <param name={quoteattr(k)} value={quoteattr(v)}/>" for k, v in self._params.items())
        obstacles = "".join(f"\n    {o}" for o in self._obstacles)
        robots = "".join(f"\n    {r}" for r in self._robots)
        return (f"<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                f"<environment name=\"world\" timeStepMs=\"{self._time_step_ms}\" seed=\"{self._seed}\"{comm}>"
                f"{params}\n  <arena width=\"{self._arena[0]!r}\" height=\"{self._arena[1]!r}\"/>"
                + (f"\n  <obstacles>{obstacles}\n  </obstacles>" if obstacles else "")
                + f"\n  <robots>{robots}\n  </robots>\n</environment>\n")


class SimulationBuilder:
    """How a :class:`Simulation` starts: its world, parameters, seed, the robots that may fail."""

    def __init__(self, world: str | os.PathLike[str] | World) -> None:
        self._world = world
        self._params: dict[str, str] = {}
        self._seed: int | None = None
        self._expected: list[str] = []
        self._step_timeout_ms: int | None = None
        self._host: SimulationHost | None = None
        self._pose_log: str | None = None
        self._history = True

    def param(self, name: str, value: object) -> SimulationBuilder:
        """The control code's parameter ``name`` (``robot.parameter``), as ``--param`` gives it: for a file, a
        ``${NAME:default}`` placeholder or a world ``<param>`` (an unknown name is refused at ``start``)."""
        self._params[name] = str(value)
        return self

    def seed(self, seed: int) -> SimulationBuilder:
        """The run's seed, over the file's (as a sweep's or ``--seed``)."""
        self._seed = int(seed)
        return self

    def expect_failure(self, robot: str) -> SimulationBuilder:
        """Robot ``robot``'s control code may raise without failing the test (``failure`` says whether it did)."""
        self._expected.append(robot)
        return self

    def step_timeout(self, seconds: float) -> SimulationBuilder:
        """A robot whose control code makes no call this long after its step went out is dropped (default 10 s)."""
        self._step_timeout_ms = max(1, int(seconds * 1000))
        return self

    def pose_log(self, path: str | os.PathLike[str]) -> SimulationBuilder:
        """Write the poses of every step ``drive`` runs into the new file ``path`` (``--pose-log``'s CSV)."""
        self._pose_log = str(Path(path).resolve())
        return self

    def history(self, keep: bool) -> SimulationBuilder:
        """Whether the simulation keeps every message and contact of its robots for ``received`` and ``contacts``
        (default: it does). A long run driven from outside (the ROS 2 bridge's) keeps none, so that its memory does not
        grow with its messages and contacts; those two then raise ValueError."""
        if not isinstance(keep, bool):
            raise TypeError(f"history is True or False, got {keep!r:.40}")
        self._history = keep
        return self

    def host(self, host: SimulationHost) -> SimulationBuilder:
        """Run on ``host`` (default: this process's, :func:`shared_host`)."""
        self._host = host
        return self

    def start(self) -> Simulation:
        """Every robot placed and its control code started; nothing computed yet (``steps`` is 0). A world file that
        cannot be read is a ValueError naming its faults."""
        folder: str | None = None
        if isinstance(self._world, World):
            folder = tempfile.mkdtemp(prefix="robosim-world-")
            path = Path(folder) / "world.xml"
            path.write_text(self._world.xml(), encoding="utf-8")
        else:
            path = Path(self._world).resolve()
            if not path.is_file():
                raise ValueError(f"{self._world}: file not found")
        try:
            host = self._host or shared_host(path.parent)
            answer = host.call("start", {"world": str(path), "params": self._params, "seed": self._seed,
                                         "expect_failure": self._expected, "step_timeout_ms": self._step_timeout_ms,
                                         "pose_log": self._pose_log, "history": self._history})
        except BaseException:
            if folder is not None:
                shutil.rmtree(folder, ignore_errors=True)
            raise
        return Simulation(host, int(answer[1]["id"]), list(answer[1]["robots"]), folder)


class Simulation:
    """A started simulation (:meth:`of` builds one). Not thread-safe: one test drives it."""

    def __init__(self, host: SimulationHost, sim_id: int, robots: list[str], folder: str | None) -> None:
        self._host = host
        self._id = sim_id
        self._robots = robots
        self._folder = folder
        self._closed = False

    @staticmethod
    def of(world: str | os.PathLike[str] | World) -> SimulationBuilder:
        """A simulation of an environment file or of a :class:`World` built in code."""
        return SimulationBuilder(world)

    def _ask(self, *request: Any) -> Any:
        if self._closed:
            raise ValueError("the simulation is closed")
        return self._host.call(request[0], self._id, *request[1:])[1]

    def run(self, n: int) -> Simulation:
        """Runs ``n`` more steps and holds; a robot's control code that raised (not expected) is a ControlFailed."""
        if self._closed:
            raise ValueError("the simulation is closed")
        answer = self._host.call("run", self._id, int(n))
        if answer[0] == "failed":
            raise ControlFailed([_failure(f) for f in answer[1]])
        return self

    def run_until(self, done: Callable[[Simulation], object], max_steps: int) -> bool:
        """Runs one step at a time until ``done(sim)`` holds (looked at before each step and after the last) or
        ``max_steps`` steps have run; whether it holds."""
        for _ in range(max_steps):
            if done(self):
                return True
            self.run(1)
        return bool(done(self))

    def drive(self, commands: dict[str, tuple[float, float] | list[float]],
              meanwhile: Callable[[], object] | None = None) -> dict[str, Any]:
        """One step, each robot driven by the link (``control="ros2"``) moving at its command: mm/s ahead and deg/s
        counter-clockwise, held to its type's limits (one not named stands still); the step's frame (the ROS 2
        bridge's, ``BridgeFrames`` in RoboSim's Java): ``step``, ``poses`` (every robot's x, y, heading as
        little-endian float64s) and ``robots`` (each driven robot's senses). A world with such robots steps only
        this way (``run`` refuses it). ``meanwhile`` runs while the host steps (the bridge publishes the last
        step's messages then)."""
        if self._closed:
            raise ValueError("the simulation is closed")
        answer = self._host.call("drive", self._id, {r: [float(c[0]), float(c[1])] for r, c in commands.items()},
                                 meanwhile=meanwhile)
        if answer[0] == "failed":
            raise ControlFailed([_failure(f) for f in answer[1]])
        return dict(answer[1])

    def world(self) -> dict[str, Any]:
        """The world as the ROS 2 bridge needs it: the step, the arena and obstacles (mm), each robot's type, sonars,
        proximity rays and sensors, and whether the link drives it."""
        return dict(self._ask("world"))

    @property
    def steps(self) -> int:
        """Steps completed so far."""
        return int(self._ask("steps"))

    @property
    def robots(self) -> list[str]:
        """The robots, in the world's order."""
        return list(self._robots)

    def pose(self, robot: str) -> Pose:
        """Where ``robot`` stands after the last step: mm, mm, degrees counter-clockwise from +x."""
        x, y, heading = self._ask("pose", robot)
        return Pose(x, y, heading)

    def sonar(self, robot: str) -> list[float]:
        """``robot``'s sonar ranges in the last step, mm (empty before the first step)."""
        return list(self._ask("sonar", robot))

    def reading(self, robot: str, sensor: str) -> list[float] | None:
        """``robot``'s sensor ``sensor`` in the last step (as ``robot.sensor``), or None if it gave none."""
        value = self._ask("reading", robot, sensor)
        return None if value is None else list(value)

    def received(self, robot: str) -> list[Received]:
        """Every message ``robot`` has received so far, in order."""
        return [Received(int(s), f, t) for s, f, t in self._ask("received", robot)]

    def contacts(self, robot: str) -> list[Contact]:
        """Every step in which ``robot`` touched something so far, in order."""
        return [Contact(int(s), w) for s, w in self._ask("contacts", robot)]

    def failure(self, robot: str) -> Failure | None:
        """What ``robot``'s control code raised so far, or None."""
        value = self._ask("failure", robot)
        return None if value is None else _failure(value)

    def failed(self, robot: str) -> bool:
        return self.failure(robot) is not None

    def reported(self, robot: str, name: str) -> float | None:
        """The newest value ``robot`` reported under ``name`` (``robot.report``), or None."""
        return self.reports(robot).get(name)

    def reports(self, robot: str) -> dict[str, float]:
        """Everything ``robot`` reported so far: the newest value of each name."""
        return dict(self._ask("reports", robot))

    def metric(self, name: str) -> float:
        """The built-in metric ``name`` of the run so far (``scripts/describe.sh metrics``); an unknown name is a
        ValueError naming them."""
        return float(self._ask("metric", name))

    def metrics(self) -> dict[str, float]:
        """Every built-in metric of the run so far (none before the first step)."""
        return dict(self._ask("metrics"))

    def ended(self, robot: str) -> str | None:
        """Why the simulation is over for ``robot`` (dropped, the end), or None while it takes part."""
        value = self._ask("ended", robot)
        return None if value is None else str(value)

    @property
    def viewer_port(self) -> int:
        """The loopback port a viewer connects to (``scripts/viewer2d.sh localhost PORT``) to watch the run."""
        return int(self._ask("viewer_port"))

    def close(self) -> None:
        """Ends the simulation (its controllers told, their processes ended); a failure not said yet is a
        ControlFailed."""
        if self._closed:
            return
        self._closed = True
        try:
            answer = self._host.call("close", self._id)
        finally:
            if self._folder is not None:
                shutil.rmtree(self._folder, ignore_errors=True)
        if answer[0] == "failed":
            raise ControlFailed([_failure(f) for f in answer[1]])

    def __enter__(self) -> Simulation:
        return self

    def __exit__(self, kind: type[BaseException] | None, *rest: object) -> None:
        if kind is None:
            self.close()
        else:  # (the test failed already: its own error is the one to see)
            try:
                self.close()
            except (AssertionError, ValueError, HostError):
                pass


def _failure(value: dict[str, Any]) -> Failure:
    return Failure(str(value["robot"]), int(value["step"]), str(value["summary"]), str(value["account"]))

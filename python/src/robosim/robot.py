"""A robot, as control code in Python sees it: the calls of RoboSim's Java ``robosim.api.Robot``, in Python's names."""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, NamedTuple

from robosim.frames import Frames, LinkClosed, LinkError, handshake

#: The link's name and version, said in the hello.
LINK = "robosim-robot-link"
VERSION = 1
#: How long the simulator gets to answer the hello, seconds (more than the 10 s it gives a stranger's hello, which it
#: may be hearing out first).
HELLO_TIMEOUT_S = 30.0

_NO_DEFAULT = object()


class SimulationOver(BaseException):  # noqa: N818 (a BaseException, as KeyboardInterrupt: ``except Exception`` lets it by)
    """The simulation is over: raised by the robot's call that was waiting, or by the next one."""


class RobotValueError(ValueError):
    """The robot refused a value (a report's name, a message too long, an unknown sensor); the link goes on."""


class Pose(NamedTuple):
    x_mm: float
    y_mm: float
    heading_deg: float


class Message(NamedTuple):
    sender: str
    text: str


class Robot:
    """One robot over the robot link. Each call is one request and one reply; ``move`` and ``turn`` return once the
    robot has moved or turned (or touched something), however many time steps that took: the simulator keeps time.

    ``name``, ``step_ms``, ``robot_names`` and ``seed`` come with the link's welcome (no round trip)."""

    def __init__(self, frames: Frames, welcome: dict[str, Any]) -> None:
        self._frames = frames
        self.name: str = _text(welcome, "robot")
        self.step_ms: int = _whole(welcome, "step_ms")
        robots = welcome.get("robots")
        if not isinstance(robots, list) or not all(isinstance(r, str) for r in robots):
            raise LinkError(f"a welcome whose robots are not texts: {robots!r:.80}")
        self.robot_names: tuple[str, ...] = tuple(robots)
        self.seed: int = _whole(welcome, "seed")

    @classmethod
    def connect(cls, host: str, port: int, robot: str, key: str | None = None) -> Robot:
        """Connects to robot ``robot``'s link at ``host``:``port`` (``key``: the secret a started script is given)."""
        hello: dict[str, Any] = {"link": LINK, "version": VERSION, "robot": robot}
        if key is not None:
            hello["key"] = key
        frames, welcome = handshake(host, port, hello, "robot link", HELLO_TIMEOUT_S)
        return cls(frames, welcome)

    def call(self, name: str, *args: Any) -> Any:
        """Makes the link's call ``name`` (hardware-sim/README.md, "The robot link") and returns its result."""
        try:
            self._frames.send([name, *args])
            reply = self._frames.receive()
        except (LinkClosed, ConnectionError) as e:  # (the end of a simulation may close the link: no crash here)
            raise SimulationOver(f"the simulator closed the link: {e}") from e
        if not isinstance(reply, list) or not reply or not isinstance(reply[0], str):
            raise LinkError(f"{name}: a reply that is not one: {reply!r:.80}")
        if reply[0] == "ok" and len(reply) == 2:
            return reply[1]
        if reply[0] == "error" and len(reply) == 3:
            kind, why = reply[1], reply[2]
            if kind == "over":
                raise SimulationOver(why)
            if kind == "value":
                raise RobotValueError(why)
            raise LinkError(f"{name}: {why}")
        raise LinkError(f"{name}: a reply that is not one: {reply!r:.80}")

    # ---- moving --------------------------------------------------------------------------------------------

    def move(self, mm: float) -> float:
        """Moves ``mm`` ahead (negative: back) at the set velocity; how far it went (less if it touched something)."""
        return float(self.call("move", mm))

    def turn(self, deg: float) -> float:
        """Turns ``deg`` degrees counter-clockwise (negative: clockwise); how far it turned."""
        return float(self.call("turn", deg))

    def set_velocity(self, mm_per_s: float) -> None:
        self.call("set_velocity", mm_per_s)

    def velocity(self) -> float:
        return float(self.call("velocity"))

    def set_rot_velocity(self, deg_per_s: float) -> None:
        self.call("set_rot_velocity", deg_per_s)

    def rot_velocity(self) -> float:
        return float(self.call("rot_velocity"))

    def sleep(self, ms: int) -> None:
        """Stands still for ``ms`` of simulated time (at least one step)."""
        self.call("sleep", int(ms))

    def tag(self) -> str:
        """Tags the robot or obstacle it touches: its name, or "" if nothing."""
        return str(self.call("tag"))

    # ---- sensing ---------------------------------------------------------------------------------------------

    def sonar_ranges(self) -> list[float]:
        """Each sonar's range, mm, as of the last step."""
        return _numbers(self.call("sonar_ranges"))

    def sonar_angles_deg(self) -> list[float]:
        """Where each sonar points, degrees from ahead, counter-clockwise."""
        return _numbers(self.call("sonar_angles_deg"))

    def sensor_names(self) -> list[str]:
        return [str(s) for s in self.call("sensor_names")]

    def sensor(self, name: str) -> list[float]:
        """The reading of the robot's sensor ``name`` (an unknown name: RobotValueError)."""
        return _numbers(self.call("sensor", name))

    def pose(self) -> Pose:
        """Where the robot is: x and y, mm, and heading, degrees (one round trip for three values)."""
        x, y, h = self.call("pose")
        return Pose(float(x), float(y), float(h))

    def last_contact(self) -> str:
        """What it last touched, or ""."""
        return str(self.call("last_contact"))

    # ---- wheels, LEDs, the gripper, range and bearing, actuators ---------------------------------------------

    def set_wheel_speeds(self, left_mm_per_s: float, right_mm_per_s: float) -> None:
        """Drives on its wheels (mm/s, positive forward), held until set again: time passes with them in ``step``,
        ``sleep`` and ``wait_for_message``; ``move`` and ``turn`` drive by their own velocities."""
        self.call("set_wheel_speeds", left_mm_per_s, right_mm_per_s)

    def step(self) -> None:
        """One time step passes, the robot driving on its wheels as set (standing still at 0 and 0)."""
        self.call("step")

    def actuator_names(self) -> list[str]:
        return [str(a) for a in self.call("actuator_names")]

    def actuate(self, name: str, values: Sequence[float]) -> None:
        """Sets actuator ``name`` to ``values`` from the next step on (values it cannot take: RobotValueError)."""
        self.call("actuate", name, [float(v) for v in values])

    def led_count(self) -> int:
        return int(self.call("led_count"))

    def set_leds(self, colour: int | str) -> None:
        """Every LED to ``colour``: ``0xRRGGBB``, or a text: a name (``"red"``, ``"gray50"``), ``"#rrggbb"``,
        ``"r,g,b"``; black is off."""
        self.call("set_leds", colour)

    def set_led(self, index: int, colour: int | str) -> None:
        """LED ``index`` to ``colour``, the others as they are."""
        self.call("set_led", int(index), colour)

    def set_rab_data(self, data: Sequence[int]) -> None:
        """The bytes its range-and-bearing device sends every step from the next on (each 0 to 255)."""
        self.call("set_rab_data", [int(b) for b in data])

    def grip(self) -> str:
        """Takes the nearest gripable object touching its front (one step): its name, or "" if none was in reach."""
        return str(self.call("grip"))

    def release(self) -> None:
        """Lets go of what it holds (one step)."""
        self.call("release")

    def gripped(self) -> str:
        """The object it holds, or ""."""
        return str(self.call("gripped"))

    # ---- messages ------------------------------------------------------------------------------------------

    def send(self, to: str, text: str) -> None:
        self.call("send", to, text)

    def broadcast(self, text: str) -> None:
        self.call("broadcast", text)

    def receive(self) -> Message | None:
        """The next message come, or None (it does not wait)."""
        return _message(self.call("receive"))

    def wait_for_message(self, ms: int) -> Message | None:
        """The next message, waiting up to ``ms`` of simulated time for one; None if none came."""
        return _message(self.call("wait_for_message", int(ms)))

    # ---- the experiment ------------------------------------------------------------------------------------

    def parameter(self, name: str, default: Any = _NO_DEFAULT) -> Any:
        """The parameter ``name`` of the environment file (``<param>``) or ``--param``: with a number as default,
        the value as a number; with a text, as given; without one, the text or None."""
        if default is _NO_DEFAULT:
            return self.call("parameter", name)
        if isinstance(default, bool) or not isinstance(default, int | float | str):
            raise TypeError(f"a parameter's default is a number or a text, not {type(default).__name__}")
        return self.call("parameter", name, default)

    def report(self, name: str, value: float) -> None:
        """Reports a value for the run's table (a sweep's metric ``report="name"``)."""
        self.call("report", name, value)


def _text(welcome: dict[str, Any], key: str) -> str:
    v = welcome.get(key)
    if not isinstance(v, str):
        raise LinkError(f"a welcome without a text {key}: {v!r:.80}")
    return v


def _whole(welcome: dict[str, Any], key: str) -> int:
    v = welcome.get(key)
    if not isinstance(v, int) or isinstance(v, bool):
        raise LinkError(f"a welcome without a whole number {key}: {v!r:.80}")
    return v


def _numbers(v: Sequence[Any]) -> list[float]:
    return [float(x) for x in v]


def _message(v: Any) -> Message | None:
    if v is None:
        return None
    sender, text = v
    return Message(str(sender), str(text))

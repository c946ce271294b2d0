"""Loop functions in Python: an experiment's own code, run inside a RoboSim world while it steps (ARGoS's
``CLoopFunctions``), named by the world as ``<loopFunctions class="python:FILE">``.

The script's ``loop_functions`` is a class (made with no arguments) that overrides any of ``LoopFunctions``'s calls:
``init``, ``reset``, ``pre_step``, ``post_step``, ``finished``, ``destroy``. Each gets the ``Experiment``: the world as
it stands (read here, sent with each call) and its changes (each one request to the simulator). The simulator starts
the script (``python -m robosim.loop FILE``) with its loop link's address and key in its environment and calls it on
the one thread that steps the world: the same results in every layout, and the same as Java loop functions doing the
same arithmetic (``random`` is Java's ``SplittableRandom``, seeded as the Java ``Experiment``'s). An exception ends
the run with its last line and exit code 4; its traceback is logged once by the simulator."""

from __future__ import annotations

import argparse
import os
import sys
import threading
import traceback
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from robosim.frames import Frames, LinkClosed, LinkError, handshake, pack
from robosim.portable import SplittableRandom
from robosim.runner import _end_with_stdin, _stdin_is_a_pipe, script_module

#: The link's name and version, said in the hello.
LINK = "robosim-loop-link"
VERSION = 2
#: Mixed into the run's seed for the experiment's own generator (Java's ``ExperimentCode``: "loopfunc").
SEED_MIX = 0x6C6F6F7066756E63
#: The calls a script's class may define, by the link's names (``finished`` is answered with ``post_step``'s).
CALLS = ("init", "reset", "pre_step", "post_step", "finished", "destroy")
#: Exit codes: the link ended as planned (0), the code failed (1), the link or the script could not be had (2).
EXIT_FAILED = 1
EXIT_UNUSABLE = 2

_NO_DEFAULT = object()


class LinkLost(BaseException):  # noqa: N818 (a BaseException, as SimulationOver: ``except Exception`` lets it by)
    """The loop link broke under a request (the simulator gone, or it refused the request as malformed)."""


class ExperimentValueError(ValueError):
    """The simulator refused a value (a report's name, an index out of range, paint beyond the floor's regions)."""


class LoopFunctions:
    """The calls the simulator makes; a script's class overrides those it needs (the others are not made)."""

    def init(self, world: Experiment) -> None:
        """Once, before step 0: the world as the file placed it."""

    def reset(self, world: Experiment) -> None:
        """The experiment starts again (a learning episode's reset); by default ``init`` again."""
        self.init(world)

    def pre_step(self, world: Experiment) -> None:
        """Before each step's moves: the world as the last step left it."""

    def post_step(self, world: Experiment) -> None:
        """After each step's moves and sensing: the world as the step released it."""

    def finished(self, world: Experiment) -> bool:
        """After each ``post_step``: True ends the run there, as planned."""
        return False

    def destroy(self, world: Experiment) -> None:
        """Once, when the run ends however it ends (close files here)."""


class Experiment:
    """The world as loop functions see and change it; units as the robot's: millimetres, degrees counter-clockwise
    from +x, colours ``0xRRGGBB``; robots, objects and lights numbered in world order from 0. Reads are of the state
    sent with the call (and of this code's own changes since); each change is one request to the simulator."""

    def __init__(self, frames: Frames, welcome: dict[str, Any]) -> None:
        self._frames = frames
        self.step_ms: int = _whole(welcome, "step_ms")
        self.seed: int = _whole(welcome, "seed")
        #: The experiment's own random numbers (Java's ``SplittableRandom``, seeded by the run's seed).
        self.random = SplittableRandom(self.seed ^ SEED_MIX)
        parameters = welcome.get("parameters")
        if not isinstance(parameters, dict) or not all(isinstance(v, str) for v in parameters.values()):
            raise LinkError(f"a welcome whose parameters are not texts: {parameters!r:.80}")
        #: The ``<param>``s of ``<loopFunctions>``, in file order.
        self.parameters: dict[str, str] = parameters
        arena = welcome.get("arena")
        if not isinstance(arena, list) or len(arena) != 2:
            raise LinkError(f"a welcome without its arena: {arena!r:.80}")
        self.arena_width_mm, self.arena_height_mm = float(arena[0]), float(arena[1])
        #: Where this run's own files go (a sweep gives each run its own).
        self.output_directory = Path(_text(welcome, "output_directory"))
        self._object_names: tuple[str, ...] = tuple(_texts(welcome, "objects"))
        self._light_names: tuple[str, ...] = tuple(_texts(welcome, "lights"))
        self.step = 0
        self._ended = False
        self._names: list[tuple[str, str]] = []
        self._robots: list[list[Any]] = []
        self._objects: list[list[Any]] = []
        self._lights: list[bool] = []

    def _see(self, call: str, state: Any) -> None:
        """Takes the world's state sent with a call (at ``init`` and ``reset``, the episode's seed with it)."""
        if not isinstance(state, dict):
            raise LinkError(f"a call's state that is not a map: {state!r:.80}")
        self.step = int(state["step"])
        if call in ("init", "reset"):
            self.seed = int(state["seed"])
            self.random = SplittableRandom(self.seed ^ SEED_MIX)
        self._ended = False
        self._names.extend((str(n), str(t)) for n, t in state["names"])
        self._robots = state["robots"]
        self._objects = state["objects"]
        self._lights = state["lights"]
        if len(self._robots) != len(self._names) or len(self._objects) != len(self._object_names) \
                or len(self._lights) != len(self._light_names):
            raise LinkError("a call's state whose robots, objects or lights are not the welcome's")

    @staticmethod
    def _at(rows: Sequence[Any], i: int, what: str) -> Any:
        """Row ``i`` of ``rows``: an IndexError naming ``what`` where there is none (a negative ``i`` too)."""
        if not 0 <= i < len(rows):
            raise IndexError(f"no {what} {i} (there are {len(rows)})")
        return rows[i]

    def _request(self, verb: str, *args: Any) -> Any:
        try:
            frame = pack([verb, *args])
        except LinkError as e:  # (a frame over 1 MiB: a value too large, as the simulator would refuse one)
            raise ExperimentValueError(f"{verb}: {e}") from None
        try:
            self._frames.send_packed(frame)
            reply = self._frames.receive()
        except (OSError, LinkError) as e:
            raise LinkLost(f"{verb}: {e}") from e
        if isinstance(reply, list) and len(reply) == 2 and reply[0] == "ok":
            return reply[1]
        if isinstance(reply, list) and len(reply) == 3 and reply[0] == "error":
            if reply[1] == "value":
                raise ExperimentValueError(f"{verb}: {reply[2]}")
            raise LinkLost(f"{verb}: {reply[2]}")
        raise LinkLost(f"{verb}: a reply that is not one: {reply!r:.80}")

    def parameter(self, name: str, default: Any = _NO_DEFAULT) -> Any:
        """Parameter ``name``: with a number as default, as a float (a value that is not one is a ValueError naming
        it); with a text, as given; without a default, the text or None."""
        value = self.parameters.get(name)
        if default is _NO_DEFAULT or isinstance(default, str):
            return default if value is None and default is not _NO_DEFAULT else value
        if isinstance(default, bool) or not isinstance(default, int | float):
            raise TypeError(f"a parameter's default is a number or a text, not {type(default).__name__}")
        if value is None:
            return float(default)
        try:
            return float(value.strip())
        except ValueError:
            raise ValueError(f"loop functions parameter {name} is {value!r}, not a number") from None

    # ---- robots --------------------------------------------------------------------------------------------

    @property
    def robots(self) -> int:
        return len(self._robots)

    def robot_name(self, robot: int) -> str:
        return self._at(self._names, robot, "robot")[0]

    def robot_type(self, robot: int) -> str:
        return self._at(self._names, robot, "robot")[1]

    def robot_x_mm(self, robot: int) -> float:
        return float(self._at(self._robots, robot, "robot")[0])

    def robot_y_mm(self, robot: int) -> float:
        return float(self._at(self._robots, robot, "robot")[1])

    def robot_heading_deg(self, robot: int) -> float:
        return float(self._at(self._robots, robot, "robot")[2])

    def present(self, robot: int) -> bool:
        """False once it has left the run."""
        return bool(self._at(self._robots, robot, "robot")[3])

    def leds(self, robot: int) -> tuple[int, ...]:
        """Its LEDs' colours as it last set them (empty: it has none)."""
        return tuple(self._at(self._robots, robot, "robot")[5])

    def carrying(self, robot: int) -> int:
        """The object it holds in its gripper, or -1."""
        return int(self._at(self._robots, robot, "robot")[4])

    def move_robot(self, robot: int, x_mm: float, y_mm: float, heading_deg: float) -> bool:
        """Puts it at a pose, letting go of what it holds; False, and nothing moved, where it would overlap."""
        pose = self._request("move_robot", robot, float(x_mm), float(y_mm), float(heading_deg))
        if not pose:
            return False
        held = self.carrying(robot)
        if held >= 0:
            self._objects[held][3] = -1
        self._robots[robot][0:3] = [float(v) for v in pose]  # (the pose as the simulator keeps it)
        self._robots[robot][4] = -1
        return True

    def tell(self, robot: int, text: str) -> None:
        """A message to the robot, from ``loop``, in its next step's messages."""
        self._request("tell", robot, text)

    # ---- objects -------------------------------------------------------------------------------------------

    @property
    def objects(self) -> int:
        return len(self._objects)

    def object_name(self, obj: int) -> str:
        return self._at(self._object_names, obj, "object")

    def object_x_mm(self, obj: int) -> float:
        return float(self._at(self._objects, obj, "object")[0])

    def object_y_mm(self, obj: int) -> float:
        return float(self._at(self._objects, obj, "object")[1])

    def object_heading_deg(self, obj: int) -> float:
        return float(self._at(self._objects, obj, "object")[2])

    def carrier(self, obj: int) -> int:
        """The robot holding it, or -1."""
        return int(self._at(self._objects, obj, "object")[3])

    def object_present(self, obj: int) -> bool:
        """False once ``remove_object`` took it out of the world (until ``add_object`` puts it back)."""
        return bool(self._at(self._objects, obj, "object")[4])

    def remove_object(self, obj: int) -> None:
        """Takes it out of the world, let go of by whoever held it: nothing meets, senses or grips it from the step's
        moves on (the next step's, after a post-step), and the viewers leave it out. It keeps its number and its last
        pose."""
        self._request("remove_object", obj)
        holder = self.carrier(obj)
        if holder >= 0:
            self._robots[holder][4] = -1
        self._objects[obj][3] = -1
        self._objects[obj][4] = False

    def add_object(self, obj: int, x_mm: float, y_mm: float, heading_deg: float) -> bool:
        """Puts an object taken out back into the world at a pose; False, and it stays out, where it would overlap."""
        pose = self._request("add_object", obj, float(x_mm), float(y_mm), float(heading_deg))
        if not pose:
            return False
        self._objects[obj] = [*(float(v) for v in pose), -1, True]
        return True

    def move_object(self, obj: int, x_mm: float, y_mm: float, heading_deg: float) -> bool:
        """Puts it at a pose, let go of by whoever held it; False, and nothing moved, where it would overlap."""
        pose = self._request("move_object", obj, float(x_mm), float(y_mm), float(heading_deg))
        if not pose:
            return False
        holder = self.carrier(obj)
        if holder >= 0:
            self._robots[holder][4] = -1
        self._objects[obj] = [*(float(v) for v in pose), -1, True]
        return True

    # ---- floor and lights ----------------------------------------------------------------------------------

    def floor_colour(self, x_mm: float, y_mm: float) -> int:
        """The floor's colour at a point, as ground sensors read it (the file's floor with this code's paint)."""
        return int(self._request("floor_colour", float(x_mm), float(y_mm)))

    def paint_disc(self, x_mm: float, y_mm: float, radius_mm: float, rgb: int) -> None:
        self._request("paint_disc", float(x_mm), float(y_mm), float(radius_mm), rgb)

    def paint_rectangle(self, x_mm: float, y_mm: float, width_mm: float, height_mm: float, rgb: int) -> None:
        """An axis-aligned rectangle, its lower-left corner at (x, y)."""
        self._request("paint_rectangle", float(x_mm), float(y_mm), float(width_mm), float(height_mm), rgb)

    def erase_paint(self) -> None:
        """Takes away everything this code painted: the file's floor again."""
        self._request("erase_paint")

    def trace(self, name: str, x_mm: float, y_mm: float, rgb: int) -> None:
        """Draws over the world for the viewers: extends trace ``name`` (a line of colour ``rgb``, begun if new) to a
        point. Not sensed; recorded and replayed; bounded as Java's ``Experiment.trace`` says."""
        self._request("trace", name, float(x_mm), float(y_mm), rgb)

    def erase_traces(self) -> None:
        """Erases every trace drawn."""
        self._request("erase_traces")

    @property
    def lights(self) -> int:
        return len(self._lights)

    def light_name(self, light: int) -> str:
        return self._at(self._light_names, light, "light")

    def light_on(self, light: int) -> bool:
        return bool(self._at(self._lights, light, "light"))

    def switch_light(self, light: int, on: bool) -> None:
        self._request("switch_light", light, bool(on))
        self._lights[light] = bool(on)

    # ---- the run -------------------------------------------------------------------------------------------

    def report(self, name: str, value: float) -> None:
        """A metric of the run: recorded with the step, a column of a sweep's tables, plotted like the built-ins."""
        self._request("report", name, float(value))

    def end(self, reason: str = "") -> None:
        """Ends the run after this step, as planned, with ``reason`` as its end's reason."""
        self._request("end", reason)
        self._ended = True


def _whole(welcome: dict[str, Any], key: str) -> int:
    v = welcome.get(key)
    if not isinstance(v, int) or isinstance(v, bool):
        raise LinkError(f"a welcome without a whole number {key}: {v!r:.80}")
    return v


def _text(welcome: dict[str, Any], key: str) -> str:
    v = welcome.get(key)
    if not isinstance(v, str):
        raise LinkError(f"a welcome without a text {key}: {v!r:.80}")
    return v


def _texts(welcome: dict[str, Any], key: str) -> list[str]:
    v = welcome.get(key)
    if not isinstance(v, list) or not all(isinstance(t, str) for t in v):
        raise LinkError(f"a welcome whose {key} are not texts: {v!r:.80}")
    return v


def load(script: Path) -> type[LoopFunctions]:
    """The loop functions' class ``script`` defines (its ``loop_functions``)."""
    made = getattr(script_module(script), "loop_functions", None)
    if not isinstance(made, type) or not issubclass(made, LoopFunctions):
        raise ValueError(f"{script}: defines no loop_functions (a class of robosim.loop.LoopFunctions, named "
                         "loop_functions: loop_functions = Foraging)")
    return made


def defined(made: type[LoopFunctions]) -> list[str]:
    """The calls ``made`` overrides, by the link's names (``reset`` too where ``init`` is: it calls it)."""
    mine = [c for c in CALLS if getattr(made, c) is not getattr(LoopFunctions, c)]
    return mine + ["reset"] if "init" in mine and "reset" not in mine else mine


def serve(frames: Frames, code: LoopFunctions, world: Experiment) -> int:
    """Answers the simulator's calls until it closes the link; the exit code (1 if a call failed). After a failure it
    goes on answering: the simulator still calls ``destroy``, so the code's files are closed."""
    failed = False
    while True:
        try:
            call = frames.receive()
        except LinkClosed:
            return EXIT_FAILED if failed else 0
        if not isinstance(call, list) or len(call) != 2 or call[0] not in CALLS:
            raise LinkError(f"a call that is not one: {call!r:.80}")
        world._see(call[0], call[1])
        result: bool | None = None
        try:
            if call[0] == "post_step":
                code.post_step(world)
                result = not world._ended and bool(code.finished(world))  # (as Java's: no finished after an end)
            else:
                getattr(code, call[0])(world)
        except LinkLost as e:
            raise LinkError(str(e)) from e
        except BaseException as e:  # (KeyboardInterrupt and SystemExit too: the call did not return)
            frames.send(["failed", _account(e)])
            failed = True
            continue
        frames.send(["done", result])


#: The longest account of a failure sent, characters: its head and its last line beyond that.
MAX_ACCOUNT = 8000


def _account(e: BaseException) -> str:
    """``e``'s traceback from the loop functions' own frames on, cut to :data:`MAX_ACCOUNT` (its last line kept)."""
    account = "".join(traceback.format_exception(e.with_traceback(_theirs(e.__traceback__))))
    if len(account) <= MAX_ACCOUNT:
        return account
    last = account.rstrip().rsplit("\n", 1)[-1][: MAX_ACCOUNT // 2]
    return account[: MAX_ACCOUNT // 2] + "\n...\n" + last + "\n"


def _theirs(tb: Any) -> Any:
    """The traceback from the loop functions' own frames on (this module's left out)."""
    while tb is not None and tb.tb_frame.f_code.co_filename == __file__:
        tb = tb.tb_next
    return tb


def connect(host: str, port: int, key: str | None, calls: list[str]) -> tuple[Frames, dict[str, Any]]:
    """The loop link at ``host``:``port``: its frames and the simulator's welcome."""
    hello: dict[str, Any] = {"link": LINK, "version": VERSION, "calls": " ".join(calls)}
    if key is not None:
        hello["key"] = key
    return handshake(host, port, hello, "loop link", 30.0)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m robosim.loop",
        description="Runs a world's loop functions written in Python over its loop link (the simulator starts it "
        "for <loopFunctions class=\"python:FILE\">). The script's `loop_functions` is a class of "
        "robosim.loop.LoopFunctions.")
    parser.add_argument("script", type=Path, help="the loop functions' script")
    args = parser.parse_args(argv)
    link = os.environ.get("ROBOSIM_LINK", "")
    host, sep, port = link.rpartition(":")
    if not sep or not port.isdigit():
        parser.error("ROBOSIM_LINK (HOST:PORT) is not set: the simulator starts this for a world's loop functions")
    if os.environ.get("ROBOSIM_LINK_KEY") and _stdin_is_a_pipe():  # (the simulator's pipe: its end ends this too)
        threading.Thread(target=_end_with_stdin, name="stdin-watch", daemon=True).start()
    try:
        made: type[LoopFunctions] | None = load(args.script)
        unmade: str | None = None
    except BaseException as e:  # (a syntax error too: said as the failure of the first call, init)
        made = None
        unmade = "".join(traceback.format_exception(e.with_traceback(_theirs(e.__traceback__))))
        if isinstance(e, SyntaxError):  # (its last line says where)
            unmade += f"{e.filename}:{e.lineno}: {type(e).__name__}: {e.msg}\n"
    try:
        frames, welcome = connect(host, int(port), os.environ.get("ROBOSIM_LINK_KEY"),
                                  defined(made) if made is not None else ["init"])
        if made is None:
            frames.receive()  # (the call of init)
            frames.send(["failed", unmade])
            return EXIT_FAILED
        world = Experiment(frames, welcome)
        return serve(frames, made(), world)
    except (OSError, LinkError) as e:
        print(f"robosim.loop: the loop link at {link}: {e}", file=sys.stderr)
        return EXIT_UNUSABLE

if __name__ == "__main__":  # (python -m robosim.loop: the module by its own name, so a script's subclass is of ours)
    from robosim.loop import main as _main

    sys.exit(_main())

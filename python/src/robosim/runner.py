"""Runs a controller script for one robot: ``python -m robosim SCRIPT`` (or ``robosim-run SCRIPT``).

The script's ``control`` is the controller: a function that takes the robot, or a class (made with no arguments)
whose ``run(robot)`` is called. Where the robot's link is comes from ``--link HOST:PORT`` and ``--robot NAME``, or
from the environment the simulator starts a script with (``ROBOSIM_LINK``, ``ROBOSIM_ROBOT``, ``ROBOSIM_LINK_KEY``).
Its return ends the robot's control code (the robot stands still); an exception is the control code's failure: its
traceback goes to the simulator, which logs it once with the robot's name."""

from __future__ import annotations

import argparse
import importlib.util
import os
import stat
import sys
import threading
import traceback
from collections.abc import Callable
from pathlib import Path
from types import ModuleType, TracebackType
from typing import Any, cast

from robosim.frames import LinkError
from robosim.robot import Robot, SimulationOver

#: Exit codes: the control code returned or the simulation ended (0), it failed (1), the link or the script could
#: not be had (2); with --check, a script that does not compile (3).
EXIT_FAILED = 1
EXIT_UNUSABLE = 2
EXIT_NOT_COMPILED = 3


def check(scripts: list[Path]) -> list[str]:
    """Each script compiled, not run: a line ``FILE:LINE: KIND: MESSAGE`` for each one that does not compile (or
    cannot be read)."""
    faults = []
    for script in scripts:
        try:
            compile(script.read_bytes(), str(script), "exec", dont_inherit=True)
        except SyntaxError as e:  # (IndentationError and TabError among them)
            where = f"{e.filename or script}:{e.lineno}" if e.lineno else str(script)
            faults.append(f"{where}: {type(e).__name__}: {e.msg}")
        except (OSError, ValueError) as e:  # (ValueError: a null byte in the source)
            faults.append(f"{script}: {e}")
    return faults


def script_module(script: Path) -> ModuleType:
    """``script`` run as a module of its own name, its folder first on the path (its own modules beside it)."""
    spec = importlib.util.spec_from_file_location(script.stem, script)
    if spec is None or spec.loader is None:
        raise ValueError(f"{script}: not a Python script")
    module = importlib.util.module_from_spec(spec)
    sys.path.insert(0, str(script.parent.resolve()))
    sys.modules[script.stem] = module
    spec.loader.exec_module(module)
    return module


def load(script: Path) -> Callable[[Robot], Any]:
    """The controller ``script`` defines (its ``control``), as a function of the robot."""
    return controller(script_module(script), script)


def controller(module: ModuleType, script: Path) -> Callable[[Robot], Any]:
    control = getattr(module, "control", None)
    if isinstance(control, type):
        run = getattr(control, "run", None)
        if not callable(run):
            raise ValueError(f"{script}: its control class {control.__name__} has no run(self, robot)")
        return lambda robot: control().run(robot)
    if callable(control):
        return cast(Callable[[Robot], Any], control)
    raise ValueError(f"{script}: defines no control (a function control(robot), or a class with run(self, robot) "
                     "named control: control = Wander)")


def run(script: Path, robot: Robot) -> int:
    """Runs ``script``'s controller on ``robot``; the exit code (0 returned or the simulation over, 1 failed)."""
    try:
        load(script)(robot)
    except SimulationOver:
        return 0
    except SystemExit as e:
        if e.code not in (None, 0):
            return _failed(robot, e)
    except BaseException as e:  # (KeyboardInterrupt too: the control code did not return)
        return _failed(robot, e)
    try:
        robot.call("bye")
    except (LinkError, OSError, SimulationOver):
        pass
    return 0


def _failed(robot: Robot, e: BaseException) -> int:
    """Tells the simulator the control code failed with ``e`` (its traceback); the exit code."""
    account = "".join(traceback.format_exception(e.with_traceback(_theirs(e.__traceback__))))
    try:
        robot.call("failed", account)
    except (LinkError, OSError, SimulationOver):
        sys.stderr.write(account)  # (the simulator cannot hear it: said here, once)
    return EXIT_FAILED


def _theirs(tb: TracebackType | None) -> TracebackType | None:
    """The traceback from the controller's own frames on (this module's left out: they are the same every time)."""
    while tb is not None and tb.tb_frame.f_code.co_filename == __file__:
        tb = tb.tb_next
    return tb


def _stdin_is_a_pipe() -> bool:
    try:
        return stat.S_ISFIFO(os.fstat(0).st_mode)
    except OSError:
        return False


def _end_with_stdin() -> None:
    """Reads stdin to its end (the simulator that started this process is gone), then ends the process at once."""
    try:
        while os.read(0, 4096):  # (the descriptor itself: sys.stdin's buffer holds a lock the interpreter's end needs)
            pass
    except OSError:
        pass
    sys.stderr.write("robosim: the simulator that started this script is gone (its pipe ended); ending\n")
    sys.stderr.flush()
    os._exit(EXIT_UNUSABLE)


def _address(text: str) -> tuple[str, int]:
    host, sep, port = text.rpartition(":")
    if not sep or not host or not port.isdigit() or not 0 < int(port) < 65536:
        raise argparse.ArgumentTypeError(f"{text!r}: not HOST:PORT")
    return host, int(port)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m robosim",
        description="Runs a controller script for one RoboSim robot over its robot link. The script's `control` "
        "is a function of the robot, or a class whose run(robot) is called.")
    parser.add_argument("script", type=Path, nargs="+",
                        help="the controller script, e.g. examples/python/wander.py (with --check, one or more)")
    parser.add_argument("--check", action="store_true",
                        help="only compile the script(s), run nothing: a line FILE:LINE: KIND: MESSAGE for each that "
                        "does not compile, and exit 3 (0 if all do); a simulator asks this before a run")
    parser.add_argument("--link", type=_address, metavar="HOST:PORT",
                        help="the robot's link (default: $ROBOSIM_LINK; a robot whose control is "
                        "robosim.hardware.link.LinkedControl says its port when it waits)")
    parser.add_argument("--robot", metavar="NAME", help="the robot's name (default: $ROBOSIM_ROBOT)")
    args = parser.parse_args(argv)
    if args.check:
        faults = check(args.script)
        for fault in faults:
            print(fault.replace("\n", " "))
        return EXIT_NOT_COMPILED if faults else 0
    if len(args.script) > 1:
        parser.error("one script (several only with --check)")
    args.script = args.script[0]
    link = args.link or (_address(os.environ["ROBOSIM_LINK"]) if os.environ.get("ROBOSIM_LINK") else None)
    name = args.robot or os.environ.get("ROBOSIM_ROBOT")
    if link is None or not name:
        parser.error("give --link HOST:PORT and --robot NAME (or ROBOSIM_LINK and ROBOSIM_ROBOT)")
    if not args.script.is_file():
        print(f"robosim: {args.script}: no such script", file=sys.stderr)
        return EXIT_UNUSABLE
    key = os.environ.get("ROBOSIM_LINK_KEY")
    if key and _stdin_is_a_pipe():  # (started by the simulator, whose pipe is its stdin: the simulator gone ends it)
        threading.Thread(target=_end_with_stdin, name="stdin-watch", daemon=True).start()
    try:
        robot = Robot.connect(link[0], link[1], name, key)
    except (OSError, LinkError) as e:
        print(f"robosim: robot {name} at {link[0]}:{link[1]}: {e}", file=sys.stderr)
        return EXIT_UNUSABLE
    return run(args.script, robot)

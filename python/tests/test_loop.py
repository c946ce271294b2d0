"""robosim.loop over a socket pair, the simulator's side played here: the calls a class defines, the state each call
brings, requests and their replies, a finished post-step, a failure's traceback (Java's side, the real one, is
runner's PythonControlIT)."""

from __future__ import annotations

import socket
import threading
from typing import Any

import pytest

from robosim.frames import Frames
from robosim.loop import Experiment, ExperimentValueError, LoopFunctions, defined, serve

WELCOME: dict[str, Any] = {"link": "robosim-loop-link", "version": 1, "step_ms": 100, "seed": -3,
                           "parameters": {"n": "4", "name": "x"}, "arena": [2000.0, 1000.0],
                           "output_directory": "/tmp", "objects": ["box"], "lights": ["l"]}


def pair() -> tuple[socket.socket, socket.socket]:
    """A connected pair whose reads give up after 10 s: a test that goes wrong fails, it does not hang."""
    mine, theirs = socket.socketpair()
    mine.settimeout(10)
    theirs.settimeout(10)
    return mine, theirs


def state(step: int, names: list[list[str]]) -> dict[str, Any]:
    return {"step": step, "seed": -3, "names": names, "robots": [[100.0, 200.0, 0.0, True, 0, [0x00FF00]]],
            "objects": [[500.0, 500.0, 0.0, 0, True]], "lights": [True]}


class Counting(LoopFunctions):
    def __init__(self) -> None:
        self.seen: list[tuple[str, int]] = []

    def init(self, world: Experiment) -> None:
        self.seen.append(("init", world.step))
        assert world.parameter("n", 1) == 4.0 and world.parameter("name", "y") == "x"
        assert world.parameter("missing", 2) == 2.0 and world.parameter("missing") is None
        assert world.robot_name(0) == "r" and world.leds(0) == (0x00FF00,) and world.carrying(0) == 0
        assert world.move_object(0, 700, 700, 10)
        assert world.carrying(0) == -1 and world.carrier(0) == -1 and world.object_x_mm(0) == 700.0
        world.remove_object(0)
        assert not world.object_present(0)
        assert world.add_object(0, 800, 800, 0) and world.object_present(0) and world.object_x_mm(0) == 800.0
        with pytest.raises(ExperimentValueError, match="report: not a name"):
            world.report("bad name", 1)
        world.trace("path", 1, 2, 0xFF0000)

    def post_step(self, world: Experiment) -> None:
        self.seen.append(("post_step", world.step))

    def finished(self, world: Experiment) -> bool:
        return world.step >= 2


class Raising(LoopFunctions):
    def pre_step(self, world: Experiment) -> None:
        raise RuntimeError("no nest here")


def test_a_class_says_the_calls_it_defines_and_reset_with_its_init() -> None:
    assert defined(Counting) == ["init", "post_step", "finished", "reset"]
    assert defined(Raising) == ["pre_step"]
    assert defined(LoopFunctions) == []


def test_calls_bring_the_world_and_requests_are_answered() -> None:
    mine, theirs = pair()
    sim = Frames(theirs)
    code = Counting()
    frames = Frames(mine)
    world = Experiment(frames, WELCOME)
    assert world.random.next_long() != 0 and world.seed == -3 and world.arena_width_mm == 2000.0
    done: list[int] = []
    t = threading.Thread(target=lambda: done.append(serve(frames, code, world)), daemon=True)
    t.start()
    sim.send(["init", state(0, [["r", "foot-bot"]])])
    assert sim.receive() == ["move_object", 0, 700.0, 700.0, 10.0]
    sim.send(["ok", [700.0, 700.0, 10.0]])
    assert sim.receive() == ["remove_object", 0]
    sim.send(["ok", None])
    assert sim.receive() == ["add_object", 0, 800.0, 800.0, 0.0]
    sim.send(["ok", [800.0, 800.0, 0.0]])
    assert sim.receive() == ["report", "bad name", 1.0]
    sim.send(["error", "value", "not a name"])
    assert sim.receive() == ["trace", "path", 1.0, 2.0, 0xFF0000]
    sim.send(["ok", None])
    assert sim.receive() == ["done", None]
    sim.send(["post_step", state(1, [])])
    assert sim.receive() == ["done", False]
    sim.send(["post_step", state(2, [])])
    assert sim.receive() == ["done", True]
    theirs.shutdown(socket.SHUT_RDWR)  # (the simulator closes the link)
    t.join(10)
    assert done == [0] and code.seen == [("init", 0), ("post_step", 1), ("post_step", 2)]
    mine.close()
    theirs.close()


def test_a_call_that_raises_sends_its_traceback_and_answers_destroy() -> None:
    mine, theirs = pair()
    sim = Frames(theirs)
    frames = Frames(mine)
    world = Experiment(frames, WELCOME)
    done: list[int] = []
    t = threading.Thread(target=lambda: done.append(serve(frames, Raising(), world)), daemon=True)
    t.start()
    sim.send(["pre_step", state(0, [["r", "foot-bot"]])])
    failed = sim.receive()
    assert failed[0] == "failed" and failed[1].rstrip().endswith("RuntimeError: no nest here")
    assert "in pre_step" in failed[1]
    sim.send(["destroy", state(0, [])])  # (after a failure it still answers: its files are closed)
    assert sim.receive() == ["done", None]
    theirs.shutdown(socket.SHUT_RDWR)
    t.join(10)
    assert done == [1], "its exit says it failed"
    mine.close()
    theirs.close()


def test_a_negative_index_and_a_value_too_large_raise_as_values() -> None:
    world = Experiment(Frames(pair()[0]), WELCOME)
    world._see("init", state(0, [["r", "foot-bot"]]))
    with pytest.raises(IndexError, match="no robot -1"):
        world.robot_x_mm(-1)
    with pytest.raises(ExperimentValueError, match="tell: a frame of"):
        world.tell(0, "x" * (1 << 20))

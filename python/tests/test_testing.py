"""robosim.testing against a real simulation host (scripts/simulation-host.sh): Python controllers run and asked from
a test, as the Java testkit does it."""

from __future__ import annotations

import threading
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from robosim.testing import ControlFailed, HostError, Simulation, SimulationHost, World, _warm_host

REPORTER = """def control(robot):
    robot.report("speed", robot.parameter("speed", 0.0))
    robot.report("seed", robot.seed)
    robot.set_velocity(robot.parameter("speed", 0.0))
    while True:
        robot.move(1000)
"""

FILE = """<?xml version="1.0" encoding="UTF-8"?>
<environment name="reporting" timeStepMs="100" seed="5">
  <param name="speed" value="${speed:300}"/>
  <arena width="6" height="6"/>
  <robots>
    <robot name="r1" type="Scout" control="python:reporter.py" x="1" y="3" heading="0"/>
  </robots>
</environment>
"""


@pytest.fixture
def reporting(tmp_path: Path) -> Path:
    (tmp_path / "reporter.py").write_text(REPORTER)
    world = tmp_path / "reporting.xml"
    world.write_text(FILE)
    return world


def test_parameters_and_the_seed_reach_the_controller(reporting: Path, simulation: Callable[..., Simulation]) -> None:
    sim = simulation(reporting, seed=42, params={"speed": 500})
    again = simulation(reporting, seed=42)
    other = simulation(reporting, seed=43)
    for s in (sim, again, other):
        s.run(10)
    assert sim.reported("r1", "speed") == 500.0 and again.reported("r1", "speed") == 300.0
    assert sim.reported("r1", "seed") == again.reported("r1", "seed") != other.reported("r1", "seed")
    assert sim.reported("r1", "speed") == 500.0 and sim.reported("r1", "nothing") is None
    assert 1000 + 500 * 0.1 * 8 <= sim.pose("r1").x_mm <= 1000 + 500 * 0.1 * 10
    assert sim.metric("distance_m") == pytest.approx(sim.metrics()["distance_m"])
    assert sim.steps == 10 and sim.ended("r1") is None and sim.viewer_port > 0


def test_mistakes_are_clear_errors(reporting: Path, tmp_path: Path, simulation: Callable[..., Simulation]) -> None:
    with pytest.raises(ValueError, match=r"speeed.*speed"):
        simulation(reporting, params={"speeed": 1})
    bad = tmp_path / "bad.xml"
    bad.write_text(FILE.replace("<arena", "<arena width=\"x\"", 1).replace(' width="6"', "", 1))
    with pytest.raises(ValueError, match="bad.xml"):
        simulation(bad)
    with pytest.raises(ValueError, match="file not found"):
        simulation(tmp_path / "none.xml")
    sim = simulation(reporting)
    with pytest.raises(ValueError, match=r"no robot named \"r9\""):
        sim.pose("r9")
    with pytest.raises(ValueError, match="no built-in metric named \"speed\".*distance_m"):
        sim.metric("speed")
    sim.close()
    with pytest.raises(ValueError, match="closed"):
        sim.run(1)


def test_an_expected_failure_is_asked_and_the_others_go_on(tmp_path: Path,
                                                           simulation: Callable[..., Simulation]) -> None:
    (tmp_path / "bad.py").write_text("def control(robot):\n    robot.move(100)\n    return 1 / 0\n")
    (tmp_path / "good.py").write_text("def control(robot):\n    while True:\n        robot.move(100)\n")
    world = (World.arena(6, 6).robot("bad", "Scout", 1, 1, 0, control=f"python:{tmp_path / 'bad.py'}")
             .robot("good", "Scout", 1, 4, 0, control=f"python:{tmp_path / 'good.py'}"))
    sim = simulation(world, expect_failure=["bad"])
    sim.run(40)
    failure = sim.failure("bad")
    assert failure is not None and sim.failed("bad") and not sim.failed("good")
    assert failure.summary == "ZeroDivisionError: division by zero"
    assert 'bad.py", line 3, in control' in failure.traceback
    assert sim.pose("good").x_mm > 2000


def test_a_failure_not_expected_fails_the_run_once(tmp_path: Path) -> None:
    (tmp_path / "bad.py").write_text("def control(robot):\n    robot.move(100)\n    raise KeyError('k')\n")
    world = World.arena(4, 4).robot("a", "Scout", 1, 1, 0, control=f"python:{tmp_path / 'bad.py'}")
    with Simulation.of(world).start() as sim:
        with pytest.raises(ControlFailed, match=r"robot a: its control code failed at step \d+: KeyError: 'k'"):
            sim.run(30)
        sim.run(5)  # (said once: the simulation goes on, the robot standing still)
        assert sim.steps == 35


def test_a_world_in_code_meets_its_obstacle(tmp_path: Path, simulation: Callable[..., Simulation]) -> None:
    (tmp_path / "ahead.py").write_text("def control(robot):\n    robot.set_velocity(500)\n    while True:\n"
                                       "        robot.move(500)\n")
    world = (World.arena(6, 4).time_step_ms(100).obstacle("wall", 3, 0, 0.5, 4)
             .robot("r", "Scout", 1, 2, 0, control=f"python:{tmp_path / 'ahead.py'}"))
    sim = simulation(world)
    assert sim.run_until(lambda s: bool(s.contacts("r")), 200)
    assert sim.contacts("r")[0].touched == "wall"
    assert len(sim.sonar("r")) > 0 and min(sim.sonar("r")) < 300
    assert sim.pose("r").x_mm < 3000


def test_simulations_side_by_side_on_one_host(reporting: Path, simulation: Callable[..., Simulation]) -> None:
    slow, fast = simulation(reporting, params={"speed": 100}), simulation(reporting, params={"speed": 900})
    slow.run(20)
    fast.run(20)
    assert fast.pose("r1").x_mm - 1000 > 8 * (slow.pose("r1").x_mm - 1000)


def test_threads_take_turns_on_a_host_and_a_close_breaks_a_call_off(reporting: Path) -> None:
    host = SimulationHost(near=reporting.parent)
    try:
        slow, fast = (Simulation.of(reporting).host(host).param("speed", v).start() for v in (100, 900))
        with ThreadPoolExecutor(2) as pool:  # (two threads, one link: each call waits for its turn)
            for done in [pool.submit(s.run, 20) for s in (slow, fast)]:
                done.result(timeout=300)
        assert fast.pose("r1").x_mm - 1000 > 8 * (slow.pose("r1").x_mm - 1000)

        sent, closed = threading.Event(), threading.Event()

        def under_way() -> None:  # (the request sent, its answer not read until the host is closed)
            sent.set()
            assert closed.wait(300)

        with ThreadPoolExecutor(1) as pool:
            call = pool.submit(host.call, "run", slow._id, 10, meanwhile=under_way)
            assert sent.wait(300)
            host.close()  # (returns without the call's answer: it stops the host)
            closed.set()
            with pytest.raises(HostError):
                call.result(timeout=300)
        with pytest.raises(HostError, match="closed"):
            host.call("run", fast._id, 1)
    finally:
        host.close()


def test_threads_asking_for_one_warm_host_at_once_start_one(reporting: Path) -> None:
    with ThreadPoolExecutor(3) as pool:
        hosts = list(pool.map(lambda _: _warm_host(99, reporting.parent), range(3)))
    try:
        assert hosts[0] is hosts[1] is hosts[2] and not hosts[0].closed
    finally:
        hosts[0].close()
    again = _warm_host(99, reporting.parent)
    try:
        assert again is not hosts[0] and not again.closed  # (closed: its next use starts another)
    finally:
        again.close()


def test_a_simulation_that_keeps_no_history_refuses_to_say_it(reporting: Path) -> None:
    sim = Simulation.of(reporting).history(False).start()
    try:
        sim.run(3)
        assert sim.pose("r1").x_mm > 1000
        with pytest.raises(ValueError, match="messages are not kept"):
            sim.received("r1")
        with pytest.raises(ValueError, match="contacts are not kept"):
            sim.contacts("r1")
    finally:
        sim.close()

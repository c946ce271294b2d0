"""pytest's fixtures for testing controllers (``robosim.testing``), registered by this package's ``pytest11`` entry
point: installed, they are there in every test session.

    def test_robot1_goes_round(simulation) -> None:
        sim = simulation("square.xml", seed=3)
        sim.run(200)
        assert sim.pose("robot1").x_mm > 1000

``simulation(world, seed=None, params=None, expect_failure=(), step_timeout_s=None)`` starts a simulation of an
environment file (relative to the test file's folder) or a ``World`` built in code, on this session's simulation
host (``robosim_host``: one JVM, started at the first use); it is closed when the test ends, and a robot's control
code that raised then (not expected) fails the test."""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path

import pytest

from robosim.testing import Simulation, SimulationHost, World, shared_host


@pytest.fixture(scope="session")
def robosim_host() -> SimulationHost:
    """This session's simulation host (``robosim.testing.shared_host``): a RoboSim JVM, started at the first use."""
    return shared_host()


@pytest.fixture
def simulation(request: pytest.FixtureRequest) -> Iterator[Callable[..., Simulation]]:
    """A function that starts a simulation (closed at the test's end): ``simulation(world, seed=None, params=None,
    expect_failure=(), step_timeout_s=None)``."""
    started: list[Simulation] = []
    folder = Path(str(request.path)).parent

    def start(world: str | os.PathLike[str] | World, *, seed: int | None = None,
              params: dict[str, object] | None = None, expect_failure: Iterable[str] = (),
              step_timeout_s: float | None = None) -> Simulation:
        if not isinstance(world, World):
            path = Path(world)
            world = path if path.is_absolute() else folder / path
        builder = Simulation.of(world).host(shared_host(folder))
        if seed is not None:
            builder.seed(seed)
        for name, value in (params or {}).items():
            builder.param(name, value)
        for robot in expect_failure:
            builder.expect_failure(robot)
        if step_timeout_s is not None:
            builder.step_timeout(step_timeout_s)
        sim = builder.start()
        started.append(sim)
        return sim

    yield start
    failed: list[BaseException] = []
    for sim in started:  # (each closed, whatever the others raise; the first failure fails the test)
        try:
            sim.close()
        except Exception as e:
            failed.append(e)
    if failed:
        raise failed[0]

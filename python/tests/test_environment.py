"""The package against a real Environment (the conftest's fixture): a robot moved and sensed over the robot link, the
simulation's end, and the run command as a user runs it."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from robosim import Robot, RobotValueError, SimulationOver

from conftest import REPO, Environment, start


def test_a_robot_moves_senses_and_reports_in_a_real_world(environment: Environment) -> None:
    robot = Robot.connect(environment.host, environment.port, "py1")
    assert (robot.name, robot.step_ms, robot.robot_names) == ("py1", 100, ("py1", "still"))
    x0, y0, h0 = robot.pose()
    assert (x0, y0, h0) == (1000.0, 3000.0, 0.0)
    assert robot.parameter("speed", 1.0) == 400.0
    robot.set_velocity(robot.parameter("speed", 1.0))
    assert robot.move(500) == pytest.approx(500.0)
    x1, y1, _ = robot.pose()
    assert (x1 - x0, y1 - y0) == (pytest.approx(500.0), pytest.approx(0.0))
    assert robot.turn(90) == pytest.approx(90.0)
    ranges, angles = robot.sonar_ranges(), robot.sonar_angles_deg()
    assert len(ranges) == len(angles) > 0 and all(r > 0 for r in ranges)
    robot.report("legs", 1)
    with pytest.raises(RobotValueError):
        robot.report("no spaces allowed", 1)
    robot.call("bye")
    code, output = environment.wait()
    assert code == 0, output
    assert "control_failed=0" in output


def test_the_simulations_end_raises_simulation_over(tmp_path: Path) -> None:
    environment = start(tmp_path, 30)
    try:
        robot = Robot.connect(environment.host, environment.port, "py1")
        with pytest.raises(SimulationOver):
            robot.sleep(60_000)
        code, output = environment.wait()
        assert code == 0, output
    finally:
        if environment.process.poll() is None:
            environment.process.kill()
            environment.process.wait(timeout=30)


def test_the_run_command_runs_a_controller_script_until_the_end(environment: Environment) -> None:
    run = subprocess.run(
        [sys.executable, "-m", "robosim", str(REPO / "examples/python/bounce.py"), "--link",
         f"{environment.host}:{environment.port}", "--robot", "py1"],
        capture_output=True, text=True, timeout=120, check=False)
    assert run.returncode == 0, run.stderr
    code, output = environment.wait()
    assert code == 0, output
    assert "steps=300 robots=2" in output and "control_failed=0" in output


def test_the_run_command_says_a_refusal_in_one_line_and_exits_2(environment: Environment) -> None:
    run = subprocess.run(
        [sys.executable, "-m", "robosim", str(REPO / "examples/python/bounce.py"), "--link",
         f"{environment.host}:{environment.port}", "--robot", "zz"],
        capture_output=True, text=True, timeout=120, check=False)
    assert run.returncode == 2
    assert run.stderr == (f"robosim: robot zz at {environment.host}:{environment.port}: {environment.host}:"
                          f"{environment.port}: the simulator refused the link: this link serves robot py1, not "
                          "\"zz\"\n")


def test_help_runs_nothing() -> None:
    run = subprocess.run([sys.executable, "-m", "robosim", "--help"], capture_output=True, text=True, timeout=60,
                         check=False)
    assert run.returncode == 0 and "usage: python -m robosim" in run.stdout and run.stderr == ""


def test_the_session_hardware_sim_readme_shows_is_a_real_one(environment: Environment,
                                                              monkeypatch: pytest.MonkeyPatch) -> None:
    import json

    import robosim.frames
    from robosim.frames import Frames

    said: list[str] = []

    class Recorded(Frames):
        def send(self, value: object) -> None:
            said.append("> " + json.dumps(value))
            super().send(value)

        def receive(self) -> object:
            value = super().receive()
            said.append("< " + json.dumps(value))
            return value

    monkeypatch.setattr(robosim.frames, "Frames", Recorded)  # (the one the link's handshake makes)
    robot = Robot.connect(environment.host, environment.port, "py1")
    robot.pose()
    robot.set_velocity(robot.parameter("speed", 300.0))
    robot.move(500)
    robot.turn(-30)
    robot.pose()
    robot.send("still", "hello")
    robot.receive()
    robot.report("legs", 1)
    with pytest.raises(RobotValueError):
        robot.sensor("laser")
    robot.call("bye")
    readme = (REPO / "hardware-sim/README.md").read_text(encoding="utf-8")
    parts = readme.split("<!-- a real session: python/tests/test_environment.py -->\n```text\n", 1)
    assert len(parts) == 2, "no session in hardware-sim/README.md; this one was:\n" + "\n".join(said)
    assert "\n".join(said) + "\n" == parts[1].split("```")[0], "this session was:\n" + "\n".join(said)
    assert environment.wait()[0] == 0

"""Tests of square.py (and of wander.py beside it) with pytest and ``robosim.testing``: a simulation of square.xml,
run and asked from the test (python/README.md, "Testing controllers"). Run them with

    pip install "./python[test]"
    python -m pytest -p no:cacheprovider examples/python
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from robosim.testing import ControlFailed, Simulation, World

HERE = Path(__file__).parent


def test_robot1_drives_a_square_and_tells_robot2_each_corner(simulation: Callable[..., Simulation]) -> None:
    sim = simulation("square.xml")
    assert sim.pose("robot1") == (2000.0, 2000.0, 0.0)
    assert sim.run_until(lambda s: len(s.received("robot2")) == 2, 400)
    first, second = sim.received("robot2")
    assert (first.sender, second.sender) == ("robot1", "robot1")
    assert first.text.startswith("corner at 4000,2000;")
    assert second.text.startswith("corner at 4000,4000;")
    x, y, heading = sim.pose("robot1")  # (a step on: the message came with the step after the corner)
    assert (round(y), round(heading)) == (4000, 180) and 3500 < x < 4000


def test_a_controller_that_raises_fails_the_test_with_its_traceback(tmp_path: Path) -> None:
    script = tmp_path / "careless.py"
    script.write_text("def control(robot):\n    robot.move(100)\n    nothing = None\n"
                      "    robot.report('n', len(nothing))\n")
    world = World.arena(4, 4).robot("a", "Scout", 1, 1, 0, control=f"python:{script}")
    with pytest.raises(ControlFailed) as failed, Simulation.of(world).start() as sim:
        sim.run(50)
    assert failed.value.failures[0].robot == "a"
    assert "careless.py\", line 4, in control" in str(failed.value)
    assert "TypeError: object of type 'NoneType' has no len()" in str(failed.value)


def test_the_notebook_style_sweep_tabulates_and_plots(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("pandas")
    pytest.importorskip("matplotlib")
    import sweep_and_plot  # noqa: PLC0415 (this folder's script)

    out = tmp_path / "speed.png"
    assert sweep_and_plot.main(["--steps", "50", "--seeds", "2", "--speeds", "200,800", "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "distance_m" in printed and "plot: " in printed
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"

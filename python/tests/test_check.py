"""``python -m robosim --check``: the scripts a simulator is about to run, compiled, not run."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path


def check(*scripts: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "robosim", "--check", *map(str, scripts)], capture_output=True,
                          text=True, timeout=60)


def test_scripts_that_compile_say_nothing(tmp_path: Path) -> None:
    good = tmp_path / "good.py"
    good.write_text("def control(robot):\n    raise RuntimeError('never run by a check')\n")
    done = check(good)
    assert (done.returncode, done.stdout, done.stderr) == (0, "", "")


def test_each_script_that_does_not_compile_is_its_line(tmp_path: Path) -> None:
    colon = tmp_path / "colon.py"
    colon.write_text("def control(robot):\n    while True\n        robot.move(1)\n")
    tabs = tmp_path / "tabs.py"
    tabs.write_text("def control(robot):\n\tx = 1\n        return x\n")
    good = tmp_path / "good.py"
    good.write_text("x = 1\n")
    done = check(colon, good, tabs, tmp_path / "none.py")
    assert done.returncode == 3
    lines = done.stdout.splitlines()
    assert lines[0] == f"{colon}:2: SyntaxError: expected ':'"
    assert lines[1] == f"{tabs}:3: TabError: inconsistent use of tabs and spaces in indentation"
    assert lines[2].startswith(f"{tmp_path / 'none.py'}: [Errno 2]")
    assert len(lines) == 3


def test_a_run_takes_one_script() -> None:
    done = subprocess.run([sys.executable, "-m", "robosim", "a.py", "b.py", "--robot", "r", "--link", "h:1"],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 2 and "one script (several only with --check)" in done.stderr

"""Fixtures: a real RoboSim Environment (scripts/headless.sh, in one JVM, on ports the system picks) whose robot
``py1`` waits for its controller on the robot link (robosim.hardware.link.LinkedControl)."""

from __future__ import annotations

import os
import re
import subprocess
import sys
import threading
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
TRANSCRIPT = REPO / "hardware-sim/src/test/resources/robot-link/transcript.txt"
#: How long the Environment gets to start (a build of RoboSim, if it is not built, takes longer: build first).
START_S = 120.0
WAITING = re.compile(r"py1: waiting for its controller on (127\.0\.0\.1):(\d+) \(the robot link\)")

WORLD = """<?xml version="1.0" encoding="UTF-8"?>
<environment name="link" timeStepMs="100" seed="7">
  <param name="speed" value="400"/>
  <arena width="6" height="6"/>
  <robots>
    <robot name="py1" type="Scout" control="robosim.hardware.link.LinkedControl" x="1" y="3" heading="0">
      <param name="link_port" value="0"/>
    </robot>
    <robot name="still" type="Scout" control="robosim.examples.BackAndForth" x="5" y="5" heading="90"/>
  </robots>
</environment>
"""


@dataclass
class Environment:
    """A headless run of WORLD: where py1's link is, and the run's output so far."""

    process: subprocess.Popen[str]
    host: str
    port: int
    lines: list[str] = field(default_factory=list)

    def wait(self, timeout: float = START_S) -> tuple[int, str]:
        """Its exit code and its output (stdout and stderr, as they came)."""
        code = self.process.wait(timeout=timeout)
        return code, "\n".join(self.lines)


def start(tmp: Path, steps: int) -> Environment:
    world = tmp / "link.xml"
    world.write_text(WORLD, encoding="utf-8")
    env = {k: v for k, v in os.environ.items() if not k.startswith("ROBOSIM_")}
    env["ROBOSIM_PYTHON"] = sys.executable
    process = subprocess.Popen(
        ["bash", str(REPO / "scripts/headless.sh"), "--one-jvm", "--env", str(world), "--steps", str(steps)],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, text=True, env=env,
        start_new_session=True)
    assert process.stdout is not None
    lines: list[str] = []
    found = threading.Event()
    where: list[tuple[str, int]] = []

    def read() -> None:
        assert process.stdout is not None
        for line in process.stdout:
            lines.append(line.rstrip("\n"))
            m = WAITING.search(line)
            if m and not found.is_set():
                where.append((m.group(1), int(m.group(2))))
                found.set()
        found.set()

    threading.Thread(target=read, name="headless-output", daemon=True).start()
    if not found.wait(START_S) or not where:
        process.kill()
        pytest.fail("the Environment did not say where py1 waits:\n" + "\n".join(lines[-30:]))
    return Environment(process, where[0][0], where[0][1], lines)


@pytest.fixture
def environment(tmp_path: Path) -> Iterator[Environment]:
    """A run of 300 steps whose robot py1 waits for its controller."""
    env = start(tmp_path, 300)
    try:
        yield env
    finally:
        if env.process.poll() is None:
            env.process.kill()
            env.process.wait(timeout=30)

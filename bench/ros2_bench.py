"""The ROS 2 bridge's speed (docs/PERFORMANCE.md, "The ROS 2 bridge"): bench/ros2/ten.xml, ten robots driven by ROS 2
with every topic published every step, through a Zenoh router to a subscriber of every topic in this process:

- ``free``: the bridge as fast as it goes (``--real-time-factor 0``), no node commanding, every sample delivered to
  this process and left in Zenoh's ring buffer (none handed to Python: the bridge's own cost);
- ``free-python``: the same, each sample handed to a Python callback (a node in Python taking every message, on the
  same two cores);
- ``lockstep``: ``--lockstep``, this process a node that answers each /clock with a cmd_vel for each of the ten (the
  other samples in the ring buffer);
- ``floor``: the same world's steps driven over the simulation link alone (``robosim.testing``'s ``drive``, the
  bridge's own loop without ROS), the thread shape's floor: the bridge's cost is its ratio to it.

Each is run ``--runs`` times in turn (ABAB...), medians and ratios printed. Needs ``pip install "./python[ros2]"`` and
a built RoboSim. ``python bench/ros2_bench.py --runs 3 --steps 3000``."""

from __future__ import annotations

import argparse
import os
import re
import socket
import statistics
import subprocess
import sys
import time
from pathlib import Path

import zenoh
from rosbags.typesys import Stores, get_typestore

from robosim.ros2.bridge import session_config
from robosim.ros2.graph import Attachment, gid, topic_keyexpr
from robosim.testing import Simulation

HERE = Path(__file__).resolve().parent
WORLD = HERE / "ros2/ten.xml"
TYPES = get_typestore(Stores.ROS2_KILTED)
DRIVEN = [f"s{i}" for i in range(1, 6)] + [f"f{i}" for i in range(1, 6)]


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def bridge_rate(port: int, steps: int, python: bool, *pace: str) -> tuple[float, int]:
    """Runs the bridge; its steps a second (its own log line) and the samples this process's Python took."""
    session = zenoh.open(session_config("peer", [f"tcp/127.0.0.1:{port}"], ["tcp/127.0.0.1:0"]))
    received = [0]
    twist = bytes(TYPES.serialize_cdr(TYPES.types["geometry_msgs/msg/Twist"](
        linear=TYPES.types["geometry_msgs/msg/Vector3"](x=0.05, y=0.0, z=0.0),
        angular=TYPES.types["geometry_msgs/msg/Vector3"](x=0.0, y=0.0, z=0.1)), "geometry_msgs/msg/Twist"))
    commands = [(session.declare_publisher(topic_keyexpr(0, f"/{r}/cmd_vel", "geometry_msgs/msg/Twist",
                                                         TYPES.hash_rihs01("geometry_msgs/msg/Twist"))),
                 Attachment(gid(f"bench {r}"))) for r in DRIVEN]
    clock_key = topic_keyexpr(0, "/clock", "rosgraph_msgs/msg/Clock", TYPES.hash_rihs01("rosgraph_msgs/msg/Clock"))

    def heard(sample: zenoh.Sample) -> None:
        received[0] += 1
        if "--lockstep" in pace and str(sample.key_expr) == clock_key:
            for publisher, attachment in commands:
                publisher.put(twist, attachment=attachment.next())

    subscribers = [session.declare_subscriber("0/**", heard) if python
                   else session.declare_subscriber("0/**", zenoh.handlers.RingChannel(1))]
    if "--lockstep" in pace and not python:
        subscribers.append(session.declare_subscriber(clock_key, heard))
    try:
        run = subprocess.run([sys.executable, "-m", "robosim.ros2", "bridge", str(WORLD), "--connect",
                              f"tcp/127.0.0.1:{port}", "--steps", str(steps), *pace], capture_output=True, text=True,
                             env={**os.environ, "ROBOSIM_PYTHON": sys.executable}, timeout=3600)
        found = re.search(r"the bridge ends after (\d+) steps \(([\d.]+) steps/s", run.stderr)
        if run.returncode != 0 or not found:
            raise SystemExit(f"the bridge failed ({run.returncode}):\n{run.stderr[-3000:]}")
        time.sleep(0.5)  # (the last samples on their way)
        return float(found.group(2)), received[0]
    finally:
        for subscriber in subscribers:
            subscriber.undeclare()
        session.close()


def floor_rate(steps: int) -> float:
    """The world's steps driven over the simulation link alone, every driven robot commanded, steps a second after
    the first."""
    with Simulation.of(WORLD).start() as sim:
        sim.drive({})
        commands = {r: (50.0, 5.7) for r in DRIVEN}
        start = time.perf_counter()
        for _ in range(steps - 1):
            sim.drive(commands)
        return (steps - 1) / (time.perf_counter() - start)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--steps", type=int, default=3000)
    args = parser.parse_args()
    port = free_port()
    router = subprocess.Popen([sys.executable, "-m", "robosim.ros2", "router", "--listen", f"tcp/127.0.0.1:{port}"],
                              stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    try:
        assert router.stdout is not None and "listening" in router.stdout.readline()
        kinds = {"free": (False, ["--real-time-factor", "0"]), "free-python": (True, ["--real-time-factor", "0"]),
                 "lockstep": (False, ["--lockstep"])}
        rates: dict[str, list[float]] = {k: [] for k in kinds} | {"floor": []}
        samples: dict[str, list[int]] = {k: [] for k in kinds}
        for run in range(args.runs):
            for kind, (python, pace) in kinds.items():
                rate, got = bridge_rate(port, args.steps, python, *pace)
                rates[kind].append(rate)
                samples[kind].append(got)
            rates["floor"].append(floor_rate(args.steps))
            print(f"run {run + 1}: " + ", ".join(f"{k} {v[-1]:.0f} steps/s" for k, v in rates.items()), flush=True)
        floor = statistics.median(rates["floor"])
        print(f"world {WORLD.relative_to(HERE.parent)}, {args.steps} steps, {args.runs} runs, medians:")
        for kind in kinds:
            median = statistics.median(rates[kind])
            print(f"  {kind}: {median:.0f} steps/s, {median / floor:.2f} of the floor; samples to Python a step "
                  f"{statistics.median(samples[kind]) / args.steps:.0f}")
        print(f"  floor (simulation link's drive alone): {floor:.0f} steps/s")
    finally:
        router.terminate()
        router.wait()


if __name__ == "__main__":
    main()

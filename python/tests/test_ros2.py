"""The ROS 2 bridge against real components: a Zenoh router started by the project's own command (``python -m
robosim.ros2 router``), the bridge running examples/ros2/arena.xml in a RoboSim JVM, and, as the ROS 2 node, the
ROBOTIS package ``zenoh-ros2-sdk`` (an implementation of rmw_zenoh's conventions nobody on this project wrote), given
every message definition from rosbags' Kilted type store so that it never reaches out to clone one. Every payload is
decoded by rosbags; every MCAP file is read back by ``mcap`` and ``mcap-ros2-support``."""

from __future__ import annotations

import csv
import math
import os
import re
import signal
import socket
import struct
import subprocess
import sys
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest
import zenoh
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory
from rosbags.typesys import Stores, get_typestore

from robosim.ros2.bridge import session_config

REPO = Path(__file__).resolve().parents[2]
WORLD = REPO / "examples/ros2/arena.xml"
TYPES = get_typestore(Stores.ROS2_KILTED)
#: Every wait's limit, s (a loaded machine is slow; nothing here waits this long when things go right).
WAIT_S = 120.0
#: No test may reach the network: git (which the SDK clones missing message definitions with) takes no https.
os.environ["GIT_ALLOW_PROTOCOL"] = "file"

#: The world's topics and their types, as a ROS 2 user reads them in python/README.md (a cmd_vel takes a
#: TwistStamped too: CMD_VEL_TYPES).
TOPICS = {
    "/clock": "rosgraph_msgs/msg/Clock", "/tf": "tf2_msgs/msg/TFMessage", "/tf_static": "tf2_msgs/msg/TFMessage",
    "/map": "nav_msgs/msg/OccupancyGrid", "/obstacles": "visualization_msgs/msg/MarkerArray",
    "/robot1/odom": "nav_msgs/msg/Odometry", "/robot1/cmd_vel": "geometry_msgs/msg/Twist",
    "/robot1/scan": "sensor_msgs/msg/LaserScan", "/robot1/received": "std_msgs/msg/String",
    "/robot2/odom": "nav_msgs/msg/Odometry", "/robot2/cmd_vel": "geometry_msgs/msg/Twist",
    "/robot2/proximity": "sensor_msgs/msg/Range", "/robot2/ground": "std_msgs/msg/Float64MultiArray",
    "/robot2/received": "std_msgs/msg/String", "/w1/odom": "nav_msgs/msg/Odometry",
}
CMD_VEL_TYPES = {"geometry_msgs/msg/Twist", "geometry_msgs/msg/TwistStamped"}
#: Published once, kept for those who come later (transient local).
LATCHED = ("/tf_static", "/map", "/obstacles")


class Process:
    """A process of ours, its output (stdout and stderr) read as it comes, a line at a time."""

    def __init__(self, args: list[str]) -> None:
        env = {k: v for k, v in os.environ.items() if not k.startswith("ROBOSIM_")}
        env["ROBOSIM_PYTHON"] = sys.executable
        self.process = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                        stdin=subprocess.DEVNULL, text=True, env=env, start_new_session=True)
        self.lines: list[str] = []
        self._said = threading.Condition()
        self._read_all = False
        threading.Thread(target=self._read, name=f"output-{args[3] if len(args) > 3 else args[-1]}",
                         daemon=True).start()

    def _read(self) -> None:
        assert self.process.stdout is not None
        for line in self.process.stdout:
            with self._said:
                self.lines.append(line.rstrip("\n"))
                self._said.notify_all()
        with self._said:
            self._read_all = True
            self._said.notify_all()

    def await_line(self, pattern: str, timeout: float | None = None) -> re.Match[str] | None:
        """The first line matching ``pattern``, waiting for it; None if the process ended without one, or, given a
        ``timeout`` (s), if none came within it."""
        wanted = re.compile(pattern)
        deadline = time.monotonic() + (WAIT_S if timeout is None else timeout)
        with self._said:
            while True:
                for line in self.lines:
                    found = wanted.search(line)
                    if found:
                        return found
                if self._read_all:
                    return None
                if time.monotonic() > deadline:
                    if timeout is not None:
                        return None
                    raise AssertionError(f"no line like {pattern!r} within {WAIT_S} s:\n" + "\n".join(self.lines))
                self._said.wait(0.5)

    def end(self, stop: bool = False) -> int:
        if stop and self.process.poll() is None:
            os.killpg(self.process.pid, signal.SIGTERM)
        try:
            code = self.process.wait(timeout=WAIT_S)
        except subprocess.TimeoutExpired:  # (nothing of it left behind: its JVM is in its process group)
            os.killpg(self.process.pid, signal.SIGKILL)
            self.process.wait()
            raise
        with self._said:  # (the reader takes the last lines)
            self._said.wait_for(lambda: self._read_all, timeout=WAIT_S)
        return code

    def output(self) -> str:
        with self._said:
            return "\n".join(self.lines)


def read_attachment(raw: bytes) -> tuple[int, int, bytes]:
    """An rmw_zenoh attachment's sequence number, time (ns) and GID (``<q q B 16s``, the GID's length 16)."""
    assert len(raw) == 33 and raw[16] == 16, raw
    sequence, stamp, _, publisher = struct.unpack("<qqB16s", raw)
    return sequence, stamp, publisher


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@pytest.fixture
def router() -> Iterator[tuple[Process, int]]:
    """A Zenoh router on a loopback port, started as a user starts one (a port another took meanwhile: another)."""
    for _ in range(5):
        port = _free_port()
        process = Process([sys.executable, "-m", "robosim.ros2", "router", "--listen", f"tcp/127.0.0.1:{port}"])
        if process.await_line(r"zenoh router listening on") is not None:
            try:
                yield process, port
            finally:
                process.end(stop=True)
            return
        process.end()
    raise AssertionError("no Zenoh router started on five free ports")


def bridge(port: int, *args: str) -> Process:
    """The bridge on examples/ros2/arena.xml, connected to the router at ``port``, its node announced."""
    process = Process([sys.executable, "-m", "robosim.ros2", "bridge", str(WORLD), "--connect",
                       f"tcp/127.0.0.1:{port}", *args])
    assert process.await_line(r"ROS 2 node /robosim on domain 0") is not None, process.output()
    return process


@pytest.fixture(scope="module")
def definitions(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Every message definition of ROS 2 Kilted as .msg files, from rosbags, where the SDK looks for them."""
    from zenoh_ros2_sdk.message_registry import get_registry

    root = tmp_path_factory.mktemp("msg")
    for name in TYPES.types:
        if "/msg/" in name:
            package, _, message = name.split("/")
            text = TYPES.generate_msgdef(name, ros_version=2)[0].split("\n" + "=" * 80)[0]
            (root / package / "msg").mkdir(parents=True, exist_ok=True)
            (root / package / "msg" / f"{message}.msg").write_text(text + "\n", encoding="utf-8")
    assert get_registry(str(root)).messages_dir == root, "the SDK's registry was made before with another folder"
    return root


def _pose_log(path: Path) -> dict[tuple[int, str], tuple[float, float, float]]:
    with path.open(encoding="utf-8") as f:
        return {(int(r["step"]), r["robot"]): (float(r["x_m"]), float(r["y_m"]), float(r["heading_deg"]))
                for r in csv.DictReader(f)}


def _until(done: Callable[[], bool], what: str) -> None:
    deadline = time.monotonic() + WAIT_S
    while not done():
        if time.monotonic() > deadline:
            raise AssertionError(f"not within {WAIT_S} s: {what}")
        time.sleep(0.05)


def test_a_ros2_node_sees_the_topics_and_drives_the_robots_in_lock_step(router: tuple[Process, int],
                                                                         definitions: Path, tmp_path: Path) -> None:
    from zenoh_ros2_sdk import ROS2Publisher, ROS2Subscriber, ZenohSession, get_topic_names_and_types

    _, port = router
    steps = 40
    running = bridge(port, "--lockstep", "--steps", str(steps), "--pose-log", str(tmp_path / "poses.csv"),
                     "--mcap", str(tmp_path / "run.mcap"))
    try:
        listed: dict[str, list[str]] = {}

        def all_listed() -> bool:
            listed.clear()
            listed.update(get_topic_names_and_types(router_port=port, timeout=1.0))
            return all(t in listed for t in TOPICS)

        _until(all_listed, "the topic list shows the bridge's topics")
        assert {t: set(listed[t]) for t in TOPICS} == {
            t: CMD_VEL_TYPES if t.endswith("/cmd_vel") else {kind} for t, kind in TOPICS.items()}

        forward = ROS2Publisher("/robot1/cmd_vel", "geometry_msgs/msg/Twist", router_port=port, node_name="driver1")
        spin = ROS2Publisher("/robot2/cmd_vel", "geometry_msgs/msg/TwistStamped", router_port=port,
                             node_name="driver2")  # (as Nav2 sends it)
        store = forward.session_mgr.store.types
        vector = store["geometry_msgs/msg/Vector3"]
        still = store["builtin_interfaces/msg/Time"](sec=0, nanosec=0)
        clocks: set[int] = set()
        scans: list[int] = []

        def on_clock(message: Any) -> None:  # (a node of lock-step: each step's clock answered with a command)
            clocks.add(message.clock.sec * 1_000_000_000 + message.clock.nanosec)
            forward.publish(linear=vector(x=0.2, y=0.0, z=0.0), angular=vector(x=0.0, y=0.0, z=0.0))
            spin.publish(header=store["std_msgs/msg/Header"](stamp=still, frame_id="robot2/base_link"),
                         twist=store["geometry_msgs/msg/Twist"](linear=vector(x=0.0, y=0.0, z=0.0),
                                                                angular=vector(x=0.0, y=0.0, z=0.5)))

        ROS2Subscriber("/robot1/scan", "sensor_msgs/msg/LaserScan", callback=lambda m: scans.append(len(m.ranges)),
                       router_port=port, node_name="scans")
        ROS2Subscriber("/clock", "rosgraph_msgs/msg/Clock", callback=on_clock, router_port=port, node_name="clock")
        assert running.end() == 0, running.output()
    finally:
        running.end(stop=True)
        ZenohSession.get_instance(router_port=port).close()
    assert clocks == {k * 100_000_000 for k in range(1, steps + 1)}
    assert scans and set(scans) == {271}  # (270 degrees, a beam a degree)
    poses = _pose_log(tmp_path / "poses.csv")
    assert sorted(step for step, robot in poses if robot == "robot1") == list(range(1, steps + 1))
    x, y, heading = poses[(steps, "robot1")]
    assert math.isclose(x, 1.0 + 0.2 * 0.1 * (steps - 1), abs_tol=1e-9) and y == 1.0 and heading == 0.0
    assert math.isclose(poses[(steps, "robot2")][2], math.degrees(0.5 * 0.1 * (steps - 1)), abs_tol=1e-9)
    assert_mcap_matches(tmp_path / "run.mcap", poses)


def assert_mcap_matches(path: Path, poses: dict[tuple[int, str], tuple[float, float, float]]) -> set[str]:
    """Every message of the MCAP decodes; each robot's pose in it (its odometry, placed by /tf_static's map ->
    odom) is the pose log's at every step the log has. The topics in it."""
    starts: dict[str, tuple[float, float, float]] = {}
    seen: dict[tuple[int, str], tuple[float, float, float]] = {}
    topics: set[str] = set()
    with path.open("rb") as f:
        reader = make_reader(f, decoder_factories=[DecoderFactory()])
        for schema, channel, message, decoded in reader.iter_decoded_messages():
            assert schema is not None and schema.encoding == "ros2msg" and channel.message_encoding == "cdr"
            assert TYPES.deserialize_cdr(message.data, schema.name) is not None
            topics.add(channel.topic)
            if channel.topic == "/tf_static":
                for t in decoded.transforms:
                    if t.header.frame_id == "map":
                        q = t.transform.rotation
                        starts[t.child_frame_id.split("/")[0]] = (t.transform.translation.x, t.transform.translation.y,
                                                                  2 * math.atan2(q.z, q.w))
            elif channel.topic.endswith("/odom"):
                robot = channel.topic.split("/")[1]
                sx, sy, syaw = starts[robot]
                p = decoded.pose.pose
                yaw = 2 * math.atan2(p.orientation.z, p.orientation.w)
                step = message.log_time // 100_000_000
                seen[(step, robot)] = (sx + p.position.x * math.cos(syaw) - p.position.y * math.sin(syaw),
                                       sy + p.position.x * math.sin(syaw) + p.position.y * math.cos(syaw), syaw + yaw)
    assert set(poses) <= set(seen), sorted(set(poses) - set(seen))[:5]
    for key, (x, y, heading) in poses.items():
        sx, sy, syaw = seen[key]
        assert math.isclose(sx, x, abs_tol=1e-9) and math.isclose(sy, y, abs_tol=1e-9), (key, seen[key], poses[key])
        assert abs(math.remainder(math.radians(heading) - syaw, math.tau)) < 1e-9, (key, seen[key], poses[key])
    return topics


def _peer(port: int) -> zenoh.Session:
    return zenoh.open(session_config("peer", [f"tcp/127.0.0.1:{port}"], ["tcp/127.0.0.1:0"]))


def _twist(x: float, turn: float) -> bytes:
    message = TYPES.types["geometry_msgs/msg/Twist"](
        linear=TYPES.types["geometry_msgs/msg/Vector3"](x=x, y=0.0, z=0.0),
        angular=TYPES.types["geometry_msgs/msg/Vector3"](x=0.0, y=0.0, z=turn))
    return bytes(TYPES.serialize_cdr(message, "geometry_msgs/msg/Twist"))


def _key(topic: str, kind: str) -> str:
    name = kind.split("/")
    return f"0/{topic.strip('/')}/{name[0]}::msg::dds_::{name[2]}_/{TYPES.hash_rihs01(kind)}"


def test_every_sample_on_the_wire_is_rmw_zenohs_and_decodes(router: tuple[Process, int], tmp_path: Path) -> None:
    _, port = router
    session = _peer(port)
    samples: list[tuple[str, bytes, bytes | None]] = []
    latched: dict[str, bytes] = {}
    clocks: list[int] = []
    heard_clock = threading.Condition()

    def heard(sample: zenoh.Sample) -> None:
        key = str(sample.key_expr)
        attachment = sample.attachment.to_bytes() if sample.attachment is not None else None
        samples.append((key, sample.payload.to_bytes(), attachment))
        if key.startswith("0/clock/"):
            with heard_clock:
                clocks.append(TYPES.deserialize_cdr(sample.payload.to_bytes(), "rosgraph_msgs/msg/Clock").clock.nanosec)
                heard_clock.notify_all()

    try:
        session.declare_subscriber("0/**", heard)
        running = bridge(port, "--lockstep", "--steps", "4")
        try:
            tokens: set[str] = set()

            def all_declared() -> bool:
                tokens.update(str(r.ok.key_expr) for r in session.liveliness().get("@ros2_lv/0/**", timeout=2.0)
                              if r.ok is not None)
                return sum("/MP/" in t or "/MS/" in t for t in tokens if "/robosim/" in t) == len(TOPICS) + 2

            _until(all_declared, "the bridge's liveliness tokens")
            node = next(t for t in tokens if t.endswith("/NN/%/%/robosim"))
            zid = node.split("/")[2]
            assert re.fullmatch(r"@ros2_lv/0/[0-9a-f]+/0/0/NN/%/%/robosim", node)
            scan = [t for t in tokens if "/MP/" in t and "%robot1%scan" in t]
            assert len(scan) == 1 and re.fullmatch(
                rf"@ros2_lv/0/{zid}/0/\d+/MP/%/%/robosim/%robot1%scan/sensor_msgs::msg::dds_::LaserScan_/"
                rf"{TYPES.hash_rihs01('sensor_msgs/msg/LaserScan')}/::,10:,:,:,,", scan[0]), scan
            assert any(t.endswith(f"/MS/%/%/robosim/%robot2%cmd_vel/geometry_msgs::msg::dds_::Twist_/"
                                  f"{TYPES.hash_rihs01('geometry_msgs/msg/Twist')}/::,10:,:,:,,") for t in tokens)
            assert any(t.endswith(f"/%map/nav_msgs::msg::dds_::OccupancyGrid_/"
                                  f"{TYPES.hash_rihs01('nav_msgs/msg/OccupancyGrid')}/:1:,1:,:,:,,") for t in tokens)

            for topic in LATCHED:  # (subscribers that come after they were published get them: transient local)
                zenoh.ext.declare_advanced_subscriber(
                    session, _key(topic, TOPICS[topic]),
                    lambda s, topic=topic: latched.setdefault(topic, s.payload.to_bytes()),
                    history=zenoh.ext.HistoryConfig(detect_late_publishers=True))
            _until(lambda: len(latched) == len(LATCHED), "the latched topics for late subscribers")
            grid = TYPES.deserialize_cdr(latched["/map"], "nav_msgs/msg/OccupancyGrid")
            assert (grid.info.width, grid.info.height) == (120, 80)
            assert math.isclose(grid.info.resolution, 0.05, abs_tol=1e-7)
            assert sum(grid.data == 100) == 16 * 16 + 40 * 2  # (the 0.8 m box, the 2 m x 0.1 m wall)
            for topic in ("/tf_static", "/obstacles"):
                assert TYPES.deserialize_cdr(latched[topic], TOPICS[topic]) is not None

            answered: set[int] = set()
            expected = {k * 100_000_000 for k in range(1, 5)}
            attachment = 0
            deadline = time.monotonic() + WAIT_S
            while answered != expected:  # (a node of our own: each step's clock answered once)
                assert time.monotonic() < deadline, f"clocks answered {sorted(answered)}:\n{running.output()}"
                with heard_clock:
                    done = set(answered)
                    heard_clock.wait_for(lambda done=done: set(clocks) - done, timeout=1.0)
                    fresh = set(clocks) - done
                for _ in fresh:
                    for robot in ("robot1", "robot2"):
                        attachment += 1
                        session.put(_key(f"/{robot}/cmd_vel", "geometry_msgs/msg/Twist"), _twist(0.1, 0.0),
                                    attachment=int.to_bytes(attachment, 8, "little") + bytes(8) + b"\x10" + bytes(16),
                                    congestion_control=zenoh.CongestionControl.BLOCK)
                answered |= fresh
            assert running.end() == 0, running.output()
        finally:
            running.end(stop=True)
    finally:
        session.close()
    by_key: dict[str, list[tuple[bytes, bytes | None]]] = {}
    for key, payload, attachment in samples:
        if "/cmd_vel/" not in key:
            by_key.setdefault(key, []).append((payload, attachment))
    every = {_key(t, k) for t, k in TOPICS.items() if not t.endswith("/cmd_vel")}
    assert {k for k in every if not k.startswith(("0/robot1/received/", "0/robot2/received/", "0/tf_static/",
                                                  "0/map/", "0/obstacles/"))} <= set(by_key) <= every
    for key, got in by_key.items():
        kind = next(k for t, k in TOPICS.items() if _key(t, k) == key)
        sequences = []
        for payload, attachment in got:
            assert attachment is not None
            sequence, stamp, gid = read_attachment(attachment)
            sequences.append(sequence)
            assert abs(stamp - time.time_ns()) < 3600 * 10**9 and len(gid) == 16
            assert TYPES.deserialize_cdr(payload, kind) is not None
        assert len(set(sequences)) == len(sequences) and min(sequences) >= 1, key


def put_until(running: Process, put: Callable[[], object], line: str) -> None:
    """Puts until the bridge says ``line`` (a sample sent as a new peer's route forms may find none): a second a try."""
    deadline = time.monotonic() + WAIT_S
    while time.monotonic() < deadline:
        put()
        if running.await_line(line, timeout=1.0):
            return
    raise AssertionError(f"no line like {line!r} within {WAIT_S} s:\n" + running.output())


def test_bad_commands_and_a_lost_router_are_said_and_the_world_goes_on(router: tuple[Process, int],
                                                                        tmp_path: Path) -> None:
    process, port = router
    session = _peer(port)
    clocks: list[int] = []
    session.declare_subscriber(_key("/clock", "rosgraph_msgs/msg/Clock"),
                               lambda s: clocks.append(TYPES.deserialize_cdr(s.payload.to_bytes(),
                                                                             "rosgraph_msgs/msg/Clock").clock.nanosec))
    running = bridge(port, "--lockstep", "--pose-log", str(tmp_path / "poses.csv"))
    try:
        _until(lambda: bool(clocks), "the first step's clock")  # (a command before it would answer no step)
        key1 = _key("/robot1/cmd_vel", "geometry_msgs/msg/Twist")
        key2 = _key("/robot2/cmd_vel", "geometry_msgs/msg/Twist")
        string = bytes(TYPES.serialize_cdr(TYPES.types["std_msgs/msg/String"](data="forward!"), "std_msgs/msg/String"))
        block = zenoh.CongestionControl.BLOCK  # (none of ours dropped on the way)
        put_until(running, lambda: session.put(key1, string, congestion_control=block),
                  r"robot1: a cmd_vel of 17 bytes, not a geometry_msgs/msg/Twist in CDR .*: "
                  r"refused \(1 so far\); the robot keeps its last command")
        put_until(running, lambda: session.put(key1, _twist(math.nan, 0.0), congestion_control=block),
                  r"robot1: a cmd_vel with a value that is not a finite number: refused \(1 so far\)")
        session.put(key1, _twist(1e306, 0.0), congestion_control=block)  # (finite, beyond any robot: held to its top)
        flood = time.monotonic()
        for _ in range(3000):  # (a flood of bad ones: a line every 10 s at most, each counted)
            session.put(key1, b"\x00\x01\x00\x00junk", congestion_control=block)
        for _ in range(2000):  # (a flood of good ones: each step takes the newest)
            session.put(key1, _twist(0.3, 0.0), congestion_control=block)
        session.put(key2, _twist(0.0, 0.0), congestion_control=block)  # (then robot2's: step 2 has both)
        _until(lambda: len(set(clocks)) >= 2, "a step driven by the good commands")
        process.end(stop=True)  # (the router goes)
        assert running.await_line(r"the Zenoh router \w+ went away: the world goes on")
        assert running.process.poll() is None
    finally:
        session.close()
        code = running.end(stop=True)
    assert code == 0, running.output()
    assert re.search(r"the bridge ends after \d+ steps", running.output())
    said = len(re.findall(r"robot1: a cmd_vel of 8 bytes", running.output()))
    assert said <= 1 + (time.monotonic() - flood) / 10, running.output()
    total = re.search(r"robot1: (\d+) cmd_vel refused in all \(nan (\d+), size (\d+)\)", running.output())
    assert total and int(total.group(2)) >= 1 and int(total.group(3)) >= 3001, running.output()
    poses = _pose_log(tmp_path / "poses.csv")
    assert math.isclose(poses[(2, "robot1")][0], 1.0 + 0.03, abs_tol=1e-9)  # (step 1 stood still; step 2 at 0.3 m/s)


def test_paced_a_command_holds_its_timeout_and_as_fast_as_it_goes_the_mcap_has_every_step(
        router: tuple[Process, int], tmp_path: Path) -> None:
    _, port = router
    session = _peer(port)
    clocks: list[int] = []
    session.declare_subscriber(_key("/clock", "rosgraph_msgs/msg/Clock"), lambda s: clocks.append(1))
    running = bridge(port, "--real-time-factor", "2", "--steps", "100", "--command-timeout", "0.5", "--pose-log",
                     str(tmp_path / "paced.csv"))
    try:
        command = session.declare_publisher(_key("/robot1/cmd_vel", "geometry_msgs/msg/Twist"),
                                            congestion_control=zenoh.CongestionControl.BLOCK)
        _until(lambda: command.matching_status.matching, "the bridge's cmd_vel subscriber, seen from here")
        command.put(_twist(0.2, 0.0))  # (once: it holds 0.5 s of simulated time)
    finally:
        session.close()
    assert running.end() == 0, running.output()
    xs = [x for (step, robot), (x, _, _) in sorted(_pose_log(tmp_path / "paced.csv").items()) if robot == "robot1"]
    moved = [round((b - a) * 1000, 6) for a, b in zip(xs, xs[1:], strict=False) if b != a]
    # (0.2 m/s, 20 mm a step, for 0.5 s of simulated time from the step it came in: five steps if it came between two
    # steps, four if it came while one was computed, too late for it)
    assert moved in ([20.0] * 4, [20.0] * 5), moved

    running = bridge(port, "--real-time-factor", "0", "--steps", "50", "--pose-log", str(tmp_path / "fast.csv"),
                     "--mcap", str(tmp_path / "fast.mcap"))
    assert running.end() == 0, running.output()
    assert_mcap_matches(tmp_path / "fast.mcap", _pose_log(tmp_path / "fast.csv"))


def test_a_recording_exports_to_mcap_with_the_pose_log_s_poses(tmp_path: Path) -> None:
    world = REPO / "examples/argos/diffusion_10.xml"
    run = subprocess.run(["bash", str(REPO / "scripts/headless.sh"), "--one-jvm", "--env", str(world), "--steps",
                          "60", "--record", str(tmp_path / "run.rec"), "--pose-log", str(tmp_path / "poses.csv")],
                         capture_output=True, text=True, timeout=WAIT_S, env={**os.environ,
                                                                             "ROBOSIM_PYTHON": sys.executable})
    assert run.returncode == 0, run.stderr
    export = subprocess.run(["bash", str(REPO / "scripts/record-tool.sh"), "export", str(tmp_path / "run.rec"),
                             "--mcap", str(tmp_path / "run.mcap")], capture_output=True, text=True, timeout=WAIT_S,
                            env={**os.environ, "ROBOSIM_PYTHON": sys.executable})
    assert export.returncode == 0, export.stderr
    topics = assert_mcap_matches(tmp_path / "run.mcap", _pose_log(tmp_path / "poses.csv"))
    assert {"/clock", "/tf", "/tf_static", "/map", "/obstacles", "/fb0/odom", "/fb0/proximity"} <= topics, topics
    again = subprocess.run(["bash", str(REPO / "scripts/record-tool.sh"), "export", str(tmp_path / "run.rec"),
                            "--mcap", str(tmp_path / "run.mcap")], capture_output=True, text=True, timeout=WAIT_S)
    assert again.returncode == 2 and "exists already" in again.stderr


def test_a_world_with_ros2_robots_runs_only_in_the_bridge(tmp_path: Path) -> None:
    run = subprocess.run(["bash", str(REPO / "scripts/headless.sh"), "--one-jvm", "--env", str(WORLD), "--steps", "5"],
                         capture_output=True, text=True, timeout=WAIT_S)
    assert run.returncode == 2, run.stderr
    assert 'robot name="robot1"' in run.stderr and "python -m robosim.ros2" in run.stderr

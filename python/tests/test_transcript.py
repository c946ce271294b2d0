"""The robot link's golden transcript (hardware-sim/src/test/resources/robot-link/transcript.txt): what this package
sends is the transcript's controller frames byte for byte, and it reads the link's answers as Java's robot gives them.
The same file is replayed against the Java side by RobotLinkTest."""

from __future__ import annotations

import socket
import struct
import threading

import pytest

from robosim import Message, Pose, Robot, RobotValueError
from robosim.frames import MAX_FRAME, Frames, LinkError, pack, unpack

from conftest import TRANSCRIPT


def transcript() -> list[tuple[bytes, bytes]]:
    """Each controller frame and the link's answer, as bytes (the frame's body, without its length)."""
    pairs = []
    lines = [line for line in TRANSCRIPT.read_text(encoding="utf-8").splitlines() if line[:2] in ("> ", "< ")]
    for sent, answer in zip(lines[::2], lines[1::2], strict=True):
        assert sent.startswith("> ") and answer.startswith("< ")
        pairs.append((bytes.fromhex(sent[2:].split()[0]), bytes.fromhex(answer[2:].split()[0])))
    return pairs


class Replay(threading.Thread):
    """A link that expects each frame of the transcript and answers with the next; what differed, if anything."""

    def __init__(self, pairs: list[tuple[bytes, bytes]]) -> None:
        super().__init__(name="replay", daemon=True)
        self.server = socket.create_server(("127.0.0.1", 0))
        self.pairs = pairs
        self.differed: list[str] = []
        self.exchanged = 0
        self.done = threading.Event()

    def run(self) -> None:
        conn, _ = self.server.accept()
        with conn, conn.makefile("rb") as r:
            for i, (want, answer) in enumerate(self.pairs):
                (n,) = struct.unpack(">I", r.read(4))
                got = r.read(n)
                if got != want:
                    self.differed.append(f"frame {i}: sent {got.hex()} ({unpack(got)!r}), not {want.hex()}")
                    break
                conn.sendall(struct.pack(">I", len(answer)) + answer)
                self.exchanged += 1
        self.done.set()


def test_the_package_sends_the_transcripts_frames_and_reads_its_answers() -> None:
    pairs = transcript()
    replay = Replay(pairs)
    replay.start()
    robot = Robot.connect("127.0.0.1", replay.server.getsockname()[1], "r1")
    assert (robot.name, robot.step_ms, robot.robot_names, robot.seed) == ("r1", 100, ("r1", "r2"), 42)
    assert robot.call("name") == "r1"
    assert robot.call("step_ms") == 100
    assert robot.call("robot_names") == ["r1", "r2"]
    assert robot.call("seed") == 42
    assert robot.move(2000) == 1000.0
    assert robot.turn(-90.0) == -90.0
    robot.set_velocity(300)
    assert robot.velocity() == 300.0
    robot.set_rot_velocity(45.0)
    assert robot.rot_velocity() == 45.0
    assert robot.tag() == ""
    robot.sleep(100)
    assert robot.sonar_ranges() == [1000.5, 250.0]
    assert robot.sonar_angles_deg() == [90.0, -90.0]
    assert robot.sensor_names() == ["bump"]
    assert robot.sensor("bump") == [0.0]
    with pytest.raises(RobotValueError, match=r"no sensor named heat \(it has: bump\)"):
        robot.sensor("heat")
    assert robot.pose() == Pose(1500.0, 2500.0, 90.0)
    assert robot.last_contact() == "wall"
    robot.send("r2", "hello")
    robot.broadcast("all")
    assert robot.receive() == Message("r2", "hi")
    assert robot.wait_for_message(500) is None
    assert robot.parameter("speed", 300.0) == 900.0
    assert robot.parameter("speed", "slow") == "900"
    assert robot.parameter("mode") is None
    robot.report("found", 3)
    robot.call("bye")
    assert replay.done.wait(10), "the replay did not reach the transcript's end"
    assert replay.differed == []
    assert replay.exchanged == len(pairs)


def test_a_frame_is_a_length_and_one_value_and_its_bounds_are_kept() -> None:
    assert pack(["move", 2000]) == bytes.fromhex("0000000992a46d6f7665cd07d0")
    assert unpack(bytes.fromhex("92a26f6bc0")) == ["ok", None]
    with pytest.raises(LinkError, match="more than one value"):
        unpack(bytes.fromhex("c0c0"))
    with pytest.raises(LinkError, match="frame of"):
        pack("x" * MAX_FRAME)
    a, b = socket.socketpair()
    with a, b:
        b.sendall(struct.pack(">I", MAX_FRAME + 1))
        with pytest.raises(LinkError, match=r"a frame of 1048577 bytes announced"):
            Frames(a).receive()


def test_a_refused_hello_is_a_link_error_saying_why() -> None:
    server = socket.create_server(("127.0.0.1", 0))

    def refuse() -> None:
        conn, _ = server.accept()
        with conn, conn.makefile("rb") as r:
            (n,) = struct.unpack(">I", r.read(4))
            r.read(n)
            conn.sendall(pack({"error": "this link serves robot r1, not \"zz\""}))

    threading.Thread(target=refuse, daemon=True).start()
    with pytest.raises(LinkError, match=r"refused the link: this link serves robot r1, not \"zz\""):
        Robot.connect("127.0.0.1", server.getsockname()[1], "zz")
    server.close()

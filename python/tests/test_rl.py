"""robosim.rl against a real learning host (scripts/learning-host.sh, started by the package): the PettingZoo and
Gymnasium checkers, the same episode from the same seed in two processes, autoreset, rewards and terminations,
viewers watching world 0, and the example's two policies."""

from __future__ import annotations

import base64
import functools
import json
import os
import select
import socket
import struct
import subprocess
import sys
import time
import urllib.request
import warnings
from pathlib import Path

import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env
from pettingzoo.test import parallel_api_test, parallel_seed_test

from robosim.rl import HostError, ParallelEnv, SingleRobotEnv, Transition, VectorEnv, sample_actions

REPO = Path(__file__).resolve().parents[2]
#: Two types of robot (an ArRobot, 8 sonars, and a Scout, 16), a box and a rock.
MIXED = REPO / "test-envs/test.xml"
DISPERSION = REPO / "examples/python/learning/dispersion.xml"
#: Three robots each with a laser, a heat and a bump sensor, near a heat source.
SENSORS = REPO / "test-envs/sensors.xml"
#: Two foot-bots: "carrier" faces a gripable can 5 mm ahead, "watcher" stands 0.5 m to its left.
GRIPPING = REPO / "test-envs/gripping.xml"
#: A generous bound on anything a test waits for (a loaded machine).
WAIT_S = 120.0


def test_a_world_passes_pettingzoos_parallel_api_test() -> None:
    env = ParallelEnv(MIXED, pose=True, message_size=2, max_steps=40)
    try:
        assert env.possible_agents == ["robot1", "robot2"]
        assert env.observation_space("robot1")["sonar"].shape == (8,)
        assert env.observation_space("robot2")["sonar"].shape == (16,)
        assert env.action_space("robot1").high.tolist()[2:] == [1.0, 1.0], "velocities, then the message's numbers"
        parallel_api_test(env, num_cycles=100)
    finally:
        env.close()


def test_a_robots_sensors_are_observed_each_a_box_its_description_gives() -> None:
    env = ParallelEnv(SENSORS, sensors=True, max_steps=20)
    try:
        space = env.observation_space("f1")
        laser, heat, bump = space["laser"], space["heat"], space["bump"]
        assert (laser.shape, float(laser.low[0]), float(laser.high[0])) == ((181,), 0.0, 8000.0), "rangeM 8, 1 deg"
        assert (bump.shape, float(bump.low[0]), float(bump.high[0])) == ((4,), 0.0, 1.0)
        assert heat.shape == (1,) and heat.low[0] == 0.0 and heat.high[0] == np.inf
        observations, _ = env.reset(seed=3)
        f1 = observations["f1"]
        assert all(space[part].contains(f1[part]) for part in space), "every part within its box"
        assert f1["laser"].min() < 8000, "a wall in sight"
        assert f1["heat"][0] > 0, "the stove in sight"
        parallel_api_test(env, num_cycles=20)
    finally:
        env.close()


def test_foot_bots_observe_their_devices_and_act_through_the_gripper_and_leds() -> None:
    env = ParallelEnv(GRIPPING, sensors=True, actuators=True, max_steps=50)
    try:
        space = env.observation_space("carrier")
        assert space["proximity"].shape == (24,) and space["light"].shape == (24,) and space["ground"].shape == (4,)
        rab = space["rab"]
        assert rab.shape == (16 * 12,), "16 messages of range, bearing and 10 bytes"
        assert (rab.low[1], rab.high[1], rab.high[0], rab.high[2]) == (-180, 180, 3000, 255), "each field its own"
        act = env.action_space("carrier")
        w = env._vector.welcome
        devices = {d["name"]: d for d in w.actuators[0]}
        assert list(devices) == ["gripper", "rab", "leds"] and act.shape == (w.action_fields,)
        assert (act.low[devices["gripper"]["offset"]], act.high[devices["leds"]["offset"]]) == (-1, 0xFFFFFF)
        observations, _ = env.reset(seed=1)
        assert all(space[part].contains(observations["carrier"][part]) for part in space)
        grip = np.zeros(act.shape, np.float32)
        grip[devices["gripper"]["offset"]] = 1.0  # take the can
        leds = devices["leds"]
        grip[leds["offset"]:leds["offset"] + leds["count"]] = 0xFF0000  # every LED red
        still = np.zeros(act.shape, np.float32)
        observations, *_ = env.step({"carrier": grip, "watcher": still})
        blobs = observations["watcher"]["camera"]
        assert blobs[0] == 0xFF0000 and abs(blobs[1] - 500) < 100, f"the watcher sees red LEDs: {blobs[:3]}"
        back = np.zeros(act.shape, np.float32)
        back[0] = -100.0  # reverse at 100 mm/s: the can comes along, filling the front rays
        for _ in range(10):
            observations, *_ = env.step({"carrier": back, "watcher": still})
        assert observations["carrier"]["proximity"][0] > 0.9, "the can held at the gripper"
        back[devices["gripper"]["offset"]] = -1.0  # let go, and keep reversing
        for _ in range(10):
            observations, *_ = env.step({"carrier": back, "watcher": still})
        assert observations["carrier"]["proximity"][0] == 0, "the can left behind, out of the rays' 100 mm"
        parallel_api_test(env, num_cycles=20)
    finally:
        env.close()


def test_a_world_passes_pettingzoos_seed_test() -> None:
    parallel_seed_test(functools.partial(ParallelEnv, DISPERSION, random_headings=True, max_steps=30))


def test_one_robot_passes_gymnasiums_env_checker() -> None:
    env = SingleRobotEnv(DISPERSION, robot="d3", pose=True, max_steps=30, reward="area_covered")
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # (its advice: a normalised action space, a spec from gymnasium.make)
            check_env(env, skip_render_check=True)
    finally:
        env.close()


def run(seed: int, actions: list[np.ndarray]) -> list[dict[str, np.ndarray]]:
    with VectorEnv(DISPERSION, worlds=3, repeat=2, pose=True, message_size=1, max_steps=10**6,
                   random_headings=True) as env:
        observations, _ = env.reset(seed=seed)
        seen = [{k: v.copy() for k, v in observations.items()}]
        for a in actions:
            observations, *_ = env.step(a)
            seen.append({k: v.copy() for k, v in observations.items()})
        return seen


def test_the_same_seed_and_actions_give_the_same_episode_in_another_process_and_another_seed_another() -> None:
    probe = VectorEnv(DISPERSION, worlds=3, message_size=1)
    rng = np.random.default_rng(4)
    actions = [sample_actions(probe, rng) for _ in range(60)]
    probe.close()
    first, again, other = run(11, actions), run(11, actions), run(12, actions)
    for step, (a, b) in enumerate(zip(first, again, strict=True)):
        for part in a:
            assert np.array_equal(a[part], b[part]), f"step {step}: {part}"
    assert not np.array_equal(first[0]["pose"], other[0]["pose"]), "another seed, other headings"
    assert not np.array_equal(first[-1]["pose"][1], first[-1]["pose"][0]), "world 1 has seed 12, world 0 seed 11"
    assert np.array_equal(first[0]["pose"][1], other[0]["pose"][0]), "world 1 of seed 11 is world 0 of seed 12"


def test_a_world_whose_episode_ended_begins_again_at_the_next_step() -> None:
    with VectorEnv(DISPERSION, worlds=2, max_steps=3, reward="distance_m") as env:
        start, _ = env.reset(seed=3)
        forward = np.zeros((2, 6, 2), np.float32)
        forward[..., 0] = 500
        total = np.zeros((2, 6))
        for k in range(3):
            _, rewards, terminated, truncated, infos = env.step(forward)
            total += rewards
            assert not terminated.any()
            assert truncated.all() == (k == 2)
        assert np.allclose(total[:, 0], infos["metrics"]["distance_m"]), "the metric's gains add up to it"
        last = infos["metrics"]["distance_m"]
        assert infos["active"].all(), "the last step is still one of the episode's"
        observations, rewards, terminated, truncated, infos = env.step(forward)
        assert infos["reset"].tolist() == [True, True]
        assert not infos["active"].any(), "a step that begins an episode is none of a robot's"
        assert not rewards.any() and not truncated.any()
        assert np.allclose(last, total[:, 0]), "the episode's last metrics, as they were given"
        assert np.array_equal(observations["sonar"], start["sonar"]), "the file's headings: the same start"
        _, rewards, *_ = env.step(forward)
        assert (rewards > 0).all()


def test_an_episode_metric_is_measured_from_the_episodes_recording_when_it_ends() -> None:
    with VectorEnv(DISPERSION, worlds=2, max_steps=5, episode_metric="area_covered", random_headings=True) as env:
        env.reset(seed=8)
        go = np.zeros((2, 6, 2), np.float32)
        go[..., 0] = 900
        for k in range(5):
            _, rewards, _, truncated, infos = env.step(go)
            assert np.isnan(infos["episode_metric"]).all() == (k < 4)
        assert truncated.all()
        assert np.array_equal(infos["episode_metric"], infos["metrics"]["area_covered"]), "as the live metric"
        assert np.array_equal(rewards, np.repeat(infos["episode_metric"][:, None], 6, axis=1).astype(np.float32))
    with pytest.raises(HostError, match="--episode-metric no.such.Metric: class no.such.Metric is not a"):
        VectorEnv(DISPERSION, worlds=1, episode_metric="no.such.Metric")


def test_a_reward_may_be_a_metric_the_worlds_loop_functions_report(tmp_path: Path,
                                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "east.py").write_text(
        "from robosim.loop import Experiment, LoopFunctions\n\n"
        "class East(LoopFunctions):\n"
        "    def post_step(self, world: Experiment) -> None:\n"
        "        world.report('east', sum(world.robot_x_mm(r) for r in range(world.robots)) / 1000)\n\n"
        "loop_functions = East\n")
    world = tmp_path / "east.xml"
    world.write_text(DISPERSION.read_text().replace(
        '<arena width="8" height="8"/>', '<loopFunctions class="python:east.py"/><arena width="8" height="8"/>'))
    monkeypatch.setenv("ROBOSIM_PYTHON", sys.executable)  # (the host starts the loop functions' script with it)
    with VectorEnv(world, worlds=2, max_steps=4, reward="east", loop_metrics=["east"], pose=True) as env:
        assert env.welcome.metrics[-1] == "east"
        observations, _ = env.reset(seed=3)
        before = observations["pose"][..., 0].astype(np.float64).sum(axis=1) / 1000
        forward = np.zeros((2, 6, 2), np.float32)
        forward[..., 0] = 500
        for _ in range(3):
            observations, rewards, _, _, infos = env.step(forward)
            east = observations["pose"][..., 0].astype(np.float64).sum(axis=1) / 1000
            assert np.allclose(infos["metrics"]["east"], east, atol=1e-3), "the loop functions' metric, as reported"
            assert np.allclose(rewards, (east - before)[:, None], atol=1e-3), "each robot gets its world's gain"
            assert (rewards != 0).any()
            before = east
    with pytest.raises(HostError, match="--loop-metric east: .* has no loop functions"):
        VectorEnv(DISPERSION, worlds=1, loop_metrics=["east"])


def test_where_the_loop_functions_end_the_experiment_every_robot_of_the_world_is_done(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "three.py").write_text(
        "from robosim.loop import Experiment, LoopFunctions\n\n"
        "class Three(LoopFunctions):\n"
        "    def finished(self, world: Experiment) -> bool:\n"
        "        return world.step >= 2 + world.seed % 2\n\n"
        "loop_functions = Three\n")
    world = tmp_path / "three.xml"
    world.write_text(DISPERSION.read_text().replace(
        '<arena width="8" height="8"/>', '<loopFunctions class="python:three.py"/><arena width="8" height="8"/>'))
    monkeypatch.setenv("ROBOSIM_PYTHON", sys.executable)
    with VectorEnv(world, worlds=2, max_steps=10) as env:
        env.reset(seed=1)
        still = np.zeros((2, 6, 2), np.float32)
        ends: list[list[bool]] = []
        for _ in range(3):
            _, _, terminated, truncated, _ = env.step(still)
            assert not truncated.any()
            assert (terminated.all(axis=1) | ~terminated.any(axis=1)).all(), "a world's robots end together"
            ends.append(terminated.all(axis=1).tolist())
        # (world 0's seed is 1: it ends once its third step is done; world 1's is 2: its second; each its own)
        assert ends == [[False, True], [True, False], [False, False]], str(ends)


def test_an_agent_whose_episode_ends_leaves_the_parallel_env() -> None:
    def out_east(t: Transition) -> np.ndarray:  # a robot that crosses x = 4.7 m is done
        return t.pose[..., 0] > 4700

    env = ParallelEnv(DISPERSION, terminate=out_east, max_steps=200)
    try:
        env.reset(seed=1)
        east = {a: np.array([800.0, 0.0], np.float32) for a in env.agents}
        _, _, terminated, _, _ = env.step(east)
        assert not any(terminated.values())
        seen: set[str] = set()
        while env.agents:
            _, _, terminated, truncated, _ = env.step({a: east[a] for a in env.agents})
            ended = {a for a in terminated if terminated[a] or truncated[a]}
            seen |= {a for a, t in terminated.items() if t}
            assert not ended & set(env.agents), "an agent whose episode ended has left"
        assert {"d3", "d6"} <= seen, "the two nearest the line end by termination"
    finally:
        env.close()


def test_bad_choices_are_one_clear_error() -> None:
    with pytest.raises(ValueError, match="reward 'speed' is not a metric"):
        VectorEnv(DISPERSION, worlds=1, reward="speed")
    with pytest.raises(HostError, match="no-such.xml: no such environment file"):
        ParallelEnv(REPO / "no-such.xml")
    with pytest.raises(HostError, match="--worlds must be 1 to 1024, got 0"):
        VectorEnv(DISPERSION, worlds=0)


def test_bad_actions_and_seeds_are_clear_errors_before_anything_is_sent() -> None:
    with VectorEnv(MIXED, worlds=2) as env:
        env.reset(seed=1)
        good = np.zeros((2, 2, 2), np.float32)
        with pytest.raises(ValueError, match=r"actions of shape \(2,\); this env takes .* \(2, 2, 2\)"):
            env.step(np.zeros(2))
        huge = good.astype(np.float64)
        huge[1, 0, 1] = 1e300
        with pytest.raises(ValueError, match="world 1, robot robot1: action field 1 is 1e[+]300, not a finite"):
            env.step(huge)
        nan = good.copy()
        nan[0, 1, 0] = np.nan
        with pytest.raises(ValueError, match="world 0, robot robot2: action field 0 is nan"):
            env.step(nan)
        for seed, why in (("7", "a whole number"), (2**64, "0 to 2\\*\\*63 - 2"), (-1, "0 to 2"), (True, "a whole")):
            with pytest.raises(ValueError, match=f"seed .*: {why}"):
                env.reset(seed=seed)  # type: ignore[arg-type]
        _, infos = env.reset(seed=5)
        assert infos["seeds"] == [5, 6], "the refused seeds changed nothing"
        env.step(good)  # (the env goes on)
    parallel = ParallelEnv(MIXED)
    try:
        parallel.reset(seed=1)
        with pytest.raises(ValueError, match="actions is a dict of agent names to actions, not a list"):
            parallel.step([np.zeros(2)])  # type: ignore[arg-type]
        with pytest.raises(ValueError, match="no agent 'robot9' \\(agents: robot1, robot2\\)"):
            parallel.step({"robot9": np.zeros(2)})
        with pytest.raises(ValueError, match=r"agent robot1: an action of shape \(\); its action space's is \(2,\)"):
            parallel.step({"robot1": 0.5})
    finally:
        parallel.close()


def test_normalized_actions_are_a_unit_box_scaled_to_each_robots_limits() -> None:
    with VectorEnv(MIXED, worlds=1, normalize_actions=True, pose=True) as env, \
            VectorEnv(MIXED, worlds=1, pose=True) as physical:
        box = env.action_space("robot1")
        assert (box.low == -1).all() and (box.high == 1).all()
        limits = physical.action_space("robot1")
        env.reset(seed=3)
        physical.reset(seed=3)
        unit = np.array([[[0.5, 0.0], [1.0, -0.25]]], np.float32)
        scaled = np.array([[[0.5 * limits.high[0], 0.0],
                            [physical.action_space("robot2").high[0],
                             -0.25 * physical.action_space("robot2").high[1]]]],
                          np.float32)
        for _ in range(5):
            env.step(unit)
            physical.step(scaled)
        assert np.allclose(env.last_pose, physical.last_pose, atol=1e-3), (env.last_pose, physical.last_pose)


def read_exact(sock: socket.socket, n: int, deadline: float) -> bytes:
    """``n`` bytes, however the server's writes split them, by ``deadline``; its end is an assertion."""
    data = b""
    while len(data) < n:
        sock.settimeout(max(0.01, deadline - time.monotonic()))
        chunk = sock.recv(n - len(data))
        assert chunk, "the web viewer closed the WebSocket"
        data += chunk
    return data


def read_frame(sock: socket.socket, deadline: float) -> tuple[int, bytes]:
    """One whole frame from the server (unmasked): its opcode and payload."""
    head = read_exact(sock, 2, deadline)
    length = head[1] & 0x7F
    if length == 126:
        length = struct.unpack(">H", read_exact(sock, 2, deadline))[0]
    elif length == 127:
        length = struct.unpack(">Q", read_exact(sock, 8, deadline))[0]
    return head[0] & 0x0F, read_exact(sock, length, deadline)


def test_viewers_watch_world_0_while_a_learner_steps_it(tmp_path: Path) -> None:
    env = ParallelEnv(DISPERSION, viewer_port=0, web_port=0, max_steps=10**6)
    log: subprocess.Popen[str] | None = None
    try:
        env.reset(seed=1)
        assert env.viewer_port and env.web_port
        page = urllib.request.urlopen(f"http://127.0.0.1:{env.web_port}/", timeout=WAIT_S).read().decode()
        assert "<html" in page.lower()
        deadline = time.monotonic() + WAIT_S
        web = socket.create_connection(("127.0.0.1", env.web_port), timeout=WAIT_S)
        key = base64.b64encode(os.urandom(16)).decode()
        web.sendall(f"GET /ws HTTP/1.1\r\nHost: 127.0.0.1:{env.web_port}\r\nUpgrade: websocket\r\n"
                    f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n"
                    f"Origin: http://127.0.0.1:{env.web_port}\r\n\r\n".encode())
        answer = b""
        while b"\r\n\r\n" not in answer:
            answer += read_exact(web, 1, deadline)
        assert answer.startswith(b"HTTP/1.1 101"), answer
        csv = tmp_path / "poses.csv"
        log = subprocess.Popen(["bash", str(REPO / "scripts/pose-log.sh"), "127.0.0.1", str(env.viewer_port), str(csv)],
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, text=True)
        go = {a: np.array([300.0, 20.0], np.float32) for a in env.possible_agents}
        kinds: set[str] = set()
        while not ({"snapshot", "update"} <= kinds and csv.exists() and csv.stat().st_size > 2000):
            assert time.monotonic() < deadline, f"within {WAIT_S} s: frames {kinds}, the CSV's {csv.exists()}"
            env.step(go)
            while select.select([web], [], [], 0)[0]:  # (every frame the page has been sent so far, each whole)
                opcode, payload = read_frame(web, deadline)
                if opcode == 1:
                    kinds.add(json.loads(payload)["type"])
        web.close()
    finally:
        env.close()
    assert log is not None
    output, _ = log.communicate(timeout=WAIT_S)
    assert log.returncode == 0, output
    rows = csv.read_text().splitlines()
    assert rows[0].startswith("step,robot,x_m,y_m,heading_deg")
    assert {row.split(",")[1] for row in rows[1:]} == {"d1", "d2", "d3", "d4", "d5", "d6"}


def test_the_examples_hand_written_policy_disperses_better_than_random() -> None:
    sys.path.insert(0, str(REPO / "examples/python/learning"))
    try:
        import dispersion
    finally:
        sys.path.pop(0)
    with VectorEnv(dispersion.WORLD, worlds=4, repeat=dispersion.REPEAT, max_steps=dispersion.EPISODE,
                   reward=dispersion.reward, random_headings=True) as env:
        written = dispersion.episodes(env, "hand-written", [1, 2, 3, 4])
        random = dispersion.episodes(env, "random", [1, 2, 3, 4])
    assert min(r for r, _, _ in written) > max(r for r, _, _ in random)
    assert sum(c for _, _, c in written) < sum(c for _, _, c in random)

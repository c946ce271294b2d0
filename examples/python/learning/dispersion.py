"""Dispersion, learned or written: six Scouts start in a cluster (dispersion.xml) and are rewarded, each step, for the
distance to their nearest neighbour (up to 2 m, scaled to 0..1) less 1 for each step in which they touch something.
This script runs a hand-written policy and a random one on the same seeds, K worlds at a time, and compares their
episode returns: ``python dispersion.py [--episodes N] [--worlds K] [--web-port P]`` (needs ``pip install
"./python[rl]"``). python/README.md, "Learning controllers", shows how to train a policy of one's own on it instead."""

from __future__ import annotations

import argparse
import statistics
from pathlib import Path

import numpy as np

from robosim.rl import Transition, VectorEnv, Welcome, sample_actions

WORLD = Path(__file__).with_name("dispersion.xml")
#: The distance to the nearest neighbour at which a robot gets the whole reward, mm.
SPREAD_MM = 2000.0
#: Actions an episode holds, and time steps an action (100 ms each): 20 s of the robots' time.
EPISODE = 100
REPEAT = 2


def reward(t: Transition) -> np.ndarray:
    """Each robot's reward (K, N): its nearest neighbour's distance, up to SPREAD_MM, as 0..1; -1 on a contact."""
    xy = t.pose[..., :2].astype(np.float64)
    apart = np.linalg.norm(xy[:, :, None, :] - xy[:, None, :, :], axis=-1)
    n = apart.shape[1]
    apart[:, np.arange(n), np.arange(n)] = np.inf
    return np.minimum(apart.min(axis=2), SPREAD_MM) / SPREAD_MM - t.contact


def hand_written(observations: dict[str, np.ndarray], welcome: Welcome) -> np.ndarray:
    """Away from whatever is nearest: drive at 600 mm/s while the way ahead (sonars within 45 degrees of it) is clear
    for 700 mm, turning away from the nearest echo while it is within 1.5 m; else stop and turn away at 120 deg/s."""
    sonar = observations["sonar"]  # (K, N, S), mm
    angles = np.radians(np.asarray(welcome.sonar_angles_deg[0]))  # every robot is a Scout
    ahead = np.abs(np.angle(np.exp(1j * angles))) <= np.radians(45)
    front = sonar[..., ahead].min(axis=-1)
    nearest = sonar.argmin(axis=-1)
    away = -np.sign(np.sin(angles[nearest]))  # nearest on the left (sin > 0): turn right
    away[away == 0] = 1.0
    close = sonar.min(axis=-1) < 1500
    actions = np.zeros((*sonar.shape[:2], 2), np.float32)
    blocked = front < 700
    actions[..., 0] = np.where(blocked, 0.0, 600.0)
    actions[..., 1] = np.where(blocked, 120.0 * away, np.where(close, 45.0 * away, 0.0))
    return actions


def episodes(env: VectorEnv, policy: str, seeds: list[int]) -> list[tuple[float, float, float]]:
    """Each world's episode under ``policy`` ("hand-written" or "random"), from each seed in ``seeds`` (a multiple of
    the worlds): its return (summed over steps, averaged over robots), area_covered and contacts at its end."""
    rng = np.random.default_rng(0)
    out = []
    for first in range(0, len(seeds), env.num_worlds):
        observations, _ = env.reset(seed=seeds[first])
        returns = np.zeros(env.num_worlds)
        for _ in range(EPISODE):
            actions = hand_written(observations, env.welcome) if policy == "hand-written" else sample_actions(env, rng)
            observations, rewards, _, truncated, infos = env.step(actions)
            returns += rewards.mean(axis=1)
        assert truncated.all(), "every episode ends at EPISODE actions"
        metrics = infos["metrics"]
        out += [(float(returns[w]), float(metrics["area_covered"][w]), float(metrics["contacts"][w]))
                for w in range(env.num_worlds)]
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--episodes", type=int, default=16, help="episodes of each policy (default 16)")
    parser.add_argument("--worlds", type=int, default=8, help="worlds stepped together (default 8)")
    parser.add_argument("--web-port", type=int, default=None, help="watch world 0 in a browser on this port")
    args = parser.parse_args()
    count = max(args.worlds, args.episodes // args.worlds * args.worlds)
    with VectorEnv(WORLD, worlds=args.worlds, repeat=REPEAT, max_steps=EPISODE, reward=reward,
                   random_headings=True, web_port=args.web_port) as env:
        if env.host.web_port is not None:
            print(f"watch world 0: http://127.0.0.1:{env.host.web_port}/")
        print(f"dispersion: {len(env.agents)} robots, {count} episodes of each policy ({args.worlds} worlds at a "
              f"time), {EPISODE} actions of {REPEAT * env.welcome.step_ms} ms each")
        print(f"{'policy':<14}{'return':>18}{'area_covered':>14}{'contacts':>10}")
        for policy in ("hand-written", "random"):
            runs = episodes(env, policy, list(range(1, count + 1)))
            returns = [r for r, _, _ in runs]
            print(f"{policy:<14}{statistics.mean(returns):>10.1f} ± {statistics.stdev(returns):<5.1f}"
                  f"{statistics.mean(a for _, a, _ in runs):>14.3f}{statistics.mean(c for _, _, c in runs):>10.1f}")


if __name__ == "__main__":
    main()

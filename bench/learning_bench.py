"""What a learner sees: K worlds of an environment file stepped from Python over the learning link (robosim.rl's
VectorEnv), every robot's action uniformly random within its limits (drawn ahead, 64 blocks, used in turn), rewards
the built-in metric area_covered's gains (what the package does a step, and no more: a learner's own reward and
policy cost what they cost). The clock starts after WARM steps and runs STEPS.
usage: PYTHON bench/learning_bench.py FILE.xml WORLDS STEPS [WARM]   (with robosim[rl] installed)
Prints one line: worlds=K robots=N steps=S wall=Ws steps/s=R robot-steps/s=R."""

import sys
import time

import numpy as np

from robosim.rl import VectorEnv, sample_actions


def main() -> None:
    path, worlds, steps = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    warm = int(sys.argv[4]) if len(sys.argv) > 4 else 500
    with VectorEnv(path, worlds=worlds, max_steps=10**9, reward="area_covered") as env:
        rng = np.random.default_rng(1)
        blocks = [sample_actions(env, rng) for _ in range(64)]
        env.reset(seed=1)
        start = 0.0
        for k in range(-warm, steps):
            if k == 0:
                start = time.perf_counter()
            env.step(blocks[k % 64])
        wall = time.perf_counter() - start
        n = len(env.agents)
        print(f"worlds={worlds} robots={n} steps={steps} wall={wall:.3f}s steps/s={steps / wall:.1f} "
              f"robot-steps/s={steps * worlds * n / wall:.1f}")


if __name__ == "__main__":
    main()

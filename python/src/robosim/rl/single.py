"""One robot of a RoboSim world as a Gymnasium ``Env`` (the others stand still, or follow a policy of one's own)."""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from typing import Any

import gymnasium
import numpy as np

from robosim.rl.vector import DEFAULT_MAX_STEPS, Reward, Terminate, VectorEnv

#: What the other robots do: their actions (N, 2 + message size) from the world's observations part by part (N, ...).
Others = Callable[[dict[str, np.ndarray]], np.ndarray]


class SingleRobotEnv(gymnasium.Env):
    """Robot ``robot`` (the file's first, unless named) of an environment file's world as a Gymnasium ``Env``: its
    observation and action spaces, its reward, its termination; ``others`` gives the other robots' actions (None:
    they stand still). Other keyword arguments as for :class:`robosim.rl.VectorEnv`."""

    metadata = {"render_modes": []}

    def __init__(self, path: str | os.PathLike[str], *, robot: str | None = None, others: Others | None = None,
                 repeat: int = 1, pose: bool = False, sensors: bool = False, actuators: bool = False,
                 message_size: int = 0,
                 max_steps: int = DEFAULT_MAX_STEPS,
                 reward: Reward = None, terminate: Terminate = None, episode_metric: str | None = None,
                 loop_metrics: Sequence[str] = (),
                 random_headings: bool = False, area_cell_m: float | None = None, web_port: int | None = None,
                 viewer_port: int | None = None, params: dict[str, str] | None = None,
                 normalize_actions: bool = False,
                 robosim_home: str | os.PathLike[str] | None = None) -> None:
        self._vector = VectorEnv(path, worlds=1, repeat=repeat, pose=pose, sensors=sensors, actuators=actuators,
                                 message_size=message_size, max_steps=max_steps, reward=reward, terminate=terminate,
                                 episode_metric=episode_metric,
                                 loop_metrics=loop_metrics, random_headings=random_headings,
                                 area_cell_m=area_cell_m, threads=1, web_port=web_port, viewer_port=viewer_port,
                                 params=params, normalize_actions=normalize_actions,
                                 robosim_home=robosim_home)
        agents = self._vector.agents
        if robot is not None and robot not in agents:
            self._vector.close()
            raise ValueError(f"no robot {robot!r} in this world ({', '.join(agents)})")
        self.robot = robot or agents[0]
        self._i = agents.index(self.robot)
        self._others = others
        self.observation_space = self._vector.observation_space(self.robot)
        self.action_space = self._vector.action_space(self.robot)
        self._parts: dict[str, np.ndarray] = {}
        # (float64: the vector env checks each value as given, 1e300 too, before it becomes float32)
        self._actions = np.zeros((1, len(agents), self._vector.welcome.action_fields))

    def reset(self, *, seed: int | None = None, options: dict[str, Any] | None = None
              ) -> tuple[dict[str, np.ndarray], dict[str, Any]]:
        super().reset(seed=seed)
        self._parts, _ = self._vector.reset(seed)
        return self._vector.layout.agent_observation(self._parts, 0, self._i), {}

    def step(self, action: np.ndarray) -> tuple[dict[str, np.ndarray], float, bool, bool, dict[str, Any]]:
        if self._others is not None:
            self._actions[0] = self._others({k: v[0] for k, v in self._parts.items()})
        else:
            self._actions[:] = 0.0
        given = np.asarray(action)
        if given.shape != self.action_space.shape:
            raise ValueError(f"an action of shape {given.shape}; the action space's is {self.action_space.shape}")
        self._actions[0, self._i] = given  # (checked as numbers, finite, by the vector env)
        self._parts, rewards, terminated, truncated, infos = self._vector.step(self._actions)
        observation = self._vector.layout.agent_observation(self._parts, 0, self._i)
        metrics = {m: float(v[0]) for m, v in infos["metrics"].items()}
        return (observation, float(rewards[0, self._i]), bool(terminated[0, self._i]), bool(truncated[0, self._i]),
                {"metrics": metrics})

    def close(self) -> None:
        self._vector.close()

"""A RoboSim world as a PettingZoo ``ParallelEnv``: its robots are the agents."""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pettingzoo
from gymnasium import spaces

from robosim.rl.vector import DEFAULT_MAX_STEPS, Reward, Terminate, VectorEnv


class ParallelEnv(pettingzoo.ParallelEnv):
    """The world of an environment file, its robots the agents (dicts keyed by robot name). ``ParallelEnv(path)``
    alone starts what it needs (a learning host of one world) with velocity actions, sonar and contact observations
    and a reward of zero; every other choice is a keyword argument, as for :class:`robosim.rl.VectorEnv`. An agent
    whose episode ends leaves ``agents`` (and stands still); ``max_steps`` actions truncate the episode."""

    metadata = {"name": "robosim_parallel_v0", "render_modes": []}

    def __init__(self, path: str | os.PathLike[str], *, repeat: int = 1, pose: bool = False, sensors: bool = False,
                 actuators: bool = False,
                 message_size: int = 0, max_steps: int = DEFAULT_MAX_STEPS, reward: Reward = None,
                 terminate: Terminate = None,
                 episode_metric: str | None = None,
                 loop_metrics: Sequence[str] = (), random_headings: bool = False, area_cell_m: float | None = None,
                 web_port: int | None = None, viewer_port: int | None = None,
                 params: dict[str, str] | None = None,
                 normalize_actions: bool = False,
                 robosim_home: str | os.PathLike[str] | None = None) -> None:
        self._vector = VectorEnv(path, worlds=1, repeat=repeat, pose=pose, sensors=sensors, actuators=actuators,
                                 message_size=message_size, max_steps=max_steps, reward=reward, terminate=terminate,
                                 episode_metric=episode_metric,
                                 loop_metrics=loop_metrics, random_headings=random_headings,
                                 area_cell_m=area_cell_m, threads=1, web_port=web_port, viewer_port=viewer_port,
                                 params=params, normalize_actions=normalize_actions,
                                 robosim_home=robosim_home)
        self.possible_agents = list(self._vector.agents)
        self.agents: list[str] = []
        self._index = {a: i for i, a in enumerate(self.possible_agents)}
        # (float64: the vector env checks each value as given, 1e300 too, before it becomes float32)
        self._actions = np.zeros((1, len(self.possible_agents), self._vector.welcome.action_fields))
        self.web_port = self._vector.host.web_port
        self.viewer_port = self._vector.host.viewer_port

    def observation_space(self, agent: str) -> spaces.Dict:
        return self._vector.observation_space(agent)

    def action_space(self, agent: str) -> spaces.Box:
        return self._vector.action_space(agent)

    def reset(self, seed: int | None = None, options: dict[str, Any] | None = None
              ) -> tuple[dict[str, Any], dict[str, Any]]:
        parts, _ = self._vector.reset(seed)
        self.agents = list(self.possible_agents)
        return self._observations(parts), {a: {} for a in self.agents}

    def step(self, actions: dict[str, Any]) -> tuple[dict[str, Any], dict[str, float], dict[str, bool],
                                                     dict[str, bool], dict[str, Any]]:
        if not isinstance(actions, Mapping):
            raise ValueError(f"actions is a dict of agent names to actions, not a {type(actions).__name__}")
        self._actions[:] = 0.0
        fields = self._actions.shape[2]
        for agent, action in actions.items():
            if agent not in self._index:
                raise ValueError(f"no agent {agent!r} (agents: {', '.join(self.possible_agents)})")
            given = np.asarray(action)
            if given.shape != (fields,):
                raise ValueError(f"agent {agent}: an action of shape {given.shape}; its action space's is ({fields},)")
            self._actions[0, self._index[agent]] = given  # (checked as numbers, finite, by the vector env)
        parts, rewards, terminated, truncated, infos = self._vector.step(self._actions)
        acting = self.agents
        observations = self._observations(parts, acting)
        metrics = {m: float(v[0]) for m, v in infos["metrics"].items()}
        out = (observations,
               {a: float(rewards[0, self._index[a]]) for a in acting},
               {a: bool(terminated[0, self._index[a]]) for a in acting},
               {a: bool(truncated[0, self._index[a]]) for a in acting},
               {a: {"metrics": metrics} for a in acting})
        self.agents = [a for a in acting if not (out[2][a] or out[3][a])]
        return out

    def _observations(self, parts: dict[str, np.ndarray], agents: list[str] | None = None) -> dict[str, Any]:
        layout = self._vector.layout
        return {a: layout.agent_observation(parts, 0, self._index[a]) for a in (agents or self.agents)}

    def state(self) -> np.ndarray:
        """Every robot's pose (x mm, y mm, heading degrees), world order: the world's state, as a learner with a
        central critic wants it."""
        return self._vector.last_pose[0].copy()

    def close(self) -> None:
        self._vector.close()

"""K copies of a world stepped together, the learner's view: arrays (K, N, ...) in, arrays out, one exchange a step."""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from gymnasium import spaces

from robosim.rl.host import Batch, LearningHost
from robosim.rl.spaces import Layout

#: Actions an episode holds before it is truncated, unless told otherwise.
DEFAULT_MAX_STEPS = 500


class Metrics(Mapping[str, np.ndarray]):
    """The metrics of K worlds by name (the built-ins, then the loop metrics named), each (K,): views of one array
    (K, M), made when asked for."""

    def __init__(self, names: list[str], values: np.ndarray) -> None:
        self._index = {name: i for i, name in enumerate(names)}
        self._values = values

    def __getitem__(self, name: str) -> np.ndarray:
        return self._values[:, self._index[name]]

    def __iter__(self) -> Iterator[str]:
        return iter(self._index)

    def __len__(self) -> int:
        return len(self._index)


@dataclass(frozen=True)
class Transition:
    """What a reward or termination function sees of one step of K worlds (arrays of the batch, read-only):
    ``observations`` part by part (K, N, ...), the robots' ``pose`` (K, N, 3) and ``contact`` (K, N) whether observed
    or not, the ``metrics`` of each world's episode so far and before this step, by name (K,), ``actions``
    (K, N, Welcome.action_fields) and ``steps``: actions since each episode began (K,)."""

    observations: dict[str, np.ndarray]
    pose: np.ndarray
    contact: np.ndarray
    metrics: Mapping[str, np.ndarray]
    previous_metrics: Mapping[str, np.ndarray]
    actions: np.ndarray
    steps: np.ndarray


#: A reward: an array broadcastable to (K, N) from a transition ((K, N); (K, 1), a world's for each of its robots; or
#: a number), or the name of a metric whose increase in a step every robot of the world gets: a built-in one
#: (``"area_covered"``: a share of the arena's cells newly visited) or one of the world's loop functions' that
#: ``loop_metrics`` names (``"collected_food"``).
Reward = Callable[[Transition], np.ndarray] | str | None
#: Which robots' episodes end (True where one does): an array broadcastable to (K, N) of bools.
Terminate = Callable[[Transition], np.ndarray] | None


class VectorEnv:
    """K copies of the world of an environment file, each with its own seed, stepped together in one JVM (the worlds
    shared out over its cores): ``reset(seed)`` gives observations (K, N, ...); ``step(actions)`` with actions (K, N,
    Welcome.action_fields) gives observations, rewards (K, N), terminations (K, N), truncations (K, N) and infos. A
    world whose episode has ended (every robot terminated, or ``max_steps`` actions) begins its next at the following
    ``step`` (Gymnasium's next-step autoreset: that step's actions for it are not used, its rewards are 0 and
    ``infos["reset"]`` says which worlds began again). A terminated robot stands still until its world begins again;
    ``infos["active"]`` (K, N) is True where a robot's step is one of its episode's (False for robots done before the
    step and for worlds that began again): a learner that takes the K x N robots as a batch keeps those.
    With ``episode_metric`` (a built-in metric's name or a ``robosim.sweep.Metric`` class on the host's class path),
    a world whose episode ends is measured from its episode's recording, as a sweep measures a run, and the value is
    added to the last reward of each robot that ends with it (``infos["episode_metric"]``: (K,), NaN for the other
    worlds); one more exchange with the host an episode end. ``loop_metrics`` names metrics the world's loop functions
    report (``Experiment.report``): each is a metric too (``Welcome.metrics``, ``Transition.metrics``), its newest value
    in the episode (0 before their first report), so a reward may name one. Where the world's loop functions end its
    experiment (``finished``, ``end``), every robot of it is terminated at that step.
    World w of ``reset(seed=s)`` runs with seed s + w; its later episodes with seeds drawn from (s, w)."""

    def __init__(self, path: str | os.PathLike[str], *, worlds: int = 8, repeat: int = 1, pose: bool = False,
                 sensors: bool = False, actuators: bool = False, message_size: int = 0,
                 max_steps: int = DEFAULT_MAX_STEPS, reward: Reward = None,
                 terminate: Terminate = None, episode_metric: str | None = None,
                 loop_metrics: Sequence[str] = (), random_headings: bool = False,
                 area_cell_m: float | None = None, threads: int | None = None, web_port: int | None = None,
                 viewer_port: int | None = None, params: dict[str, str] | None = None,
                 normalize_actions: bool = False,
                 robosim_home: str | os.PathLike[str] | None = None) -> None:
        if max_steps < 1:
            raise ValueError(f"max_steps must be >= 1, got {max_steps}")
        self.host = LearningHost(path, worlds=worlds, repeat=repeat, message_size=message_size, sensors=sensors,
                                 actuators=actuators, random_headings=random_headings, area_cell_m=area_cell_m,
                                 threads=threads,
                                 episode_metric=episode_metric,
                                 loop_metrics=loop_metrics, web_port=web_port, viewer_port=viewer_port,
                                 params=params, robosim_home=robosim_home)
        self.welcome = self.host.welcome
        if isinstance(reward, str) and reward not in self.welcome.metrics:
            self.host.close()
            raise ValueError(f"reward {reward!r} is not a metric ({', '.join(self.welcome.metrics)}; a metric of "
                             "the world's loop functions is one where loop_metrics names it)")
        self.layout = Layout(self.welcome, pose)
        self.agents = list(self.welcome.robots)
        self.num_worlds = worlds
        self.max_steps = max_steps
        self._reward = reward
        self._terminate = terminate
        self._observation_spaces = [self.layout.observation_space(i) for i in range(len(self.agents))]
        physical = [self.layout.action_space(i) for i in range(len(self.agents))]
        #: With normalize_actions, an action's field a in [-1, 1] is mid + half * a in the robot's own units.
        self._mid = np.array([(b.high + b.low) / 2 for b in physical], np.float64)
        self._half = np.array([(b.high - b.low) / 2 for b in physical], np.float64)
        self.normalize_actions = normalize_actions
        self._action_spaces = [spaces.Box(-1.0, 1.0, b.shape, np.float32) for b in physical] if normalize_actions \
            else physical
        n = len(self.agents)
        self._actions = np.zeros((worlds, n, self.welcome.action_fields), np.float32)
        self._done = np.zeros((worlds, n), bool)
        self._any_done = False
        #: The worlds whose episode has ended, and the seed each begins its next with at the next step.
        self._ended: dict[int, int] = {}
        self._steps = np.zeros(worlds, np.int64)
        #: Steps until the first world's truncation (while no robot is done and there is no termination function).
        self._first_end = max_steps
        self._generators: list[np.random.Generator] = []
        self._metrics: np.ndarray | None = None
        #: Every robot's pose after the last reset or step (K, N, 3): x mm, y mm, heading degrees.
        self.last_pose = np.zeros((worlds, n, 3), np.float32)

    def observation_space(self, agent: str) -> spaces.Dict:
        return self._observation_spaces[self.agents.index(agent)]

    def action_space(self, agent: str) -> spaces.Box:
        return self._action_spaces[self.agents.index(agent)]

    def reset(self, seed: int | None = None) -> tuple[dict[str, np.ndarray], dict[str, Any]]:
        """Every world begins a new episode (seed None: seeds drawn from the last seeded reset's, or the file's)."""
        if seed is not None:
            seed = self._checked_seed(seed)
        if seed is None:
            seed = self.welcome.seed if not self._generators else int(self._generators[0].integers(2**62))
        self._generators = [np.random.default_rng([seed, w]) for w in range(self.num_worlds)]
        seeds = [seed + w for w in range(self.num_worlds)]
        batch = self.host.reset(seeds)
        self._done[:] = False
        self._any_done = False
        self._ended = {}
        self._steps[:] = 0
        self._first_end = self.max_steps
        self._metrics = batch.metrics.copy()
        self.last_pose = batch.pose
        return self.layout.observations(batch), {"seeds": seeds}

    def step(self, actions: np.ndarray) -> tuple[dict[str, np.ndarray], np.ndarray, np.ndarray, np.ndarray,
                                                 dict[str, Any]]:
        """One action of every robot of every world (float32 (K, N, Welcome.action_fields); velocities beyond a robot's
        limits are held to them)."""
        if self._metrics is None:
            raise RuntimeError("reset() before step()")
        given = self._checked_actions(actions)
        if self.normalize_actions:
            given = self._mid + self._half * np.clip(given, -1.0, 1.0)
        np.copyto(self._actions, given, casting="unsafe")
        again = list(self._ended)
        if self._any_done:
            self._actions[self._done] = 0.0
        batch = self.host.step(self._actions, self._ended)
        observations = self.layout.observations(batch)
        previous = self._metrics
        metrics = batch.metrics.copy()
        self._steps += 1
        self._first_end -= 1
        if again:
            previous = previous.copy()  # (the array the last step gave out, as infos["metrics"], stays as it was)
            previous[again] = metrics[again]
            self._steps[again] = 0
            self._done[again] = False
            self._first_end = self.max_steps - int(self._steps.max())
        active = ~self._done
        if again:
            active[again] = False
        transition = Transition(observations, batch.pose, batch.contact, Metrics(self.welcome.metrics, metrics),
                                Metrics(self.welcome.metrics, previous), self._actions.copy(), self._steps.copy())
        shape = self._done.shape
        rewards = self._rewards(transition, shape)
        measured: np.ndarray | None = None
        finished = batch.finished is not None and bool(batch.finished.any())
        if self._first_end <= 0 or self._terminate is not None or self._any_done or finished:
            terminated = np.zeros(shape, bool) if self._terminate is None else np.broadcast_to(
                np.asarray(self._terminate(transition), bool), shape).copy()
            if finished:  # (the world's loop functions ended its experiment: every robot of it is done)
                assert batch.finished is not None
                terminated |= batch.finished.astype(bool)[:, None]
            terminated &= ~self._done
            truncated = np.broadcast_to((self._steps >= self.max_steps)[:, None], shape) & ~self._done & ~terminated
            rewards[self._done] = 0.0
            if again:
                rewards[again] = 0.0
                terminated[again] = False
                truncated[again] = False
            self._done |= terminated | truncated
            self._any_done = bool(self._done.any())
            ended = np.flatnonzero(self._done.all(axis=1)).tolist() if self._any_done else []
            self._ended = {w: int(self._generators[w].integers(2**62)) for w in ended}
            self._metrics = metrics
            self.last_pose = batch.pose
            if ended and self.welcome.episode_metric is not None:
                values = self.host.measure(ended)
                measured = np.full(self.num_worlds, np.nan)
                measured[ended] = values
                last = terminated | truncated
                rewards[ended] += np.where(last[ended], np.asarray(values, np.float32)[:, None], 0.0)
        else:
            terminated = np.zeros(shape, bool)
            truncated = np.zeros(shape, bool)
            if again:
                rewards[again] = 0.0
            self._ended = {}
        self._metrics = metrics
        self.last_pose = batch.pose
        reset = np.zeros(self.num_worlds, bool)
        if again:
            reset[again] = True
        infos = {"reset": reset, "active": active, "metrics": transition.metrics}
        if self.welcome.episode_metric is not None:
            infos["episode_metric"] = measured if measured is not None else np.full(self.num_worlds, np.nan)
        return observations, rewards, terminated, truncated, infos

    def _checked_seed(self, seed: object) -> int:
        """``seed`` as the host takes it (a whole number, 0 to 2**63 - K: world w runs with seed + w), or a
        ValueError; checked before anything changes."""
        if isinstance(seed, bool) or not isinstance(seed, int | np.integer):
            raise ValueError(f"seed {seed!r}: a whole number (an int), or None")
        if not 0 <= int(seed) < 2**63 - self.num_worlds:
            raise ValueError(f"seed {seed}: 0 to 2**63 - {self.num_worlds} (world w runs with seed + w)")
        return int(seed)

    def _checked_actions(self, actions: object) -> np.ndarray:
        """``actions`` as numbers of shape (K, N, F), each finite within float32's range, or a ValueError naming the
        world, the robot and the field."""
        given = np.asarray(actions)
        if given.shape != self._actions.shape:
            raise ValueError(f"actions of shape {given.shape}; this env takes (worlds, robots, fields) = "
                             f"{self._actions.shape} (no broadcasting: one action a robot of each world)")
        if not (np.issubdtype(given.dtype, np.number) or given.dtype == np.bool_):
            raise ValueError(f"actions of type {given.dtype}: numbers")
        values = given.astype(np.float64)
        bad = ~np.isfinite(values) | (np.abs(values) > np.finfo(np.float32).max)
        if bad.any():
            w, r, f = (int(i) for i in np.argwhere(bad)[0])
            value = float(values[w, r, f])
            raise ValueError(f"world {w}, robot {self.agents[r]}: action field {f} is {value!r}, not a finite float32")
        return values

    def _rewards(self, transition: Transition, shape: tuple[int, int]) -> np.ndarray:
        if self._reward is None:
            return np.zeros(shape, np.float32)
        if isinstance(self._reward, str):
            gain = (transition.metrics[self._reward] - transition.previous_metrics[self._reward]).astype(np.float32)
            return np.repeat(gain[:, None], shape[1], axis=1)
        given = np.array(self._reward(transition), np.float32)  # (a copy: this step's zeros go into it, not theirs)
        return given if given.shape == shape else np.broadcast_to(given, shape).copy()

    def close(self) -> None:
        self.host.close()

    def __enter__(self) -> VectorEnv:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def sample_actions(env: VectorEnv, rng: np.random.Generator) -> np.ndarray:
    """Uniformly random actions for every robot of every world, within each robot's action space."""
    lows = np.stack([env.action_space(a).low for a in env.agents])
    highs = np.stack([env.action_space(a).high for a in env.agents])
    return rng.uniform(lows, highs, size=(env.num_worlds, *lows.shape)).astype(np.float32)


__all__ = ["Batch", "Metrics", "Transition", "VectorEnv", "sample_actions"]

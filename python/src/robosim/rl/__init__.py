"""Learning controllers over RoboSim worlds (``pip install "robosim[rl]"``): a world's robots as a PettingZoo
``ParallelEnv``, K copies of a world stepped together (``VectorEnv``), one robot as a Gymnasium ``Env``
(``SingleRobotEnv``); all over the learning link to a learning host this package starts (python/README.md)."""

from robosim.rl.host import Batch, HostError, LearningHost, Welcome, find_home
from robosim.rl.parallel import ParallelEnv
from robosim.rl.single import SingleRobotEnv
from robosim.rl.spaces import Layout
from robosim.rl.vector import Transition, VectorEnv, sample_actions

__all__ = ["Batch", "HostError", "Layout", "LearningHost", "ParallelEnv", "SingleRobotEnv", "Transition", "VectorEnv",
           "Welcome", "find_home", "sample_actions"]

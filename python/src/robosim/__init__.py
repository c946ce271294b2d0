"""Control code for RoboSim robots in Python: a robot (``Robot``) over RoboSim's robot link, and a command that runs
a controller script for one robot (``python -m robosim SCRIPT``); runs and sweeps of worlds from Python
(``robosim.run``, ``robosim.sweep``: ``robosim.runs``, loaded at their first use)."""

from robosim.frames import LinkError
from robosim.robot import Message, Pose, Robot, RobotValueError, SimulationOver

__all__ = ["LinkError", "Message", "Pose", "Robot", "RobotValueError", "RunResult", "SimulationOver", "run", "sweep"]


def __getattr__(name: str) -> object:
    """``run``, ``sweep`` and ``RunResult`` from ``robosim.runs``, imported when first asked for (a controller's
    ``import robosim`` does not load the hosts' code)."""
    if name in ("run", "sweep", "RunResult"):
        from robosim import runs  # noqa: PLC0415

        return getattr(runs, name)
    raise AttributeError(f"module 'robosim' has no attribute {name!r}")

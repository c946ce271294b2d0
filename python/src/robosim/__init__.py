"""Control code for RoboSim robots in Python: a robot (``Robot``) over RoboSim's robot link, and a command that runs
a controller script for one robot (``python -m robosim SCRIPT``)."""

from robosim.frames import LinkError
from robosim.robot import Message, Pose, Robot, RobotValueError, SimulationOver

__all__ = ["LinkError", "Message", "Pose", "Robot", "RobotValueError", "SimulationOver"]

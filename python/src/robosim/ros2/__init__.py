"""RoboSim and ROS 2 (``pip install "robosim[ros2]"``; python/README.md, "From ROS 2"): the ROS 2 bridge, which
drives a world's ``control="ros2"`` robots by ROS 2 topics over Zenoh as ``rmw_zenoh`` speaks it
(``robosim.ros2.bridge``), and a run's messages as an MCAP file (``robosim.ros2.recorder``), live or exported from a
recording. ``python -m robosim.ros2 --help`` says how to run them."""

from robosim.ros2.bridge import Bridge, Options
from robosim.ros2.messages import Messages, Topic
from robosim.ros2.recorder import Recorder

__all__ = ["Bridge", "Messages", "Options", "Recorder", "Topic"]

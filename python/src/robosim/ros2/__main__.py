"""``python -m robosim.ros2``: the ROS 2 bridge (``bridge WORLD``), a Zenoh router for it (``router``), and the
MCAP export that ``record-tool.sh export`` hands a recording's frames to (``export``)."""

import sys

from robosim.ros2.cli import main

sys.exit(main())

#!/usr/bin/env bash
# One robot process: scripts/robot.sh CONTROL NAME HOST 8000 [--type ArRobot|Scout|CLASS] (default: the file's type) [--classpath PATH[:PATH...]] [--help]
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.hardware.RobotMain "$@"

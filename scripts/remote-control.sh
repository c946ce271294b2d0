#!/usr/bin/env bash
# The Remote Control: drives the robots listed in a RobotInfo.xml (each running
# robosim.examples.RemoteControlRobot) from the keyboard. Needs a display.
#   scripts/remote-control.sh [test-envs/RobotInfo.xml] [--classpath PATH[:PATH...]]      see --help
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.remote.RemoteControlMain "$@"

#!/usr/bin/env bash
# Many robots in one process: scripts/robots.sh HOST 8000 --robot NAME:TYPE:CONTROL ... [--classpath PATH[:PATH...]] [--help]
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.hardware.MultiRobotMain "$@"

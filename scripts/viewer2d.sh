#!/usr/bin/env bash
# A viewer window onto a running Environment: scripts/viewer2d.sh HOST 3000 [--sonar] [--classpath PATH[:PATH...]] [--help]
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.viewer.Viewer2DMain "$@"

#!/usr/bin/env bash
# The Geometry process: scripts/geometry.sh HOST 10000 [--classpath PATH[:PATH...]] [--help]
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.geometry.GeometryMain "$@"

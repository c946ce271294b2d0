#!/usr/bin/env bash
# The Environment server: scripts/environment.sh FILE.xml [--no-geometry] [--steps N] [--classpath PATH[:PATH...]] [--help]
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.environment.EnvironmentMain "$@"

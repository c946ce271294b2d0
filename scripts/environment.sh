#!/usr/bin/env bash
# The Environment server: scripts/environment.sh FILE.xml [--no-geometry] [--steps N] [--speed F] [--classpath PATH[:PATH...]] [--help]
# Without --steps it runs in real time (--speed 1) unless --speed says otherwise (--speed 0: flat out).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.environment.EnvironmentMain "$@"

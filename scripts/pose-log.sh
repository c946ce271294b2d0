#!/usr/bin/env bash
# A recording viewer without a display, on this machine or another: writes every step's poses of a running
# Environment as CSV until the simulation ends:
#   scripts/pose-log.sh HOST 3000 FILE.csv [--progress] [--timeout-s S] [--help]
# With the simulation's keys (ROBOSIM_KEYS) it connects over TLS and proves the secret, as every client does.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.runner.PoseLogMain "$@"

#!/usr/bin/env bash
# Replays a recording made with --record (environment.sh, headless.sh) to any viewer:
#   scripts/replay.sh FILE [--viewer-port P] [--control-port P] [--speed X] [--paused] [--exit-at-end] [--help]
# then scripts/viewer2d.sh (or pose-log.sh) on the viewer port, and the Control Panel (or
# `echo "seek 2500" | nc localhost 8100`) to pause, resume, step N, seek K, speed X (0.1 to 100), stop.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.environment.replay.ReplayMain "$@"

#!/usr/bin/env bash
# A whole run, every part its own process: scripts/headless.sh --env FILE --steps N [--classpath PATH[:PATH...]] [--help]
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_java robosim.runner.HeadlessRunner "$@"

#!/usr/bin/env bash
# The demo: the bundled default environment (test-envs/test.xml), every part its own process, with
# live progress and a summary. With a display ($DISPLAY set) it also opens a viewer window and runs
# at 10x real time so you can watch; without one it runs headless as fast as it can.
#   scripts/demo.sh [--classpath PATH[:PATH...]] [headless.sh options...] [--help]
# Other arguments go to headless.sh (for example --steps 10000; scripts/headless.sh --help lists
# them). --classpath (or ROBOSIM_CLASSPATH) adds entries after RoboSim's own jars to every process;
# relative entries are taken from the directory you start the demo in.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_take_classpath "$@"
set -- "${ROBOSIM_ARGS[@]}"
for a in "$@"; do
  case $a in --) break ;; -h|--help) robosim_usage; exit 0 ;; esac
done
cd "$ROBOSIM_HOME"
if [ -n "${DISPLAY:-}" ]; then
  exec scripts/headless.sh --env test-envs/test.xml --steps 2000 --speed 10 --viewer --progress "$@"
fi
exec scripts/headless.sh --env test-envs/test.xml --steps 5000 --progress "$@"

#!/usr/bin/env bash
# The demo: the bundled default environment (test-envs/test.xml), every part its own process, with
# live progress and a summary. With a display ($DISPLAY set) it also opens a viewer window and runs
# at 10x real time so you can watch; without one it runs headless as fast as it can.
# Extra arguments go to headless.sh (for example --steps 10000).
cd "$(dirname "${BASH_SOURCE[0]}")/.." || exit 1
if [ -n "${DISPLAY:-}" ]; then
  exec scripts/headless.sh --env test-envs/test.xml --steps 2000 --speed 10 --viewer --progress "$@"
fi
exec scripts/headless.sh --env test-envs/test.xml --steps 5000 --progress "$@"

#!/usr/bin/env bash
# Makes control-panel.png and remote-control.png: the real windows under Xvfb, attached to a running
# simulation of test-envs/remote.xml (two RemoteControlRobots, test-envs/RobotInfo.xml).
# Needs Debian's xvfb (installed here if missing and we are root).
#   scripts/screenshot-panels.sh [--write-docs | --out DIR] [--classpath PATH[:PATH...]] [--help]
# Writes both into a fresh temporary directory (its path is printed), into DIR with --out DIR, or into
# docs/ (which README.md shows) with --write-docs.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_script_args docs "$@"
[ ${#ROBOSIM_ARGS[@]} = 0 ] || robosim_fail "takes no arguments, got '${ROBOSIM_ARGS[0]}' (see --help)"
[ ${#ROBOSIM_PASS[@]} = 0 ] || robosim_fail "takes nothing after -- (see --help)"
dir=$(robosim_out_dir)
cd "$ROBOSIM_HOME"
robosim_need_xvfb screenshot-panels
robosim_build_if_stale
cp=$(robosim_classpath)
display=:$((90 + RANDOM % 9))
Xvfb "$display" -screen 0 1024x768x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
pids=()
cleanup() { kill "$xvfb" "${pids[@]}" 2>/dev/null || true; }
trap cleanup EXIT
base=$((14000 + RANDOM % 800))
java -cp "$cp" robosim.environment.EnvironmentMain test-envs/remote.xml --no-geometry --robot-port "$base" \
  --viewer-port $((base + 1)) --control-port $((base + 2)) --speed 4 >/dev/null 2>&1 &
pids+=($!)
for r in rc1 rc2; do
  java -cp "$cp" -Drobosim.robotInfo=test-envs/RobotInfo.xml robosim.hardware.RobotMain \
    robosim.examples.RemoteControlRobot "$r" 127.0.0.1 "$base" --type "$([ $r = rc1 ] && echo ArRobot || echo Scout)" \
    >/dev/null 2>&1 &
  pids+=($!)
done
sleep 4   # a script, not a test: let the processes come up
java -cp "$cp" robosim.control.ControlPanelMain 127.0.0.1 $((base + 2)) step 20 >/dev/null
java -cp "$cp" robosim.control.ControlPanelMain 127.0.0.1 $((base + 2)) resume >/dev/null
DISPLAY=$display java -cp "$cp" robosim.control.ControlPanelMain 127.0.0.1 $((base + 2)) >/dev/null 2>&1 &
pids+=($!)
sleep 4
DISPLAY=$display java -cp "$cp" robosim.viewer.ScreenCapture "$dir/control-panel.png"
kill "${pids[-1]}"
DISPLAY=$display java -cp "$cp" robosim.remote.RemoteControlMain test-envs/RobotInfo.xml >/dev/null 2>&1 &
pids+=($!)
sleep 4
DISPLAY=$display java -cp "$cp" robosim.viewer.ScreenCapture "$dir/remote-control.png" --keys UP,UP,LEFT,TAB,RIGHT
echo "wrote $dir/control-panel.png and $dir/remote-control.png"

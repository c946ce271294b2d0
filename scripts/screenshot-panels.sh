#!/usr/bin/env bash
# Makes docs/control-panel.png and docs/remote-control.png: the real windows under Xvfb, attached to
# a running simulation of test-envs/remote.xml (two RemoteControlRobots, test-envs/RobotInfo.xml).
# Needs Debian's xvfb (installed here if missing and we are root).
#   scripts/screenshot-panels.sh
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source scripts/common.sh
robosim_need_xvfb screenshot-panels
robosim_build_if_missing
jar=$(ls runner/target/runner-*.jar | head -n 1)
cp="runner/target/lib/*:$jar"
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
mkdir -p docs
DISPLAY=$display java -cp "$cp" robosim.viewer.ScreenCapture docs/control-panel.png
kill "${pids[-1]}"
DISPLAY=$display java -cp "$cp" robosim.remote.RemoteControlMain test-envs/RobotInfo.xml >/dev/null 2>&1 &
pids+=($!)
sleep 4
DISPLAY=$display java -cp "$cp" robosim.viewer.ScreenCapture docs/remote-control.png --keys UP,UP,LEFT,TAB,RIGHT
echo "wrote docs/control-panel.png and docs/remote-control.png"

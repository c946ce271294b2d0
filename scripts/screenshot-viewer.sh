#!/usr/bin/env bash
# Makes viewer.png: a real Viewer2D window under Xvfb, watching test-envs/test.xml with sonar
# cones on; and robot-viewer.png beside it: the robot-specific window (viewer2d.sh --watch f1) on
# test-envs/sensors.xml. Needs Debian's xvfb (installed here if missing and we are root).
#   scripts/screenshot-viewer.sh [--write-docs | --out DIR | OUT.png] [--classpath PATH[:PATH...]] [--help]
# Writes viewer.png into a fresh temporary directory (its path is printed), into DIR with --out DIR,
# to OUT.png, or to docs/viewer.png (which README.md shows) with --write-docs; robot-viewer.png goes
# into the same directory.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_script_args docs "$@"
[ ${#ROBOSIM_ARGS[@]} -le 1 ] || robosim_fail "takes at most one argument, OUT.png, got ${ROBOSIM_ARGS[*]} (see --help)"
[ ${#ROBOSIM_PASS[@]} = 0 ] || robosim_fail "takes nothing after -- (see --help)"
if [ ${#ROBOSIM_ARGS[@]} = 1 ]; then
  if [ "$ROBOSIM_WRITE_DOCS" = 1 ] || [ -n "$ROBOSIM_OUT_ARG" ]; then
    robosim_fail "give OUT.png, --out DIR or --write-docs, not more than one"
  fi
  out=$(robosim_abs "${ROBOSIM_ARGS[0]}")
else
  out="$(robosim_out_dir)/viewer.png"
fi
cd "$ROBOSIM_HOME"
robosim_need_xvfb screenshot-viewer
robosim_build_if_stale
cp=$(robosim_classpath)
display=:$((90 + RANDOM % 9))
Xvfb "$display" -screen 0 920x660x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
run="" viewer=""
cleanup() { kill "$xvfb" ${run:+"$run"} ${viewer:+"$viewer"} 2>/dev/null || true; }
trap cleanup EXIT
ports=$((13000 + RANDOM % 900))
scripts/headless.sh --env test-envs/test.xml --steps 3000 --speed 8 --ports $((ports + 2000)),$ports,$((ports + 4000)) \
  >/dev/null 2>&1 &
run=$!
sleep 3
DISPLAY=$display java -cp "$cp" robosim.viewer.Viewer2DMain 127.0.0.1 "$ports" --sonar >/dev/null 2>&1 &
viewer=$!
sleep 12   # a script, not a test: let the robots drive a while so trails and sonar show
mkdir -p "$(dirname "$out")"
DISPLAY=$display java -cp "$cp" robosim.viewer.ScreenCapture "$out"
echo "wrote $out"
kill "$viewer" "$run" 2>/dev/null || true
wait "$viewer" "$run" 2>/dev/null || true
ports=$((ports + 100))
scripts/headless.sh --env test-envs/sensors.xml --steps 3000 --speed 2 \
  --ports $((ports + 2000)),$ports,$((ports + 4000)) >/dev/null 2>&1 &
run=$!
sleep 3
DISPLAY=$display java -cp "$cp" robosim.viewer.Viewer2DMain 127.0.0.1 "$ports" --watch f1 >/dev/null 2>&1 &
viewer=$!
sleep 10
robot_out="$(dirname "$out")/robot-viewer.png"
DISPLAY=$display java -cp "$cp" robosim.viewer.ScreenCapture "$robot_out"
echo "wrote $robot_out"

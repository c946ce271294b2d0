#!/usr/bin/env bash
# Makes docs/viewer.png: a real Viewer2D window under Xvfb, watching test-envs/test.xml with sonar
# cones on. Needs Debian's xvfb (installed here if missing and we are root).
#   scripts/screenshot-viewer.sh [OUT.png]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
out=${1:-docs/viewer.png}
source scripts/common.sh
robosim_need_xvfb screenshot-viewer
robosim_build_if_missing
jar=$(ls runner/target/runner-*.jar | head -n 1)
cp="runner/target/lib/*:$jar"
display=:$((90 + RANDOM % 9))
Xvfb "$display" -screen 0 920x660x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
run=""
cleanup() { kill "$xvfb" ${run:+"$run"} 2>/dev/null || true; pkill -f "Viewer2DMain 127.0.0.1 13.." 2>/dev/null || true; }
trap cleanup EXIT
ports=$((13000 + RANDOM % 900))
scripts/headless.sh --env test-envs/test.xml --steps 3000 --speed 8 --ports $((ports + 2000)),$ports,$((ports + 4000)) \
  >/dev/null 2>&1 &
run=$!
sleep 3
DISPLAY=$display java -cp "$cp" robosim.viewer.Viewer2DMain 127.0.0.1 "$ports" --sonar >/dev/null 2>&1 &
sleep 12   # a script, not a test: let the robots drive a while so trails and sonar show
mkdir -p "$(dirname "$out")"
DISPLAY=$display java -cp "$cp" robosim.viewer.ScreenCapture "$out"
echo "wrote $out"

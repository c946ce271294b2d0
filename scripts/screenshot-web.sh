#!/usr/bin/env bash
# Makes web-2d.png and web-3d.png: the browser viewer (--web-port) in Debian's headless chromium, watching
# test-envs/maze.xml (sonar rays on in 2D), replay.png: the page on a replay of that run, paused at a
# step with its timeline, web-robot.png: the page's robot panel watching f1 on test-envs/sensors.xml, and
# web-3d-foraging.png: the 3D view of test-envs/foraging.xml (its floor, lamp, cans and the foot-bots' LEDs).
# Needs chromium (installed here if missing and we are root).
#   scripts/screenshot-web.sh [--write-docs | --out DIR] [--classpath PATH[:PATH...]] [--help]
# Writes into a fresh temporary directory (its path is printed), into DIR with --out DIR, or into docs/
# (which docs/VIEWERS.md shows) with --write-docs.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_script_args docs "$@"
[ ${#ROBOSIM_ARGS[@]} = 0 ] || robosim_fail "takes no arguments, got ${ROBOSIM_ARGS[*]} (see --help)"
[ ${#ROBOSIM_PASS[@]} = 0 ] || robosim_fail "takes nothing after -- (see --help)"
out=$(robosim_out_dir)
cd "$ROBOSIM_HOME"
if ! command -v chromium >/dev/null; then
  if [ "$(id -u)" = 0 ]; then apt-get update -qq && apt-get install -y -qq chromium >/dev/null; else
    robosim_fail "needs chromium (apt-get install chromium)"; fi
fi
robosim_build_if_stale
tmp=$(mktemp -d)
run="" replay=""
cleanup() { kill ${run:+"$run"} ${replay:+"$replay"} 2>/dev/null || true; rm -rf "$tmp"; }
trap cleanup EXIT
shot() { # FILE URL: the page after 4 s of its own time, loaded twice: headless chromium's time is virtual and runs
  # on without waiting for the network, so a server's first page, which starts the server's feed of the world, is
  # shot before the world has come (step -, an empty canvas); the second finds the feed running
  local i
  for i in 1 2; do
    chromium --headless=new --no-sandbox --disable-dev-shm-usage --enable-unsafe-swiftshader --use-angle=swiftshader \
      --user-data-dir="$tmp/chrome" --window-size=1200,800 --virtual-time-budget=4000 --screenshot="$1" "$2" \
      >/dev/null 2>&1
  done
  echo "wrote $1"
}
free_port() { local p; while :; do p=$((20000 + RANDOM % 20000))
  (exec 3<>"/dev/tcp/127.0.0.1/$p") 2>/dev/null || { echo "$p"; return; }; done; }
alive() { kill -0 "$1" 2>/dev/null || { tail -n 5 "$tmp/$3" >&2; robosim_fail "$2 stopped early (its last lines above)"; }; }
web=$(free_port)
scripts/headless.sh --env test-envs/maze.xml --steps 3000 --speed 8 --web-port "$web" --record "$tmp/maze.rec" \
  >"$tmp/run.log" 2>&1 &
run=$!
sleep 12   # a script, not a test: let the robots drive a while so trails and sonar show
alive "$run" "the run" run.log
shot "$out/web-2d.png" "http://localhost:$web/?sonar=1"
shot "$out/web-3d.png" "http://localhost:$web/?view=3d"
kill "$run" 2>/dev/null || true; wait "$run" 2>/dev/null || true; run=""
web=$(free_port); control=$(free_port)
scripts/replay.sh "$tmp/maze.rec" --viewer-port 0 --control-port "$control" --web-port "$web" --paused \
  >"$tmp/replay.log" 2>&1 &
replay=$!
sleep 5   # the replay is listening
alive "$replay" "the replay" replay.log
scripts/control-panel.sh localhost "$control" "seek 200" >/dev/null
shot "$out/replay.png" "http://localhost:$web/?follow=w3"
kill "$replay" 2>/dev/null || true; wait "$replay" 2>/dev/null || true; replay=""
web=$(free_port)
scripts/headless.sh --env test-envs/sensors.xml --steps 3000 --speed 2 --web-port "$web" >"$tmp/sensors.log" 2>&1 &
run=$!
sleep 12   # the followers have found their leader
alive "$run" "the sensors run" sensors.log
shot "$out/web-robot.png" "http://localhost:$web/?watch=f1&follow=f1"
kill "$run" 2>/dev/null || true; wait "$run" 2>/dev/null || true; run=""
web=$(free_port)
scripts/headless.sh --env test-envs/foraging.xml --steps 30000 --speed 4 --web-port "$web" >"$tmp/foraging.log" 2>&1 &
run=$!
sleep 15   # the foot-bots have found cans and carry some
alive "$run" "the foraging run" foraging.log
shot "$out/web-3d-foraging.png" "http://localhost:$web/?view=3d"

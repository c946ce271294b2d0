#!/usr/bin/env bash
# Output-stream reset interval against speed and heap: the paper benchmark (10 robots in one process,
# Geometry as a process) for STEPS steps at each interval; near the end (95%) a full GC in the
# Environment, the robots' and the Geometry process, then their old-generation sizes (SerialGC).
#   scripts/bench-reset.sh [STEPS]     (default 100000; writes docs/perf/reset-interval.txt)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
steps=${1:-100000}
mkdir -p docs/perf
out=docs/perf/reset-interval.txt
tenured() {
  [ -n "$1" ] || return 0
  jcmd "$1" GC.run >/dev/null 2>&1 || true
  jcmd "$1" GC.heap_info 2>/dev/null | sed -nE 's/.*tenured generation +total [0-9]+K, used ([0-9]+)K.*/\1/p' || true
}
echo "reset_every steps steps_per_s env_old_kb robots_old_kb geometry_old_kb" | tee "$out"
for n in 1 16 256 4096 0; do
  log=$(mktemp)
  scripts/headless.sh --env test-envs/paper-benchmark.xml --steps "$steps" --robots-in-one-process \
    --reset-every "$n" --progress >"$log" 2>/dev/null &
  run=$!
  target=$((steps * 95 / 100)); at=0
  while kill -0 "$run" 2>/dev/null; do
    at=$( (grep -oE '^step [0-9]+' "$log" || true) | tail -n 1 | cut -d' ' -f2); at=${at:-0}
    [ "$at" -ge "$target" ] && break
    sleep 1   # a script, not a test: polling a progress line
  done
  env=$( (pgrep -f "EnvironmentMain test-envs/paper-benchmark.xml --steps $steps" || true) | head -n 1)
  robots=$( (pgrep -f "MultiRobotMain 127.0.0.1 [0-9]+ --reset-every $n" || true) | head -n 1)
  geo=$( (pgrep -f "GeometryMain 127.0.0.1 [0-9]+ --reset-every $n" || true) | head -n 1)
  e=$(tenured "$env"); r=$(tenured "$robots"); g=$(tenured "$geo")
  wait "$run" || true
  rate=$(tail -n 1 "$log" | (grep -oE '(^| )steps_per_s=[0-9.]+' || true) | sed -E 's/.*=//')
  echo "$n $steps ${rate:-?} ${e:-?} ${r:-?} ${g:-?}" | tee -a "$out"
  rm -f "$log"
done

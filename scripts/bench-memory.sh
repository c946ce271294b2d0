#!/usr/bin/env bash
# Heap over a long run at the default reset interval: the paper benchmark (10 robots in one process,
# Geometry as a process) for 130,000 steps (a margin for jcmd); at step 10,000 and at step 100,000 a full GC in the
# Environment, the robots' JVM and Geometry, then their old-generation sizes (SerialGC).
#   scripts/bench-memory.sh          (writes docs/perf/memory.txt)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
mkdir -p docs/perf
out=docs/perf/memory.txt
steps=130000
tenured() {
  [ -n "$1" ] || return 0
  jcmd "$1" GC.run >/dev/null 2>&1 || true
  jcmd "$1" GC.heap_info 2>/dev/null | sed -nE 's/.*tenured generation +total [0-9]+K, used ([0-9]+)K.*/\1/p' || true
}
log=$(mktemp)
scripts/headless.sh --env test-envs/paper-benchmark.xml --steps "$steps" --robots-in-one-process --progress \
  >"$log" 2>/dev/null &
run=$!
echo "step env_old_kb robots_old_kb geometry_old_kb" | tee "$out"
for target in 10000 100000; do
  at=0
  while kill -0 "$run" 2>/dev/null; do
    at=$( (grep -oE '^step [0-9]+' "$log" || true) | tail -n 1 | cut -d' ' -f2); at=${at:-0}
    [ "$at" -ge "$target" ] && break
    sleep 1   # a script, not a test: polling a progress line
  done
  env=$( (pgrep -f "EnvironmentMain test-envs/paper-benchmark.xml --steps $steps" || true) | head -n 1)
  robots=$( (pgrep -f "MultiRobotMain 127.0.0.1" || true) | head -n 1)
  geo=$( (pgrep -f "GeometryMain 127.0.0.1" || true) | head -n 1)
  echo "$at $(tenured "$env") $(tenured "$robots") $(tenured "$geo")" | tee -a "$out"
done
wait "$run" || true
tail -n 1 "$log" | tee -a "$out"
rm -f "$log"

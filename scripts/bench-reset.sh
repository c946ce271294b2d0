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
source scripts/bench-lib.sh
echo "reset_every steps steps_per_s env_old_kb robots_old_kb geometry_old_kb" | tee "$out"
for n in 1 16 256 4096 0; do
  log=$(mktemp)
  scripts/headless.sh --env test-envs/paper-benchmark.xml --steps "$steps" --robots-in-one-process \
    --reset-every "$n" --progress >"$log" 2>/dev/null &
  run=$!
  await_step "$log" "$run" $((steps * 95 / 100)) >/dev/null
  env=$(pid_of "EnvironmentMain test-envs/paper-benchmark.xml --steps $steps")
  robots=$(pid_of "MultiRobotMain 127.0.0.1 [0-9]+ --reset-every $n")
  geo=$(pid_of "GeometryMain 127.0.0.1 [0-9]+ --reset-every $n")
  e=$(tenured "$env"); r=$(tenured "$robots"); g=$(tenured "$geo")
  wait "$run" || true
  rate=$(tail -n 1 "$log" | (grep -oE '(^| )steps_per_s=[0-9.]+' || true) | sed -E 's/.*=//')
  echo "$n $steps ${rate:-?} ${e:-?} ${r:-?} ${g:-?}" | tee -a "$out"
  rm -f "$log"
done

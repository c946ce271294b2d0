#!/usr/bin/env bash
# Output-stream reset interval against speed and heap: the paper benchmark (10 robots in one process,
# Geometry as a process) for STEPS + 30% steps at each interval (the margin lets jcmd finish); at step
# STEPS a full GC in the Environment, the robots' and the Geometry process, then their old-generation
# sizes (SerialGC). steps_per_s is over the whole run.
#   scripts/bench-reset.sh [STEPS] [--write-docs | --out DIR] [--classpath PATH[:PATH...]] [--help]
# STEPS defaults to 100000. Writes reset-interval.txt into a fresh temporary directory (its path is
# printed), into DIR with --out DIR, or into docs/perf/ (which docs/PERFORMANCE.md quotes and
# bench.sh plots) with --write-docs.
# The floor (bench/Floor.java 10 STEPS obj) runs before and after, in the same sitting; each
# row's ratio is its steps/s over their mean.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_script_args docs/perf "$@"
[ ${#ROBOSIM_ARGS[@]} -le 1 ] || robosim_fail "takes at most one argument, STEPS, got ${ROBOSIM_ARGS[*]} (see --help)"
[ ${#ROBOSIM_PASS[@]} = 0 ] || robosim_fail "takes nothing after -- (see --help)"
steps=${ROBOSIM_ARGS[0]:-100000}
robosim_count STEPS "$steps"
total=$((steps + steps * 3 / 10))
out="$(robosim_out_dir)/reset-interval.txt"
cd "$ROBOSIM_HOME"
robosim_build_if_stale
source scripts/bench-lib.sh
floor_run() { java bench/Floor.java 10 "$steps" obj | awk '{ for (i = 1; i <= NF; i++) { split($i, kv, "=");
  v[kv[1]] = kv[2] } } END { sub(/s$/, "", v["wall"]); printf "%.1f", v["steps"] / v["wall"] }'; }
f1=$(floor_run)
echo "reset_every steps steps_per_s env_old_kb robots_old_kb geometry_old_kb" | tee "$out"
rows=()
for n in 1 16 256 4096 0; do
  log=$(mktemp)
  scripts/headless.sh --env test-envs/paper-benchmark.xml --steps "$total" --robots-in-one-process \
    --reset-every "$n" --progress >"$log" 2>/dev/null &
  run=$!
  await_step "$log" "$run" "$steps" >/dev/null
  env=$(pid_of "EnvironmentMain test-envs/paper-benchmark.xml --steps $total")
  robots=$(pid_of "MultiRobotMain 127.0.0.1 [0-9]+ --reset-every $n")
  geo=$(pid_of "GeometryMain 127.0.0.1 [0-9]+ --reset-every $n")
  e=$(tenured "$env"); r=$(tenured "$robots"); g=$(tenured "$geo")
  wait "$run" || true
  rate=$(tail -n 1 "$log" | (grep -oE '(^| )steps_per_s=[0-9.]+' || true) | sed -E 's/.*=//')
  echo "$n $steps ${rate:-?} ${e:-?} ${r:-?} ${g:-?}" | tee -a "$out"
  rows+=("$n ${rate:-0}")
  rm -f "$log"
done
f2=$(floor_run)
echo "floor (Floor.java 10 $steps obj) before: $f1 steps/s, after: $f2 steps/s" | tee -a "$out"
for row in "${rows[@]}"; do
  set -- $row
  awk -v n="$1" -v r="$2" -v a="$f1" -v b="$f2" 'BEGIN { printf "ratio reset_every=%s %.2f\n", (n == 0 ? "never" : n), r / ((a + b) / 2) }'
done | tee -a "$out"
echo "bench-reset: wrote $out"

#!/usr/bin/env bash
# Heap over a long run at the default reset interval: the paper benchmark (10 robots in one process,
# Geometry as a process) for 130,000 steps (a margin for jcmd); at step 10,000 and at step 100,000 a full GC in the
# Environment, the robots' JVM and Geometry, then their old-generation sizes (SerialGC).
#   scripts/bench-memory.sh [--write-docs | --out DIR] [--classpath PATH[:PATH...]] [--help]
# Writes memory.txt into a fresh temporary directory (its path is printed), into DIR with --out DIR,
# or into docs/perf/ (the file docs/PERFORMANCE.md quotes) with --write-docs.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_script_args docs/perf "$@"
[ ${#ROBOSIM_ARGS[@]} = 0 ] || robosim_fail "takes no arguments, got '${ROBOSIM_ARGS[0]}' (see --help)"
[ ${#ROBOSIM_PASS[@]} = 0 ] || robosim_fail "takes nothing after -- (see --help)"
out="$(robosim_out_dir)/memory.txt"
cd "$ROBOSIM_HOME"
robosim_build_if_stale
steps=130000
source scripts/bench-lib.sh
log=$(mktemp)
scripts/headless.sh --env test-envs/paper-benchmark.xml --steps "$steps" --robots-in-one-process --progress \
  >"$log" 2>/dev/null &
run=$!
echo "step env_old_kb robots_old_kb geometry_old_kb" | tee "$out"
for target in 10000 100000; do
  at=$(await_step "$log" "$run" "$target")
  env=$(pid_of "EnvironmentMain test-envs/paper-benchmark.xml --steps $steps")
  robots=$(pid_of "MultiRobotMain 127.0.0.1")
  geo=$(pid_of "GeometryMain 127.0.0.1")
  echo "$at $(tenured "$env") $(tenured "$robots") $(tenured "$geo")" | tee -a "$out"
done
wait "$run" || true
tail -n 1 "$log" | tee -a "$out"
rm -f "$log"
echo "bench-memory: wrote $out"

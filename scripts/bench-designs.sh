#!/usr/bin/env bash
# Each coordinator design against the floor of its own thread shape, in one sitting, alternated:
#   scripts/bench-designs.sh [REPS] [--quick] [--write-docs | --out DIR] [--classpath PATH[:PATH...]] [--help]
# REPS defaults to 2. For N = 10, 100, 1000 robots (test-envs/bench-N.xml: Wander Scouts, 16 sonars read
# every step, Geometry as its own process, robots in one process with a socket each), each repetition runs in turn:
#   bench/FloorThreads.java N S             the cheapest thread-per-client shape (a reader per socket,
#                                           one loop thread writing every reply)
#   headless.sh --coordinator THREADS       the default, the report's design, with and without
#                                           --no-geometry (the Geometry process's round trip, which the
#                                           floors do not have)
#   bench/FloorShared.java N S              the cheapest socket-per-robot shape (one thread each side)
#   headless.sh --coordinator SEQUENTIAL    the original's loop, with and without --no-geometry
# and, for each design, where the time goes: the Environment alone driven by the floors' client shape
# (robosim.bench.BareRobots: one thread owns every robot's socket, no control code), with requests that
# ask for nothing ("bare still": the coordination alone), with the workload's move and 16 sonars
# in-process ("bare --no-geometry"), and with the Geometry process ("bare").
# It prints each run with its ratio to its own floor of the same repetition, then the medians. Writes
# designs.csv (one row per run, appended) into a fresh temporary directory (printed), DIR with
# --out DIR, or docs/perf/ with --write-docs. --quick: one repetition with a fifth of the steps.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_bench_args 2 docs/perf "$@"
reps=$BENCH_REPS quick=$BENCH_QUICK
dir=$(robosim_out_dir)
robosim_build_if_stale
out=$dir/designs.csv
sitting=$(date -u +%Y-%m-%dT%H:%MZ)
[ -f "$out" ] || echo "sitting,variant,robots,steps,rep,steps_per_s,floor,floor_steps_per_s,ratio_to_floor" > "$out"

steps_for() {
  local s
  case $1 in 10) s=5000 ;; 100) s=1000 ;; *) s=150 ;; esac
  [ "$quick" = 1 ] && s=$((s / 5))
  echo "$s"
}
source "$ROBOSIM_HOME/scripts/bench-lib.sh" # (floor_rate, rate, row)

designs() { # design robots steps rep floor floor_rate: the design with and without the Geometry process
  local g r
  for g in "" --no-geometry; do
    r=$(scripts/headless.sh --env "test-envs/bench-$2.xml" --steps "$3" --robots-in-one-process \
      --connection PER_ROBOT --coordinator "$1" ${g:+"$g"} 2>/dev/null | tail -n 1 | rate) || true
    row "$1${g:+ $g}" "$2" "$3" "$4" "${r:-}" "$5" "$6"
  done
}

bench_jar=$(ls bench-jmh/target/bench-jmh-*.jar 2>/dev/null | head -n 1 || true)
[ -n "$bench_jar" ] || { ./mvnw -q -B -ntp package -DskipTests -pl protocol,bench-jmh >&2; bench_jar=$(ls bench-jmh/target/bench-jmh-*.jar | head -n 1); }
bare() { # design robots steps rep floor floor_rate still|sonar --no-geometry|"": the Environment, bare clients
  local log=$dir/bare-environment.log port gport gpid="" r variant
  scripts/environment.sh --robot-port 0 --viewer-port 0 --geometry-port 0 --control-port -1 \
    --coordinator "$1" --steps "$3" ${8:+"$8"} "test-envs/bench-$2.xml" > "$log" 2>&1 &
  local epid=$!
  for _ in $(seq 300); do grep -q '^listening' "$log" && break; sleep 0.1; done
  port=$(grep -oE '^listening robots=[0-9]+' "$log" | cut -d= -f2)
  if [ -z "$8" ]; then
    gport=$(grep -oE 'geometry=[0-9]+' "$log" | cut -d= -f2)
    scripts/geometry.sh 127.0.0.1 "$gport" > /dev/null 2>&1 & gpid=$!
  fi
  r=$(java -cp "bench-jmh/target/lib/*:$bench_jar" robosim.bench.BareRobots "$port" "$2" \
    $([ "$7" = still ] && echo still) | floor_rate) || true
  wait "$epid" || true
  [ -z "$gpid" ] || wait "$gpid" || true
  variant="$1 bare"
  [ "$7" = still ] && variant="$variant still"
  row "$variant${8:+ $8}" "$2" "$3" "$4" "${r:-}" "$5" "$6"
}
bare_rows() { # design robots steps rep floor floor_rate
  bare "$@" still --no-geometry
  bare "$@" sonar --no-geometry
  bare "$@" sonar ""
}

for rep in $(seq "$reps"); do
  echo "== repetition $rep of $reps"
  for n in 10 100 1000; do
    s=$(steps_for "$n")
    ft=$(java bench/FloorThreads.java "$n" "$s" | floor_rate)
    row FloorThreads "$n" "$s" "$rep" "$ft" FloorThreads "$ft"
    designs THREADS "$n" "$s" "$rep" FloorThreads "$ft"
    bare_rows THREADS "$n" "$s" "$rep" FloorThreads "$ft"
    fs=$(java bench/FloorShared.java "$n" "$s" | floor_rate)
    row FloorShared "$n" "$s" "$rep" "$fs" FloorShared "$fs"
    designs SEQUENTIAL "$n" "$s" "$rep" FloorShared "$fs"
    bare_rows SEQUENTIAL "$n" "$s" "$rep" FloorShared "$fs"
  done
done
echo "== medians of this sitting (ratio: to the floor of the same shape, same repetition)"
awk -F, -v s="$sitting" '$1 == s && $2 != "FloorThreads" && $2 != "FloorShared" {
    k = $2 " N=" $3; n[k]++; r[k, n[k]] = $9; v[k, n[k]] = $6; order[k] = NR }
  END { for (k in n) { m = n[k]; for (i = 1; i <= m; i++) for (j = i + 1; j <= m; j++) {
          if (r[k, j] < r[k, i]) { t = r[k, i]; r[k, i] = r[k, j]; r[k, j] = t }
          if (v[k, j] < v[k, i]) { t = v[k, i]; v[k, i] = v[k, j]; v[k, j] = t } }
        mid = int((m + 1) / 2); med = (m % 2) ? r[k, mid] : (r[k, mid] + r[k, mid + 1]) / 2
        medv = (m % 2) ? v[k, mid] : (v[k, mid] + v[k, mid + 1]) / 2
        printf "%-28s %9.1f steps/s  ratio %.2f\n", k, medv, med } }' "$out" | sort
echo "bench-designs: rows appended to $out"

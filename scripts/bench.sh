#!/usr/bin/env bash
# The benchmark suite (outside the tests): every speed question of the performance work, each run
# next to bench/Floor.java in the same sitting, repeated and alternated.
#   scripts/bench.sh [REPS] [--quick] [--write-docs | --out DIR] [--classpath PATH[:PATH...]] [--help]
# REPS defaults to 3. --quick: one repetition with fewer steps (a smoke run).
# Writes results.csv (one row per run, appended) and the plots *.png (robosim.bench.Plots, which also
# reads reset-interval.txt and serialization.txt / message-sizes.txt from bench-reset.sh and
# bench-serialization.sh in the same directory) into a fresh temporary directory (its path is
# printed), into DIR with --out DIR, or into docs/perf/ (which docs/PERFORMANCE.md quotes) with
# --write-docs.
#
# Scenarios (column `scenario`):
#   floor      Floor.java N STEPS obj, and obj-nostep at 10 (the reference; `ratio_to_floor` divides by it)
#   scaling    test-envs/bench-N.xml (N Wander Scouts, 16 sonars read every step, Geometry a process),
#              N = 1, 10, 100, 1000; robots in one process, and at 1 and 10 also as separate processes
#   paper      test-envs/paper-benchmark.xml (10 BackAndForth, 5000 steps), robots as separate processes:
#              each coordinator design and each of the report's untested ideas
#   designs    bench-100.xml, robots in one process: each coordinator design and robot exchange threading
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_bench_args 3 docs/perf "$@"
reps=$BENCH_REPS quick=$BENCH_QUICK
floor=bench/Floor.java
dir=$(robosim_out_dir)
robosim_build_if_stale
ls bench-jmh/target/lib/xchart-*.jar >/dev/null 2>&1 || ./mvnw -q -B package -DskipTests -pl bench-jmh -am

out=$dir/results.csv
sitting=$(date -u +%Y-%m-%dT%H:%MZ)
[ -f "$out" ] || echo "sitting,scenario,variant,robots,robots_in,steps,rep,steps_per_s,robot_steps_per_s,floor_steps_per_s,ratio_to_floor" > "$out"

# steps per run, by robot count: long enough to warm up, short enough for a sitting of minutes
steps_for() {
  local n=$1 s
  case $n in 1) s=20000 ;; 10) s=5000 ;; 100) s=1000 ;; *) s=150 ;; esac
  [ "$quick" = 1 ] && s=$((s / 5))
  echo "$s"
}
rate() { (grep -oE '(^| )steps(_per_s|/s)=[0-9.]+' || true) | head -n 1 | sed -E 's/.*=//'; }
floor_rate() { awk '{ for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] } }
  END { sub(/s$/, "", v["wall"]); if (v["wall"] > 0) printf "%.1f", v["steps"] / v["wall"] }'; }
declare -A floor_of

row() { # scenario variant robots robots_in steps rep steps_per_s
  local f=${floor_of[$3]:-} ratio=""
  [ -n "$f" ] && [ -n "$7" ] && ratio=$(awk -v a="$7" -v b="$f" 'BEGIN { printf "%.3f", a / b }')
  local rs
  rs=$(awk -v a="${7:-0}" -v n="$3" 'BEGIN { printf "%.1f", a * n }')
  echo "$sitting,$1,$2,$3,$4,$5,$6,$7,$rs,$f,$ratio" >> "$out"
  printf '%-8s %-34s N=%-5s %-12s %8s steps/s  floor %8s  ratio %s\n' "$1" "$2" "$3" "$4" "$7" "$f" "$ratio"
}

run_floor() { # rep n
  local s l r
  s=$(steps_for "$2")
  # the floor prints whole steps/s; steps / wall keeps the decimals that matter at 1000 clients
  l=$(java "$floor" "$2" "$s" obj); r=$(echo "$l" | floor_rate)
  floor_of[$2]=$r
  row floor obj "$2" threads "$s" "$1" "$r"
}

headless() { # scenario variant rep env steps robots robots_in [options...]
  local scenario=$1 variant=$2 rep=$3 env=$4 s=$5 n=$6 in=$7 l r
  shift 7
  local extra=()
  [ "$in" = one-process ] && extra+=(--robots-in-one-process)
  l=$(scripts/headless.sh --env "$env" --steps "$s" "${extra[@]}" "$@" 2>/dev/null | tail -n 1) || true
  r=$(echo "$l" | rate)
  row "$scenario" "$variant" "$n" "$in" "$s" "$rep" "${r:-}"
}

for rep in $(seq "$reps"); do
  echo "== repetition $rep of $reps"
  for n in 1 10 100 1000; do
    run_floor "$rep" "$n"
    s=$(steps_for "$n")
    headless scaling default "$rep" "test-envs/bench-$n.xml" "$s" "$n" one-process
    if [ "$n" -le 10 ]; then
      headless scaling default "$rep" "test-envs/bench-$n.xml" "$s" "$n" processes
    fi
  done
  # the floor without a step message, for the no-step-messages setting
  s=$(steps_for 10)
  l=$(java "$floor" 10 "$s" obj-nostep); row floor obj-nostep 10 threads "$s" "$rep" "$(echo "$l" | floor_rate)"
  p=5000; [ "$quick" = 1 ] && p=1000
  for d in SEQUENTIAL THREADS TWO_THREADS; do
    headless paper "coordinator=$d" "$rep" test-envs/paper-benchmark.xml "$p" 10 processes --coordinator "$d"
  done
  headless paper "no-step-messages" "$rep" test-envs/paper-benchmark.xml "$p" 10 processes --no-step-messages
  headless paper "exchange=SEND_RECEIVE" "$rep" test-envs/paper-benchmark.xml "$p" 10 processes --exchange SEND_RECEIVE
  s=$(steps_for 100)
  for d in SEQUENTIAL THREADS TWO_THREADS; do
    headless designs "coordinator=$d" "$rep" test-envs/bench-100.xml "$s" 100 one-process --coordinator "$d"
  done
  for x in ONE_THREAD SEND_RECEIVE; do
    headless designs "exchange=$x" "$rep" test-envs/bench-100.xml "$s" 100 one-process --exchange "$x"
  done
  headless designs "no-step-messages" "$rep" test-envs/bench-100.xml "$s" 100 one-process --no-step-messages
done

jar=$(ls bench-jmh/target/bench-jmh-*.jar | grep -v sources | head -n 1)
java -cp "bench-jmh/target/lib/*:$jar" robosim.bench.Plots "$dir"
echo "bench: rows appended to $out; plots in $dir/*.png"

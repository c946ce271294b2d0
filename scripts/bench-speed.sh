#!/usr/bin/env bash
# The speed table against ARGoS and Stage, in one sitting, alternated:
#   scripts/bench-speed.sh [REPS] [--quick] [--peers PREFIX] [--write-docs | --out DIR] [--classpath PATH[:PATH...]] [--help]
# REPS defaults to 2. For N = 10, 100, 1000 robots (test-envs/bench-N.xml: Wander Scouts, 16 sonars of 5 m
# read every step), each repetition runs in turn:
#   bench/FloorThreads.java N S             the floor of the thread-per-client shape
#   headless.sh --robots-in-one-process     the default: one shared connection for the robots' process
#   headless.sh ... --connection PER_ROBOT  a socket per robot, the default THREADS coordinator
#   bench/FloorShared.java N S              the floor of the one-thread-each-side shape
#   headless.sh ... --coordinator SEQUENTIAL  a socket per robot, the original loop
#   bench/Engine.java N S                   the engine alone: the floor of the one-JVM layout
#   headless.sh --one-jvm                   the whole simulation in one JVM
#   ARGoS 3 and Stage 4.3, with --peers PREFIX (built there by the peers' build-peers.sh): one round of the
#                                           peers' side-by-side.sh (../shared/peers/, or PEERS_SCRIPT) at N, S
# Every run is printed with its ratio to the floor of the same repetition (the shared connection and
# THREADS to FloorThreads, SEQUENTIAL to FloorShared, one JVM to Engine, the peers to Engine too), then the
# medians; without --peers the table shows the marks of ARGoS 3 and Stage 4.3 measured once on this machine
# kind (the speed issue) instead. Writes speed.csv (one row per run,
# appended) and speed.png (robosim.bench.SpeedPlot) into a fresh temporary directory (printed), DIR with
# --out DIR, or docs/perf/ with --write-docs, which also writes the medians' table into docs/PERFORMANCE.md
# between its speed-table marks (the doc's one current table). --quick: one repetition with a fifth of the steps.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_peer_bench_args 2 "$@"
peers=$BENCH_PEERS peer_script=$BENCH_PEER_SCRIPT
[ -z "$peers" ] || [ -x "$peers/stage/bin/stage" ] \
  || robosim_fail "--peers $peers: no stage/bin/stage there (build the peers with their build-peers.sh)"
reps=$BENCH_REPS quick=$BENCH_QUICK
dir=$(robosim_out_dir)
robosim_build_if_stale
jar=$(ls bench-jmh/target/bench-jmh-*.jar 2>/dev/null | head -n 1 || true)
ls bench-jmh/target/lib/xchart-*.jar >/dev/null 2>&1 && [ -n "$jar" ] \
  || { ./mvnw -q -B -ntp package -DskipTests -pl bench-jmh -am >&2; jar=$(ls bench-jmh/target/bench-jmh-*.jar | head -n 1); }
out=$dir/speed.csv
sitting=$(date -u +%Y-%m-%dT%H:%MZ)
[ -f "$out" ] || echo "sitting,variant,robots,steps,rep,steps_per_s,floor,floor_steps_per_s,ratio_to_floor" > "$out"
echo "java: $(java -version 2>&1 | head -n 1) ($ROBOSIM_JAVA_CHOICE)"

steps_for() {
  local s
  case $1 in 10) s=20000 ;; 100) s=3000 ;; *) s=600 ;; esac
  [ "$quick" = 1 ] && s=$((s / 5))
  echo "$s"
}
source "$ROBOSIM_HOME/scripts/bench-lib.sh" # (floor_rate, rate, row)
run() { # robots steps [options...]: steps/s of one headless run
  local n=$1 s=$2
  shift 2
  scripts/headless.sh --env "test-envs/bench-$n.xml" --steps "$s" --robots-in-one-process "$@" 2>/dev/null \
    | tail -n 1 | rate || true
}

for rep in $(seq "$reps"); do
  echo "== repetition $rep of $reps"
  for n in 10 100 1000; do
    s=$(steps_for "$n")
    ft=$(java bench/FloorThreads.java "$n" "$s" | floor_rate)
    row FloorThreads "$n" "$s" "$rep" "$ft" FloorThreads "$ft"
    row shared-connection "$n" "$s" "$rep" "$(run "$n" "$s")" FloorThreads "$ft"
    row THREADS-per-robot "$n" "$s" "$rep" "$(run "$n" "$s" --connection PER_ROBOT)" FloorThreads "$ft"
    fs=$(java bench/FloorShared.java "$n" "$s" | floor_rate)
    row FloorShared "$n" "$s" "$rep" "$fs" FloorShared "$fs"
    row SEQUENTIAL-per-robot "$n" "$s" "$rep" "$(run "$n" "$s" --coordinator SEQUENTIAL)" FloorShared "$fs"
    en=$(java -cp "runner/target/lib/*" bench/Engine.java "$n" "$s" | floor_rate)
    row Engine "$n" "$s" "$rep" "$en" Engine "$en"
    row one-jvm "$n" "$s" "$rep" "$(scripts/headless.sh --env "test-envs/bench-$n.xml" --steps "$s" --one-jvm 2>/dev/null \
      | tail -n 1 | rate || true)" Engine "$en"
    if [ -n "$peers" ]; then
      pd=$(mktemp -d)
      env SIZES="$n" "STEPS_$n=$s" SKIP="robosim floor" OUT_DIR="$pd" bash "$peer_script" 1 "$peers" >/dev/null 2>&1 || true
      for sys in argos stage; do
        pr=$(awk -F'\t' -v s=$sys '$2 == s && $7 == "ok" { print $5 }' "$pd/raw.tsv" | tail -n 1)
        row "$([ $sys = argos ] && echo ARGoS-3 || echo Stage-4.3)" "$n" "$s" "$rep" "$pr" Engine "$en"
      done
      rm -rf "$pd"
    fi
  done
done
echo "== medians of this sitting (ratio: to the floor of the same shape, same repetition)"
table=$(mktemp); trap 'rm -f "$table"' EXIT
java -cp "bench-jmh/target/lib/*:$jar" robosim.bench.SpeedPlot "$dir" | tee "$table"
echo "bench-speed: rows appended to $out"
if [ "$ROBOSIM_WRITE_DOCS" = 1 ]; then
  replace_marked speed-table "$table" docs/PERFORMANCE.md
  echo "bench-speed: docs/PERFORMANCE.md's speed table is now this sitting's (keep this output as docs/perf/speed-DATE.txt)"
fi

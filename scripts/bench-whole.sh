#!/usr/bin/env bash
# What a sweep pays per run: whole-process wall times of a short run, in one sitting, alternated:
#   scripts/bench-whole.sh [REPS] [--example NAME] [--peers PREFIX] [--classpath PATH[:PATH...]] [--help]
# REPS defaults to 5. Each repetition times, as whole processes (start-up, warm-up, the run and the end):
#   headless.sh --one-jvm --env test-envs/bench-10.xml --steps 5000     the whole simulation in one JVM (and
#                                                                        its summary's wall_s: the run alone)
#   headless.sh --one-jvm --env test-envs/bench-10.xml --steps 1        its start-up and end alone
#   headless.sh --robots-in-one-process ... --steps 5000                every part its own process
#   ARGoS 3, 10 robots, 5000 steps, with --peers PREFIX (one round of the peers' side-by-side.sh,
#                                                                        ../shared/peers/ or PEERS_SCRIPT)
# With --example NAME, ARGoS's example experiment NAME instead: examples/argos/NAME.xml (its seed) in RoboSim
# and, with --peers, NAME.argos run by ../shared/peers/run-argos-example.sh (5000 steps, the file's seed), and
# its shortest run (10 steps, one second of the examples' 10 ticks a second: ARGoS's start-up and end alone).
# Prints every time, then the medians and the one-JVM run's ratio to ARGoS (whole processes; for an example
# also the runs alone: RoboSim's wall_s against ARGoS's 5000 steps less its 10); writes no file.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
example=""
args=()
while [ $# -gt 0 ]; do
  case $1 in
    --example|--example=*)
      if [ "$1" = --example ]; then
        [ $# -ge 2 ] || robosim_fail "--example needs the name of a world in examples/argos/"; example=$2; shift
      else
        example=${1#--example=}
      fi
      shift
      [ -n "$example" ] || robosim_fail "--example needs the name of a world in examples/argos/, got an empty one" ;;
    *) args+=("$1"); shift ;;
  esac
done
robosim_peer_bench_args 5 "${args[@]}"
world=$ROBOSIM_HOME/test-envs/bench-10.xml
if [ -n "$example" ]; then
  world=$ROBOSIM_HOME/examples/argos/$example.xml
  [ -f "$world" ] || robosim_fail "--example $example: no examples/argos/$example.xml"
  runner=$(dirname "$BENCH_PEER_SCRIPT")/run-argos-example.sh
  [ -z "$BENCH_PEERS" ] || [ -x "$runner" ] || robosim_fail "no $runner (the peers' scripts)"
fi
[ "$ROBOSIM_WRITE_DOCS" = 1 ] && robosim_fail "writes no file: no --write-docs"
[ -n "$ROBOSIM_OUT_ARG" ] && robosim_fail "writes no file: no --out"
reps=$BENCH_REPS peers=$BENCH_PEERS peer_script=$BENCH_PEER_SCRIPT
robosim_build_if_stale
echo "java: $(java -version 2>&1 | head -n 1) ($ROBOSIM_JAVA_CHOICE)"
seconds() { # a command's whole wall time, s
  local t0=$EPOCHREALTIME
  "$@" >/dev/null 2>&1 || { echo "bench-whole: failed: $*" >&2; echo NaN; return 0; }
  awk -v a="$t0" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.3f", b - a }'
}
# the run's own wall time (its summary's wall_s), from its output
run_s() { sed -n 's/.* wall_s=\([0-9.]*\) .*/\1/p' "$1" | tail -n 1 | grep . || echo NaN; }
# RoboSim's runs in a folder of their own (an example's loop functions write their output where it runs)
work=$(mktemp -d)
log=$work/run.txt
trap 'rm -rf "$work"' EXIT
cd "$work"
scripts=$ROBOSIM_HOME/scripts
declare -a one run start procs argos argos_start
# ARGoS's wall time of example $1 for $2 steps (run-argos-example.sh's wall_s), or NaN with its last lines on stderr
argos_s() {
  local pd
  pd=$(mktemp -d)
  if "$runner" "$peers" "$1" "$2" "" "$pd/run" >"$pd/out.txt" 2>&1; then
    sed -n 's/.*wall_s=\([0-9.]*\).*/\1/p' "$pd/out.txt" | head -n 1 | grep . || echo NaN
  else
    echo "bench-whole: ARGoS's $1 failed: $(tail -n 3 "$pd/out.txt" | tr '\n' ' ')" >&2; echo NaN
  fi
  rm -rf "$pd"
}
for rep in $(seq "$reps"); do
  t0=$EPOCHREALTIME
  if "$scripts/headless.sh" --one-jvm --env "$world" --steps 5000 >"$log" 2>&1; then
    one+=("$(awk -v a="$t0" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.3f", b - a }')"); run+=("$(run_s "$log")")
  else
    echo "bench-whole: failed: headless.sh --one-jvm --env $world" >&2; one+=(NaN); run+=(NaN)
  fi
  start+=("$(seconds "$scripts/headless.sh" --one-jvm --env "$world" --steps 1)")
  procs+=("$(seconds "$scripts/headless.sh" --robots-in-one-process --env "$world" --steps 5000)")
  line="rep $rep: one-jvm 5000 steps ${one[-1]} s (run ${run[-1]} s), one-jvm 1 step ${start[-1]} s, processes 5000 steps ${procs[-1]} s"
  if [ -n "$peers" ] && [ -n "$example" ]; then
    argos+=("$(argos_s "$example" 5000)")
    argos_start+=("$(argos_s "$example" 10)")
    line="$line, ARGoS 5000 steps ${argos[-1]} s, ARGoS 10 steps ${argos_start[-1]} s"
  elif [ -n "$peers" ]; then
    pd=$(mktemp -d)
    SIZES=10 STEPS_10=5000 SKIP="stage robosim floor" OUT_DIR=$pd bash "$peer_script" 1 "$peers" >/dev/null 2>&1 || true
    argos+=("$(awk -F'\t' '$2 == "argos" && $7 == "ok" { print $6 }' "$pd/raw.tsv" | tail -n 1 | grep . || echo NaN)")
    rm -rf "$pd"
    line="$line, ARGoS 5000 steps ${argos[-1]:-NaN} s"
  fi
  echo "$line"
done
median() { printf '%s\n' "$@" | grep -v '^NaN$' | sort -g | awk '{a[NR]=$1} END {print (NR ? (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2) : "NaN")}'; }
m1=$(median "${one[@]}"); mr=$(median "${run[@]}"); ms=$(median "${start[@]}"); mp=$(median "${procs[@]}")
echo "median whole-process s (${world#"$ROBOSIM_HOME"/}): one-jvm-5000=$m1 (its run $mr) one-jvm-1=$ms processes-5000=$mp"
if [ -n "$peers" ]; then
  ma=$(median "${argos[@]}")
  # (a median that is NaN, every run of its kind failed, gives NaN ratios: awk's own NaN differs by awk)
  awk -v o="$m1" -v a="$ma" -v p="$mp" 'function r(x, y) { return x == "NaN" || y == "NaN" ? "NaN" : sprintf("%.2f", x / y) }
    BEGIN { printf "median ARGoS-5000=%s; one-jvm / ARGoS = %s, processes / ARGoS = %s\n", a, r(o, a), r(p, a) }'
  if [ -n "$example" ]; then
    # (ARGoS's run alone: its 5000 steps less its 10-step run, each rep's pair, so 4990 steps; RoboSim's: its
    # summary's wall_s, 5000 steps)
    alone=()
    for i in "${!argos[@]}"; do
      alone+=("$(awk -v a="${argos[$i]}" -v b="${argos_start[$i]}" 'BEGIN { if (a == "NaN" || b == "NaN") print "NaN"; else printf "%.3f", a - b }')")
    done
    mb=$(median "${argos_start[@]}") mra=$(median "${alone[@]}")
    awk -v r="$mr" -v a="$mra" -v b="$mb" 'BEGIN { q = r == "NaN" || a == "NaN" ? "NaN" : sprintf("%.2f", (5000 / r) / (4990 / a))
      printf "median ARGoS-10=%s; the runs alone: RoboSim %s s (5000 steps), ARGoS %s s (4990 steps); RoboSim / ARGoS, steps a second = %s\n", b, r, a, q }'
  fi
fi

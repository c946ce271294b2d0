#!/usr/bin/env bash
# Where a short one-JVM run's whole process goes, phase by phase:
#   scripts/bench-phases.sh [REPS] [--example NAME] [--steps N] [--classpath PATH[:PATH...]] [--help]
# REPS defaults to 5. Runs `headless.sh --one-jvm` on examples/argos/NAME.xml (default flocking) for N steps (default
# 5000) with the JVM's class-initialization log (-Xlog:class+init, with its uptime) and its compilers' times
# (-XX:+CITime) added to ROBOSIM_JAVA_OPTS: options of their own, so on JDK 19 and later a class-data archive of their
# own, which the three untimed runs before the timed ones train. Each process's wall time is split where the classes
# that open each phase are first initialized:
#   jvm       the JVM's start to RoboSim's main class (robosim.runner.HeadlessRunner)
#   command   the command line (picocli), to reading the world (robosim.environment.config.EnvironmentLoader)
#   world     the world file read and checked (to robosim.runner.ChildProcesses)
#   set-up    the Environment, its ports and its robots, to the first step (robosim.environment.core.SimulationCore)
#   run       the run itself: its summary's wall_s
#   rest      the script before the JVM, and the end after the last step (the wall time less the rest)
# and the CPU time the JIT compilers spent in the process (CITime's total). Prints each run and the medians; writes no
# file of its own (the runs write theirs in a temporary folder, removed at the end).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
example=flocking steps=5000 args=()
while [ $# -gt 0 ]; do
  case $1 in
    --example) [ $# -ge 2 ] || robosim_fail "--example needs the name of a world in examples/argos/"; example=$2; shift 2 ;;
    --example=*) example=${1#--example=}; shift ;;
    --steps) [ $# -ge 2 ] || robosim_fail "--steps needs a number of steps"; steps=$2; shift 2 ;;
    --steps=*) steps=${1#--steps=}; shift ;;
    *) args+=("$1"); shift ;;
  esac
done
robosim_bench_args 5 "" "${args[@]}" # (writes no file: no --write-docs, no --out)
world=$ROBOSIM_HOME/examples/argos/$example.xml
[ -f "$world" ] || robosim_fail "--example $example: no examples/argos/$example.xml"
case $steps in ''|*[!0-9]*|0) robosim_fail "--steps needs a whole number of steps > 0, got '$steps'" ;; esac
robosim_build_if_stale
echo "java: $(java -version 2>&1 | head -n 1) ($ROBOSIM_JAVA_CHOICE)"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" # (the log's path is relative, so the options, and with them the archive, are the same every time)
export ROBOSIM_JAVA_OPTS="${ROBOSIM_JAVA_OPTS:+$ROBOSIM_JAVA_OPTS }-Xlog:class+init=info:file=init.log:uptime -XX:+CITime"
run() { "$ROBOSIM_HOME/scripts/headless.sh" --one-jvm --env "$world" --steps "$steps" >out.txt 2>&1; }
for _ in 1 2 3; do
  run || { tail -n 5 out.txt >&2; robosim_fail "headless.sh failed on $world"; }
  sleep 2 # (a JDK 25 training run's archive is assembled in the background after it)
done
# the uptime, s, at which class $1 (slashes) was first initialized, from init.log; NaN when it was not
at() { sed -n "s|^\[\([0-9.]*\)s\].*Initializing '$1'.*|\1|p" init.log | head -n 1 | grep . || echo NaN; }
declare -a jvm command world_ setup runs rest whole jit
for rep in $(seq "$BENCH_REPS"); do
  t0=$EPOCHREALTIME
  run || { tail -n 5 out.txt >&2; robosim_fail "headless.sh failed on $world"; }
  w=$(awk -v a="$t0" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.3f", b - a }')
  wall=$(sed -n 's/.* wall_s=\([0-9.]*\) .*/\1/p' out.txt | tail -n 1 | grep . || echo NaN)
  c=$(sed -n 's/.*Total compilation time *: *\([0-9.]*\) s.*/\1/p' out.txt | head -n 1 | grep . || echo NaN)
  # (a marker or figure not found is NaN, and so is every phase computed from it: awk's own NaN differs by awk)
  line=$(awk -v m="$(at robosim/runner/HeadlessRunner)" -v l="$(at robosim/environment/config/EnvironmentLoader)" \
    -v p="$(at robosim/runner/ChildProcesses)" -v s="$(at robosim/environment/core/SimulationCore)" \
    -v r="$wall" -v w="$w" -v c="$c" '
    function v(x) { return x == "NaN" ? "NaN" : sprintf("%.3f", x) }
    function d(a, b) { return a == "NaN" || b == "NaN" ? "NaN" : sprintf("%.3f", b - a) }
    BEGIN { rest = s == "NaN" || r == "NaN" ? "NaN" : w - s - r
      print v(m), d(m, l), d(l, p), d(p, s), v(r), v(rest), v(w), v(c) }')
  read -r a b d e f g h i <<<"$line"
  jvm+=("$a"); command+=("$b"); world_+=("$d"); setup+=("$e"); runs+=("$f"); rest+=("$g"); whole+=("$h"); jit+=("$i")
  echo "run $rep: jvm $a s, command $b s, world $d s, set-up $e s, run $f s, rest $g s; whole $h s; JIT CPU $i s"
done
median() { printf '%s\n' "$@" | grep -v '^NaN$' | sort -g | awk '{a[NR]=$1} END {print (NR ? (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2) : "NaN")}'; }
echo "medians (examples/argos/$example.xml, $steps steps, one JVM): jvm $(median "${jvm[@]}") s, command $(median "${command[@]}") s," \
  "world $(median "${world_[@]}") s, set-up $(median "${setup[@]}") s, run $(median "${runs[@]}") s, rest $(median "${rest[@]}") s;" \
  "whole $(median "${whole[@]}") s; JIT CPU $(median "${jit[@]}") s"

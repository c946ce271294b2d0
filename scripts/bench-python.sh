#!/usr/bin/env bash
# What control code in Python costs: examples/python/wander-10.xml (ten Wander robots, robots as processes) run with
# Java's Wander and with Python's, alternated, in one sitting, and the robot link's floor:
#   scripts/bench-python.sh [REPS] [--steps N] [--one-jvm] [--help]
# REPS (default 5) pairs of headless runs of --steps N (default 3000); --one-jvm runs both in one JVM instead. The
# Python is $ROBOSIM_PYTHON, else python3, with this checkout's package (python/src) on its path and msgpack
# installed. Prints each run's steps/s (the run's own summary: start-up left out) and its controllers' calls, then
# the medians, Python / Java, and the round trips a step; then the floor, bench/LinkFloor.java: a Python controller's
# calls to a robot that answers at once, no simulation (its us/round_trip, once before the runs and once after).
# Writes no file.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
source "$(dirname "${BASH_SOURCE[0]}")/bench-lib.sh"
robosim_take_classpath "$@"
reps=5 steps=3000 layout=()
set -- "${ROBOSIM_ARGS[@]}"
while [ $# -gt 0 ]; do
  case $1 in
    -h|--help) robosim_usage; exit 0 ;;
    --steps) [ -n "${2:-}" ] || robosim_fail "--steps needs a number"; steps=$2; shift ;;
    --one-jvm) layout=(--one-jvm) ;;
    -?*) robosim_fail "unknown option $1 (see --help)" ;;
    *) reps=$1 ;;
  esac
  shift
done
robosim_count REPS "$reps"
robosim_count --steps "$steps"
python=${ROBOSIM_PYTHON:-python3}
export ROBOSIM_PYTHON=$python PYTHONPATH="$ROBOSIM_HOME/python/src${PYTHONPATH:+:$PYTHONPATH}"
"$python" -c 'import msgpack' 2>/dev/null || robosim_fail "$python cannot import msgpack (pip install ./python)"
robosim_build_if_stale
echo "java: $(java -version 2>&1 | head -n 1) ($ROBOSIM_JAVA_CHOICE); python: $("$python" --version 2>&1)"
floor() {
  (cd "$ROBOSIM_HOME" && java -Dmsgpack.universal-buffer=true -cp "$ROBOSIM_LIB/*" bench/LinkFloor.java "$python" 20000 \
    2>/dev/null)
}
echo "floor before: $(floor)"
run() { # $1: java or python -> "STEPS_PER_S CALLS"
  local out control=()
  [ "$1" = java ] && control=(--param control=robosim.examples.Wander)
  out=$(cd "$ROBOSIM_HOME" && scripts/headless.sh "${layout[@]}" --env examples/python/wander-10.xml --steps "$steps" \
    "${control[@]}" 2>&1) || { echo "NaN 0"; return 0; }
  echo "$(rate <<<"$out") $(sed -nE 's/.* its controller made ([0-9]+) calls over the robot link$/\1/p' <<<"$out" \
    | awk '{ s += $1 } END { print s + 0 }')"
}
declare -a js ps calls
for rep in $(seq "$reps"); do
  read -r j _ <<<"$(run java)"
  read -r p c <<<"$(run python)"
  js+=("$j") ps+=("$p") calls+=("$c")
  echo "rep $rep: java ${j} steps/s, python ${p} steps/s, python's calls ${c}"
done
median() { printf '%s\n' "$@" | grep -v '^NaN$' | sort -g | awk '{a[NR]=$1} END {print (NR ? (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2) : "NaN")}'; }
mj=$(median "${js[@]}") mp=$(median "${ps[@]}") mc=$(median "${calls[@]}")
awk -v j="$mj" -v p="$mp" -v c="$mc" -v s="$steps" 'BEGIN { printf "median steps/s: java=%s python=%s; python / java = %.2f; round trips a step (10 robots) = %.2f, a robot-step = %.3f\n", j, p, p / j, c / s, c / s / 10 }'
echo "floor after: $(floor)"

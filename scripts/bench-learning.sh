#!/usr/bin/env bash
# What a learner sees, against the limit: K worlds of test-envs/bench-10.xml (ten Scouts) stepped from Python over the
# learning link (bench/learning_bench.py: robosim.rl's VectorEnv, random actions, a built-in metric's reward), and
# the same worlds stepped in the JVM with the actions made inline (bench/LearningEngine.java: the same BatchWorlds
# and threads, no link), alternated, in one sitting, and the link's floor (bench/LearningLinkFloor.java: the same
# frames both ways, answered at once, nothing simulated):
#   scripts/bench-learning.sh [REPS] [--worlds "1 8 32"] [--robot-steps N] [--env FILE.xml] [--help]
# REPS (default 3) pairs for each K; each run steps N robot-steps (default 400000) after 160000 of warm-up (the JIT
# compiler, on the cores the worlds are stepped on, is done by then). The
# Python is $ROBOSIM_PYTHON, else python3, with robosim[rl] installed (pip install "./python[rl]"). Prints each
# run's robot-steps/s, then a row for each K: the medians, Python / JVM, the floor's microseconds a step and
# Python / (JVM and floor): Python's rate against the rate of a step of the JVM's plus an exchange of the floor's.
# Writes no file.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_take_classpath "$@"
reps=3 worlds="1 8 32" robot_steps=400000 env=test-envs/bench-10.xml
set -- "${ROBOSIM_ARGS[@]}"
while [ $# -gt 0 ]; do
  case $1 in
    -h|--help) robosim_usage; exit 0 ;;
    --worlds) [ -n "${2:-}" ] || robosim_fail "--worlds needs a list, e.g. \"1 8 32\""; worlds=$2; shift ;;
    --robot-steps) [ -n "${2:-}" ] || robosim_fail "--robot-steps needs a number"; robot_steps=$2; shift ;;
    --env) [ -n "${2:-}" ] || robosim_fail "--env needs a file"; env=$2; shift ;;
    -?*) robosim_fail "unknown option $1 (see --help)" ;;
    *) reps=$1 ;;
  esac
  shift
done
robosim_count REPS "$reps"
robosim_count --robot-steps "$robot_steps"
for k in $worlds; do robosim_count "--worlds (each)" "$k"; done
python=${ROBOSIM_PYTHON:-python3}
"$python" -c 'import robosim.rl' 2>/dev/null || robosim_fail "$python cannot import robosim.rl (pip install \"./python[rl]\")"
robosim_build_if_stale
env=$(robosim_abs "$env")
robots=$(grep -c "<robot " "$env")
sonars=8; grep -q 'type="Scout"' "$env" && sonars=16   # the most sonars of a robot: a Scout's 16, else an ArRobot's 8
echo "java: $(java -version 2>&1 | head -n 1) ($ROBOSIM_JAVA_CHOICE); python: $("$python" --version 2>&1); $(nproc) cores"
value() { sed -nE 's/.* robot-steps\/s=([0-9.]+).*/\1/p' | tail -n 1; }
median() { printf '%s\n' "$@" | grep -v '^$' | sort -g | awk '{a[NR]=$1} END {print (NR ? (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2) : "NaN")}'; }
rows=()
for k in $worlds; do
  steps=$(( robot_steps / (k * robots) )); [ "$steps" -ge 1 ] || steps=1
  warm=$(( 160000 / (k * robots) ))
  js=() ps=() fs=()
  for rep in $(seq "$reps"); do
    j=$(cd "$ROBOSIM_HOME" && java -cp "$(robosim_classpath)" bench/LearningEngine.java "$env" "$k" "$steps" "$warm" 2>&1 | value)
    p=$(cd "$ROBOSIM_HOME" && "$python" bench/learning_bench.py "$env" "$k" "$steps" "$warm" 2>&1 | value)
    f=$(cd "$ROBOSIM_HOME" && java -Dmsgpack.universal-buffer=true -cp "$(robosim_classpath)" bench/LearningLinkFloor.java \
      "$python" "$k" "$robots" "$sonars" 5000 2>&1 | sed -nE 's/.* us\/step=([0-9.]+).*/\1/p')
    js+=("${j:-}") ps+=("${p:-}") fs+=("${f:-}")
    echo "K=$k rep $rep: jvm ${j:-failed} robot-steps/s, python ${p:-failed} robot-steps/s, link floor ${f:-failed} us/step"
  done
  rows+=("$(awk -v k="$k" -v n="$robots" -v j="$(median "${js[@]}")" -v p="$(median "${ps[@]}")" \
    -v f="$(median "${fs[@]}")" 'BEGIN { limit = 1e6 / (k * n * 1e6 / j + f) * k * n;
      printf "| %d x %d | %.0f | %.0f | %.2f | %.0f | %.2f |", k, n, j, p, p / j, f, p / limit }')")
done
echo "| worlds x robots | JVM, actions inline (robot-steps/s) | Python over the link (robot-steps/s) | Python / JVM |" \
  "link floor (us/step) | Python / (JVM + floor) |"
echo "|---|---|---|---|---|---|"
printf '%s\n' "${rows[@]}"

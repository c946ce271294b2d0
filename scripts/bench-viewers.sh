#!/usr/bin/env bash
# What viewers cost the robots: the paper benchmark (10 robots) with no viewers against the same run
# with 2 live viewers (asking 30 updates/s, like a Viewer2D window) and 1 that never reads, and with
# 2 live viewers that take every step, alternated, in one sitting:
#   scripts/bench-viewers.sh [REPS] [STEPS] [--classpath PATH[:PATH...]] [--help]
# REPS defaults to 3, STEPS to 5000. Prints every run and the medians; writes no file.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_script_args "" "$@"
[ ${#ROBOSIM_ARGS[@]} -le 2 ] || robosim_fail "takes at most REPS and STEPS, got ${ROBOSIM_ARGS[*]} (see --help)"
[ ${#ROBOSIM_PASS[@]} = 0 ] || robosim_fail "takes nothing after -- (see --help)"
reps=${ROBOSIM_ARGS[0]:-3}; steps=${ROBOSIM_ARGS[1]:-5000}
robosim_count REPS "$reps"; robosim_count STEPS "$steps"
cd "$ROBOSIM_HOME"
robosim_build_if_stale
rate() { grep -oE '(^| )steps_per_s=[0-9.]+' | head -n 1 | sed -E 's/.*=//'; }
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
declare -a none three every
for _ in $(seq "$reps"); do
  l=$(scripts/headless.sh --env test-envs/paper-benchmark.xml --steps "$steps" 2>/dev/null | tail -n 1)
  echo "no viewers        $l"; none+=("$(echo "$l" | rate)")
  l=$(scripts/headless.sh --env test-envs/paper-benchmark.xml --steps "$steps" --live-viewers 2 --frozen-viewers 1 2>/dev/null | tail -n 1)
  echo "2 live + 1 frozen $l"; three+=("$(echo "$l" | rate)")
  l=$(scripts/headless.sh --env test-envs/paper-benchmark.xml --steps "$steps" --live-viewers 2 --live-viewer-fps 0 --frozen-viewers 1 2>/dev/null | tail -n 1)
  echo "2 every-step + 1 frozen $l"; every+=("$(echo "$l" | rate)")
done
a=$(median "${none[@]}"); b=$(median "${three[@]}"); c=$(median "${every[@]}")
awk -v a="$a" -v b="$b" -v c="$c" 'BEGIN { printf "median steps/s: no viewers=%s; 2 live at 30/s + 1 frozen=%s (ratio %.2f); 2 every-step + 1 frozen=%s (ratio %.2f)\n", a, b, b/a, c, c/a }'

#!/usr/bin/env bash
# The original report's benchmark against the floor, in one sitting, repeated and alternated:
#   scripts/bench-paper.sh [REPS] [STEPS] [--classpath PATH[:PATH...]] [-- headless.sh options...] [--help]
# REPS defaults to 3, STEPS to 5000. Runs, REPS times each in turn: bench/Floor.java (clients
# as threads), bench/FloorProcesses (clients as processes), headless.sh on test-envs/paper-benchmark.xml
# (robots as processes) and the same with --robots-in-one-process. Prints every line, then the
# medians and the ratios to the floor; writes no file (bench/FloorProcesses compiles to bench/classes).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_paper_bench_args "$@"
reps=$BENCH_REPS; steps=$BENCH_STEPS
set -- "${ROBOSIM_PASS[@]}"
floor=bench/Floor.java
declare -a f fp hp ho
rate() { grep -oE '(^| )steps(_per_s|/s)=[0-9.]+' | head -n 1 | sed -E 's/.*=//'; }
for _ in $(seq "$reps"); do
  l=$(java "$floor" 10 "$steps" obj); echo "floor            $l"; f+=("$(echo "$l" | rate)")
  l=$(java -cp bench/classes FloorProcesses 10 "$steps" obj); echo "floor-processes  $l"; fp+=("$(echo "$l" | rate)")
  l=$(scripts/headless.sh --env test-envs/paper-benchmark.xml --steps "$steps" "$@" 2>/dev/null | tail -n 1); echo "headless         $l"; hp+=("$(echo "$l" | rate)")
  l=$(scripts/headless.sh --env test-envs/paper-benchmark.xml --steps "$steps" --robots-in-one-process "$@" 2>/dev/null | tail -n 1); echo "headless-1proc   $l"; ho+=("$(echo "$l" | rate)")
done
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
mf=$(median "${f[@]}"); mfp=$(median "${fp[@]}"); mh=$(median "${hp[@]}"); mo=$(median "${ho[@]}")
echo "median steps/s: floor=$mf floor-processes=$mfp headless=$mh headless-1proc=$mo"
awk -v f="$mf" -v fp="$mfp" -v h="$mh" -v o="$mo" 'BEGIN { printf "ratio to floor: headless=%.2f headless-1proc=%.2f floor-processes=%.2f; headless to floor-processes=%.2f\n", h/f, o/f, fp/f, h/fp }'

#!/usr/bin/env bash
# What a sweep costs beyond its runs, in one sitting (docs/PERFORMANCE.md, "Sweeps"):
#   scripts/bench-sweep.sh [REPS] [--quick] [--slurm] [--peers PREFIX] [--out DIR | --write-docs] [--help]
# REPS (default 1) rounds of, alternated:
#   sweep   scripts/sweep.sh of 200 runs: test-envs/bench-10.xml (10 Wander Scouts), 2000 steps, 20 seeds x 10
#           speeds, one JVM a run, a pool as large as the cores; its floor is its own rows: the sum of their
#           wall times / runs at once (what the pool would take with no cost of its own)
#   loop    the same 200 runs by hand: xargs -P CORES of headless.sh --one-jvm (no recording, no metrics)
#   cpu     one of these runs alone, its CPU time (user + system; the median of 3, alternated, after one of each
#           unmeasured), with the sweep's JVM options for its runs (C1 alone, serial GC) and with the JVM's defaults
# --slurm   also the sweep through the one-node Slurm (scripts/slurm-cluster.sh start first), --max-parallel
#           CORES: the overhead per task = (wall x CORES - the rows' wall times) / runs (submission to row
#           written, less the run)
# --peers   also ARGoS 3 on the same workload (10 robots, 2000 steps; one round of the peers' side-by-side.sh,
#           ../shared/peers/ or PEERS_SCRIPT), one run's whole-process time x 200 / CORES: the least a
#           sweep of ARGoS runs could take
# --quick   20 runs (2 seeds x 10 speeds) instead of 200
# Prints each round and the ratios; with --out DIR or --write-docs also writes sweep-DATE.txt there.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
slurm=0 args=()
for a in "$@"; do if [ "$a" = --slurm ]; then slurm=1; else args+=("$a"); fi; done
robosim_peer_bench_args 1 "${args[@]}"
reps=$BENCH_REPS peers=$BENCH_PEERS peer_script=$BENCH_PEER_SCRIPT
robosim_build_if_stale
cores=$(nproc)
seeds=20
[ "$BENCH_QUICK" = 1 ] && seeds=2
runs=$((seeds * 10))
work=$(mktemp -d "${TMPDIR:-/tmp}/robosim-bench-sweep.XXXXXX")
trap 'rm -rf "$work"' EXIT
speeds="100 200 300 400 500 600 700 800 900 1000"
cat > "$work/spec.xml" <<XML
<sweep world="$ROBOSIM_HOME/test-envs/bench-10.xml" steps="2000">
  <seeds from="1" to="$seeds"/>
  <param name="speed" values="$speeds"/>
</sweep>
XML
report=()
say() { echo "$1"; report+=("$1"); }
say "bench-sweep: $(date -u +%Y-%m-%dT%H:%MZ), java: $(java -version 2>&1 | head -n 1) ($ROBOSIM_JAVA_CHOICE), $cores cores, $runs runs"
seconds() { # a command's whole wall time, s
  local t0=$EPOCHREALTIME
  "$@" >/dev/null 2>&1 || { echo "bench-sweep: failed: $*" >&2; echo NaN; return 0; }
  awk -v a="$t0" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.2f", b - a }'
}
cpu() { # a command's CPU time (user + system, its children's), s
  local TIMEFORMAT='%3U %3S' t
  t=$( { time "$@" >/dev/null 2>&1; } 2>&1 ) || { echo NaN; return 0; }
  awk -v t="$t" 'BEGIN { split(t, a, " "); printf "%.2f", a[1] + a[2] }'
}
rowsum() { awk -F, 'NR > 1 { s += $NF } END { printf "%.2f", s }' "$1/runs.csv"; }
loop() {
  for s in $(seq 1 "$seeds"); do for v in $speeds; do echo "$s $v"; done; done \
    | xargs -P "$cores" -L 1 sh -c 'exec "$0" --one-jvm --env "$1" --steps 2000 --seed "$2" --param speed="$3"' \
      "$ROBOSIM_HOME/scripts/headless.sh" "$ROBOSIM_HOME/test-envs/bench-10.xml"
}
for rep in $(seq "$reps"); do
  rm -rf "$work/local"
  sweep=$(seconds scripts/sweep.sh "$work/spec.xml" --out "$work/local" --jobs "$cores")
  sum=$(rowsum "$work/local")
  by_hand=$(seconds loop)
  one=(scripts/headless.sh --one-jvm --env test-envs/bench-10.xml --steps 2000)
  fast="-XX:TieredStopAtLevel=1 -XX:+UseSerialGC"
  # each first once unmeasured: its class-data archive (one per JVM options) is made at the end of a first run
  ROBOSIM_JAVA_OPTS=$fast cpu "${one[@]}" >/dev/null
  cpu "${one[@]}" >/dev/null
  shorts=() defaults=()
  for i in 1 2 3; do
    shorts+=("$(ROBOSIM_JAVA_OPTS=$fast cpu "${one[@]}")")
    defaults+=("$(cpu "${one[@]}")")
  done
  short=$(printf '%s\n' "${shorts[@]}" | sort -g | sed -n 2p)
  defaults=$(printf '%s\n' "${defaults[@]}" | sort -g | sed -n 2p)
  line=$(awk -v w="$sweep" -v s="$sum" -v c="$cores" -v l="$by_hand" -v a="$short" -v d="$defaults" 'BEGIN { printf "sweep %.2f s; its rows %.2f s / %d at once = %.2f s (sweep / that = %.2f); loop %.2f s (sweep / loop = %.2f); one run'"'"'s CPU %.2f s with the sweep'"'"'s JVM options, %.2f s with the defaults (%.2f)", w, s, c, s / c, w / (s / c), l, w / l, a, d, a / d }')
  if [ "$slurm" = 1 ]; then
    rm -rf "$work/slurm"
    through=$(seconds scripts/sweep.sh "$work/spec.xml" --out "$work/slurm" --slurm --wait --max-parallel "$cores")
    ssum=$(rowsum "$work/slurm")
    line="$line; slurm $(awk -v w="$through" -v s="$ssum" -v c="$cores" -v n="$runs" 'BEGIN { printf "%.2f s, overhead per task %.2f s (its rows %.2f s)", w, (w * c - s) / n, s }')"
  fi
  if [ -n "$peers" ]; then
    pd=$(mktemp -d)
    SIZES=10 STEPS_10=2000 SKIP="stage robosim floor" OUT_DIR=$pd bash "$peer_script" 1 "$peers" >/dev/null 2>&1 || true
    argos=$(awk -F'\t' '$2 == "argos" && $7 == "ok" { print $6 }' "$pd/raw.tsv" | tail -n 1)
    rm -rf "$pd"
    line="$line; ARGoS one run ${argos:-NaN} s, x $runs / $cores = $(awk -v a="${argos:-0}" -v n="$runs" -v c="$cores" -v w="$sweep" 'BEGIN { printf "%.2f s (sweep / that = %.2f)", a * n / c, (a > 0 ? w / (a * n / c) : 0) }')"
  fi
  say "round $rep: $line"
done
if [ "$ROBOSIM_WRITE_DOCS" = 1 ] || [ -n "$ROBOSIM_OUT_ARG" ]; then
  out=$(robosim_out_dir)
  printf '%s\n' "${report[@]}" > "$out/sweep-$(date -u +%Y-%m-%d).txt"
fi

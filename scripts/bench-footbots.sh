#!/usr/bin/env bash
# The foot-bot workload against ARGoS, alternated in one sitting:
#   scripts/bench-footbots.sh [REPS] [--peers PREFIX] [--write-docs | --out DIR] [--classpath PATH[:PATH...]] [--help]
# REPS defaults to 3. Each repetition runs, in turn, 3000 steps of bench/footbots-100.xml (100 foot-bots running
# Diffusion, ARGoS's footbot_diffusion, with proximity, light, motor-ground and range-and-bearing on):
#   headless.sh --one-jvm                      the whole simulation in one JVM (its summary's steps_per_s, and the
#                                              whole process's wall time)
#   bench/FootBotEngine.java                   its floor: the core and the engine alone, decisions inline
#   ARGoS 3 on bench/footbots-100.argos        with --peers PREFIX (built by ../shared/peers/build-peers.sh, with
#                                              ARGoS's examples): the same world, its own footbot_diffusion
# then, once, the memory: bench/footbots-1000.xml (1,000 foot-bots, every device on), 300 steps in one JVM, the
# largest process's maximum resident set (/usr/bin/time). Prints every figure, then the medians and ratios, and
# writes them to footbots.txt (docs/perf/ with --write-docs, which docs/PERFORMANCE.md quotes).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_peer_bench_args 3 "$@"
reps=$BENCH_REPS peers=$BENCH_PEERS
out="$(robosim_out_dir)/footbots.txt"
cd "$ROBOSIM_HOME"
robosim_build_if_stale
if [ -n "$peers" ] && [ ! -f "$peers/build/argos3-examples/controllers/footbot_diffusion/libfootbot_diffusion.so" ]; then
  robosim_fail "--peers $peers: ARGoS's examples are not built there (build-peers.sh with argos3-examples: PEERS.md)"
fi
steps=3000
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
field() { sed -n "s/.* $1=\([0-9.]*\).*/\1/p" | tail -n 1; }
median() { printf '%s\n' "$@" | grep -v '^NaN$' | sort -g | awk '{a[NR]=$1} END {print (NR ? (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2) : "NaN")}'; }
{
  echo "commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown), $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores"
  echo "java: $(java -version 2>&1 | head -n 1) ($ROBOSIM_JAVA_CHOICE)"
} | tee "$out"
declare -a one whole floor argos
for rep in $(seq "$reps"); do
  t0=$EPOCHREALTIME
  scripts/headless.sh --one-jvm --env bench/footbots-100.xml --steps "$steps" >"$tmp/one.txt" 2>&1
  whole+=("$(awk -v a="$t0" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.3f", b - a }')")
  one+=("$(field steps_per_s <"$tmp/one.txt")")
  java -cp "$(robosim_classpath)" bench/FootBotEngine.java bench/footbots-100.xml "$steps" >"$tmp/floor.txt" 2>&1
  floor+=("$(sed -n 's/.* steps\/s=\([0-9.]*\).*/\1/p' "$tmp/floor.txt")")
  line="rep $rep: one-jvm ${one[-1]} steps/s (whole process ${whole[-1]} s), FootBotEngine ${floor[-1]} steps/s"
  if [ -n "$peers" ]; then
    run="$tmp/argos"; mkdir -p "$run"
    ln -sfn "$peers/build/argos3-examples" "$run/build"
    cp bench/footbots-floor.png "$run/"
    sed "s/length=\"[0-9]*\"/length=\"$((steps / 10))\"/" bench/footbots-100.argos >"$run/footbots-100.argos"
    (cd "$run" && LD_LIBRARY_PATH="$peers/argos3/lib/argos3" /usr/bin/time -f "wall_s=%e" -o time.txt \
      "$peers/argos3/bin/argos3" -z -c footbots-100.argos >argos.log 2>&1) || { tail -3 "$run/argos.log" >&2; robosim_fail "argos3 failed"; }
    argos+=("$(awk -v s="$steps" -F= '{ printf "%.1f", s / $2 }' "$run/time.txt")")
    line="$line, ARGoS ${argos[-1]} ticks/s (whole process $(cut -d= -f2 "$run/time.txt") s)"
  fi
  echo "$line" | tee -a "$out"
done
mo=$(median "${one[@]}"); mf=$(median "${floor[@]}"); mw=$(median "${whole[@]}")
awk -v o="$mo" -v f="$mf" -v w="$mw" 'BEGIN { printf "median: one-jvm %s steps/s (%.2f of FootBotEngine %s), whole process %s s\n", o, o/f, f, w }' | tee -a "$out"
if [ -n "$peers" ]; then
  ma=$(median "${argos[@]}")
  awk -v o="$mo" -v a="$ma" -v f="$mf" 'BEGIN { printf "median ARGoS %s ticks/s: one-jvm / ARGoS = %.2f, FootBotEngine / ARGoS = %.2f\n", a, o/a, f/a }' | tee -a "$out"
fi
/usr/bin/time -f "peak_kib=%M" -o "$tmp/mem.txt" scripts/headless.sh --one-jvm --env bench/footbots-1000.xml --steps 300 \
  >"$tmp/mem-run.txt" 2>&1
echo "memory: 1000 foot-bots, every device, 300 steps, one JVM: $(field steps_per_s <"$tmp/mem-run.txt") steps/s," \
  "peak resident $(( $(cut -d= -f2 "$tmp/mem.txt") / 1024 )) MiB" | tee -a "$out"

#!/usr/bin/env bash
# ARGoS's own example experiments side by side with RoboSim's ports of them (examples/argos/), in one sitting:
#   scripts/bench-argos-examples.sh [SEEDS] --peers PREFIX [--write-docs | --out DIR] [--quick] [--help]
# SEEDS defaults to 10 (--quick: 2). For each seed 1..SEEDS, in turn, RoboSim then ARGoS (PREFIX built by
# ../shared/peers/build-peers.sh with ARGoS's examples; ARGoS's runs by ../shared/peers/run-argos-example.sh or, for
# the scaled world, as it runs one), each 5000 steps of 100 ms, visualization off:
#   foraging       examples/argos/foraging.xml (RoboSim, one JVM) and foraging.argos: the items collected (the
#                  loop functions' foraging.txt, 4th column, last line) and the steps per second
#   diffusion_10   examples/argos/diffusion_10.xml and diffusion_10.argos: the steps per second
#   diffusion_100  bench/diffusion_100.xml and bench/diffusion_100.argos (ten times the robots and obstacles, an
#                  arena sqrt(10) times as wide): the steps per second
#   flocking       examples/argos/flocking.xml and flocking.argos: the steps per second, and the steps until the
#                  order parameter (the length of the robots' mean heading) passes 0.9, each from a second run,
#                  not timed, that writes it: RoboSim's with --pose-log (a viewer of every step, which makes a
#                  small world's run take half as long again), ARGoS's with loop functions of ours added that write
#                  it each step (bench/argos/flocking_order_loop_functions.cpp, built here against PREFIX's ARGoS)
#   flocking_100   bench/flocking_100.xml and bench/flocking_100.argos (ten times the robots, placed in a square
#                  sqrt(10) times as wide): the steps per second
# The floor of a one-JVM run's thread shape, for the diffusion worlds (whose controller it can run inline):
# bench/FootBotEngine.java, the core and the engine alone stepping the same world, Diffusion's decisions inline.
# RoboSim's steps per second are its summary's (the run, from step 0 to the end) and its whole process's (JVM start
# to exit, as ARGoS's are: 5000 over its wall time). Then a sweep of foraging over 40 seeds: scripts/sweep.sh (warm
# JVMs, as many workers as cores) against ARGoS's 40 runs with xargs -P (as many as cores), their wall times.
# Prints every figure, then the means with 95% intervals, the medians and the ratios, and writes them to
# argos-examples.txt (docs/perf/ with --write-docs, which docs/PERFORMANCE.md quotes).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_peer_bench_args 10 "$@"
[ "$BENCH_QUICK" = 1 ] && BENCH_REPS=2
seeds=$BENCH_REPS peers=$BENCH_PEERS
[ -n "$peers" ] || robosim_fail "needs --peers PREFIX, where ../shared/peers/build-peers.sh built ARGoS and its examples"
[ -f "$peers/build/argos3-examples/loop_functions/foraging_loop_functions/libforaging_loop_functions.so" ] \
  || robosim_fail "--peers $peers: ARGoS's examples are not built there (build-peers.sh with argos3-examples: PEERS.md)"
runner=$ROBOSIM_HOME/../shared/peers/run-argos-example.sh
[ -x "$runner" ] || robosim_fail "no $runner (the peers' scripts)"
out="$(robosim_out_dir)/argos-examples.txt"
cd "$ROBOSIM_HOME"
robosim_build_if_stale
steps=5000
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
field() { sed -n "s/\(.* \)\{0,1\}$1=\([0-9.]*\).*/\2/p" | tail -n 1; }
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR ? (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2) : "NaN")}'; }
# mean and 95% interval (Student's t) of the numbers given
interval() { printf '%s\n' "$@" | awk '{s+=$1; q+=$1*$1; n++} END {m=s/n; sd=(n>1)?sqrt((q-n*m*m)/(n-1)):0;
  split("12.706 4.303 3.182 2.776 2.571 2.447 2.365 2.306 2.262 2.228 2.201 2.179 2.160 2.145 2.131 2.120 2.110 2.101 2.093", t, " ");
  tt=(n-1<=19)?t[n-1]:1.96; h=(n>1)?tt*sd/sqrt(n):0; printf "%.1f (%.1f to %.1f)", m, m-h, m+h}'; }
# the first step whose robots' mean heading is longer than 0.9, from a pose log (step,robot,x_m,y_m,heading_deg,...)
order() { awk -F, 'NR > 1 { c[$1] += cos($5 * 3.14159265358979 / 180); s[$1] += sin($5 * 3.14159265358979 / 180); n[$1]++ }
  END { first = -1; for (k in n) if (sqrt(c[k]^2 + s[k]^2) / n[k] > 0.9 && (first < 0 || k + 0 < first)) first = k + 0; print first }' "$1"; }
elapsed() { awk -v a="$1" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.3f", b - a }'; }
{
  echo "commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown), $(date -u +%Y-%m-%dT%H:%MZ), $(nproc) cores"
  echo "java: $(java -version 2>&1 | head -n 1) ($ROBOSIM_JAVA_CHOICE); ARGoS: $peers/argos3/bin/argos3"
  echo "$seeds seeds, $steps steps of 100 ms each run"
} | tee "$out"
declare -A one whole argos floor
declare -a items_rs items_ar order_rs order_ar
# ARGoS's flocking.argos with our loop functions that write its order parameter each step (flocking_order.txt)
g++ -std=c++17 -O2 -shared -fPIC -I"$peers/argos3/include" $(pkg-config --cflags lua5.3 2>/dev/null || echo -I/usr/include/lua5.3) \
  bench/argos/flocking_order_loop_functions.cpp -L"$peers/argos3/lib/argos3" -largos3core_simulator \
  -largos3plugin_simulator_footbot -largos3plugin_simulator_entities -o "$tmp/libflocking_order.so" \
  || robosim_fail "cannot build bench/argos/flocking_order_loop_functions.cpp against $peers (g++, ARGoS's headers)"
flocking_argos=$peers/argos3-examples/experiments/flocking.argos
[ -f "$flocking_argos" ] || flocking_argos=$peers/src/argos3-examples/experiments/flocking.argos
python3 - "$flocking_argos" "$tmp/flocking_order.argos" "$tmp/libflocking_order.so" <<'PY'
import re, sys
s = open(sys.argv[1]).read()
s = re.sub(r'<visualization>.*?</visualization>', '<visualization/>', s, flags=re.S)
s = s.replace('<arena ', '<loop_functions library="' + sys.argv[3] + '" label="flocking_order"/>\n  <arena ', 1)
open(sys.argv[2], 'w').write(s)
PY
# the first step whose order parameter is over 0.9, from flocking_order.txt (step, order)
order_argos() { awk -F'\t' '$2 > 0.9 { print $1; found = 1; exit } END { if (!found) print -1 }' "$1"; }
# robosim NAME WORLD SEED: a run in one JVM in a folder of its own (the loop functions write there)
robosim() {
  local dir="$tmp/rs-$1-$3" t0=$EPOCHREALTIME
  mkdir -p "$dir"
  (cd "$dir" && "$ROBOSIM_HOME/scripts/headless.sh" --one-jvm --env "$ROBOSIM_HOME/$2" --steps "$steps" --seed "$3" \
    "${@:4}" >run.txt 2>&1) || { tail -5 "$dir/run.txt" >&2; robosim_fail "RoboSim's $1 (seed $3) failed"; }
  whole[$1]+="$(awk -v s="$steps" -v w="$(elapsed "$t0")" 'BEGIN { printf "%.1f", s / w }') "
  one[$1]+="$(field steps_per_s <"$dir/run.txt") "
}
# engine WORLD: the floor's steps per second on WORLD (the file's seed)
engine() {
  java -cp "$(robosim_classpath)" bench/FootBotEngine.java "$1" "$steps" 2>&1 | sed -n 's/.* steps\/s=\([0-9.]*\).*/\1/p'
}
# argos NAME SEED [ARGOS-FILE]: ARGoS's example NAME (or the file given, run as run-argos-example.sh runs one)
argos() {
  local dir="$tmp/ar-$1-$2"
  if [ $# -lt 3 ]; then
    "$runner" "$peers" "$1" "$steps" "$2" "$dir" >"$tmp/ar.txt" 2>&1 || { cat "$tmp/ar.txt" >&2; robosim_fail "ARGoS's $1 failed"; }
  else
    mkdir -p "$dir"; ln -sfn "$peers/build/argos3-examples" "$dir/build"
    sed -e "s/length=\"[0-9]*\"/length=\"$((steps / 10))\"/" -e "s/random_seed=\"[0-9]*\"/random_seed=\"$2\"/" "$3" >"$dir/$1.argos"
    (cd "$dir" && LD_LIBRARY_PATH="$peers/argos3/lib/argos3" /usr/bin/time -f "wall_s=%e peak_kib=%M" -o time.txt \
      "$peers/argos3/bin/argos3" -z -c "$1.argos" >argos.log 2>&1) || { tail -3 "$dir/argos.log" >&2; robosim_fail "argos3 failed on $1"; }
    cat "$dir/time.txt" >"$tmp/ar.txt"
  fi
  argos[$1]+="$(awk -v s="$steps" -v w="$(field wall_s <"$tmp/ar.txt")" 'BEGIN { printf "%.1f", s / w }') "
}
for seed in $(seq "$seeds"); do
  robosim foraging examples/argos/foraging.xml "$seed"
  items_rs+=("$(tail -n 1 "$tmp/rs-foraging-$seed/foraging.txt" | cut -f4)")
  argos foraging "$seed"
  items_ar+=("$(tail -n 1 "$tmp/ar-foraging-$seed/foraging.txt" | cut -f4)")
  robosim diffusion_10 examples/argos/diffusion_10.xml "$seed"
  floor[diffusion_10]+="$(engine examples/argos/diffusion_10.xml) "
  argos diffusion_10 "$seed"
  robosim diffusion_100 bench/diffusion_100.xml "$seed"
  floor[diffusion_100]+="$(engine bench/diffusion_100.xml) "
  argos diffusion_100 "$seed" bench/diffusion_100.argos
  robosim flocking examples/argos/flocking.xml "$seed"
  robosim flocking_order examples/argos/flocking.xml "$seed" --pose-log poses.csv
  order_rs+=("$(order "$tmp/rs-flocking_order-$seed/poses.csv")")
  argos flocking "$seed"
  argos flocking_order "$seed" "$tmp/flocking_order.argos"
  order_ar+=("$(order_argos "$tmp/ar-flocking_order-$seed/flocking_order.txt")")
  robosim flocking_100 bench/flocking_100.xml "$seed"
  argos flocking_100 "$seed" bench/flocking_100.argos
  echo "seed $seed: foraging items RoboSim ${items_rs[-1]} ARGoS ${items_ar[-1]};" \
    "steps/s (RoboSim run, whole process; ARGoS whole process):" \
    "foraging $(echo ${one[foraging]} | awk '{print $NF}'), $(echo ${whole[foraging]} | awk '{print $NF}'); $(echo ${argos[foraging]} | awk '{print $NF}')" \
    "diffusion_10 $(echo ${one[diffusion_10]} | awk '{print $NF}'), $(echo ${whole[diffusion_10]} | awk '{print $NF}'); $(echo ${argos[diffusion_10]} | awk '{print $NF}')" \
    "diffusion_100 $(echo ${one[diffusion_100]} | awk '{print $NF}'), $(echo ${whole[diffusion_100]} | awk '{print $NF}'); $(echo ${argos[diffusion_100]} | awk '{print $NF}')" \
    "flocking $(echo ${one[flocking]} | awk '{print $NF}'), $(echo ${whole[flocking]} | awk '{print $NF}'); $(echo ${argos[flocking]} | awk '{print $NF}')" \
    "flocking_100 $(echo ${one[flocking_100]} | awk '{print $NF}'), $(echo ${whole[flocking_100]} | awk '{print $NF}'); $(echo ${argos[flocking_100]} | awk '{print $NF}');" \
    "flocking's order parameter over 0.9 from step RoboSim ${order_rs[-1]} ARGoS ${order_ar[-1]}" \
    | tee -a "$out"
done
echo "foraging items collected in $steps steps, mean (95% interval) over $seeds seeds: RoboSim $(interval "${items_rs[@]}")," \
  "ARGoS $(interval "${items_ar[@]}")" | tee -a "$out"
echo "flocking: steps until the order parameter passes 0.9, mean (95% interval) over $seeds seeds: RoboSim" \
  "$(interval "${order_rs[@]}"), ARGoS $(interval "${order_ar[@]}")" | tee -a "$out"
for w in foraging diffusion_10 diffusion_100 flocking flocking_100; do
  # shellcheck disable=SC2086
  mo=$(median ${one[$w]}); mw=$(median ${whole[$w]}); ma=$(median ${argos[$w]})
  # shellcheck disable=SC2086
  mf=$(median ${floor[$w]:-})
  awk -v w="$w" -v o="$mo" -v p="$mw" -v a="$ma" -v f="$mf" 'BEGIN { printf "median %s: RoboSim %s steps/s (whole process %s), ARGoS %s: RoboSim / ARGoS = %.2f (whole process %.2f)%s\n", w, o, p, a, o/a, p/a, (f == "" || f == "NaN" ? "" : sprintf("; the floor %s: RoboSim / floor = %.2f", f, o/f)) }' \
    | tee -a "$out"
done
runs=$((seeds >= 10 ? 40 : 4 * seeds))
cat >"$tmp/foraging.sweep.xml" <<XML
<sweep world="$ROBOSIM_HOME/examples/argos/foraging.xml" steps="$steps">
  <seeds from="1" to="$runs"/>
  <metrics><metric report="collected_food"/></metrics>
</sweep>
XML
t0=$EPOCHREALTIME
scripts/sweep.sh "$tmp/foraging.sweep.xml" --out "$tmp/sweep" >"$tmp/sweep.txt" 2>&1 || { tail -5 "$tmp/sweep.txt" >&2; robosim_fail "the sweep failed"; }
sweep_s=$(elapsed "$t0")
t0=$EPOCHREALTIME
seq "$runs" | xargs -P "$(nproc)" -I{} "$runner" "$peers" foraging "$steps" {} "$tmp/xargs-{}" >"$tmp/xargs.txt" 2>&1 \
  || { tail -5 "$tmp/xargs.txt" >&2; robosim_fail "ARGoS's runs failed"; }
xargs_s=$(elapsed "$t0")
awk -v n="$runs" -v r="$sweep_s" -v a="$xargs_s" -v p="$(nproc)" 'BEGIN { printf "sweep of foraging over %d seeds: scripts/sweep.sh %.1f s, ARGoS with xargs -P %d %.1f s: ARGoS / RoboSim = %.2f\n", n, r, p, a, a/r }' \
  | tee -a "$out"

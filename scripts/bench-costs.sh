#!/usr/bin/env bash
# What TLS and recording cost, in one sitting, repeated and alternated:
#   scripts/bench-costs.sh [REPS] [STEPS] [--classpath PATH[:PATH...]] [-- headless.sh options...] [--help]
# REPS defaults to 3, STEPS to 5000. Makes fresh keys in a temporary directory (removed at the end, with the
# recordings), then runs, REPS times each in turn: bench/FloorProcesses (10 client processes, plain sockets:
# the floor of the paper benchmark's shape), and headless.sh on test-envs/paper-benchmark.xml plain, with
# the keys (ROBOSIM_KEYS: TLS and the secret on every connection), with --record, with --record and a
# page's network side reading the browser viewer (--web-port; bench/WebPageReader: the feed, the robot
# panel's feed for robot1, a status a second, no drawing: what serving a page costs the run), and with
# --record and a real page (the page in a headless chromium on this same machine, watching robot1:
# skipped, saying so, without one); plain and with the keys again with --robots-in-one-process. Prints every line, the medians and the ratios to
# the floor; writes no file in the repository (bench/FloorProcesses compiles to bench/classes).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_paper_bench_args "$@"
reps=$BENCH_REPS; steps=$BENCH_STEPS
set -- "${ROBOSIM_PASS[@]}"
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
scripts/make-keys.sh "$tmp/keys" >/dev/null
rate() { grep -oE '(^| )steps(_per_s|/s)=[0-9.]+' | head -n 1 | sed -E 's/.*=//'; }
run() { # NAME KEYS [headless options]
  local name=$1 keys=$2 l; shift 2
  l=$(env -u ROBOSIM_SECRET -u ROBOSIM_SECRET_FILE ROBOSIM_KEYS="$keys" scripts/headless.sh \
      --env test-envs/paper-benchmark.xml --steps "$steps" "$@" 2>/dev/null | tail -n 1)
  printf '%-20s %s\n' "$name" "$l"; echo "$l" | rate > "$tmp/last"
}
free_port() { local p; while :; do p=$((20000 + RANDOM % 20000))
  (exec 3<>"/dev/tcp/127.0.0.1/$p") 2>/dev/null || { echo "$p"; return; }; done; }
browser=$(command -v chromium || true)
[ -n "$browser" ] || echo "bench-costs: no chromium (apt-get install chromium): the run with a browser viewer is skipped"
javac -d bench/classes bench/WebPageReader.java
page_on() { # PORT: a headless chromium that opens the browser viewer as soon as it answers; prints its pid
  printf '%s\n' "<!doctype html><script>const u='http://localhost:$1/?watch=robot1';" \
    "(function t(){fetch(u,{mode:'no-cors'}).then(()=>location.href=u,()=>setTimeout(t,100))})()</script>" > "$tmp/wait.html"
  "$browser" --headless=new --no-sandbox --disable-dev-shm-usage --user-data-dir="$tmp/chrome" \
    --window-size=1200,800 "file://$tmp/wait.html" >/dev/null 2>&1 & echo $!
}
declare -a fp p t rec rf rw po to
for i in $(seq "$reps"); do
  l=$(java -cp bench/classes FloorProcesses 10 "$steps" obj); echo "floor-processes      $l"; fp+=("$(echo "$l" | rate)")
  run plain "" "$@"; p+=("$(cat "$tmp/last")")
  run tls "$tmp/keys" "$@"; t+=("$(cat "$tmp/last")")
  run record "" --record "$tmp/run-$i.rec" "$@"; rec+=("$(cat "$tmp/last")")
  echo "  recording: $(stat -c %s "$tmp/run-$i.rec") bytes"
  wp=$(free_port); java -cp bench/classes WebPageReader "$wp" robot1 >/dev/null 2>&1 & reader=$!
  run record+feed "" --record "$tmp/feed-$i.rec" --web-port "$wp" "$@"; rf+=("$(cat "$tmp/last")")
  kill "$reader" 2>/dev/null || true; wait "$reader" 2>/dev/null || true   # (it ends with the run)
  if [ -n "$browser" ]; then
    wp=$(free_port); page=$(page_on "$wp")
    run record+web "" --record "$tmp/web-$i.rec" --web-port "$wp" "$@"; rw+=("$(cat "$tmp/last")")
    kill "$page" 2>/dev/null || true
    while kill -0 "$page" 2>/dev/null; do sleep 0.1; done   # (not a child of this shell: wait cannot)
  fi
  run plain-1proc "" --robots-in-one-process "$@"; po+=("$(cat "$tmp/last")")
  run tls-1proc "$tmp/keys" --robots-in-one-process "$@"; to+=("$(cat "$tmp/last")")
done
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
m_fp=$(median "${fp[@]}"); m_p=$(median "${p[@]}"); m_t=$(median "${t[@]}"); m_r=$(median "${rec[@]}")
m_po=$(median "${po[@]}"); m_to=$(median "${to[@]}"); m_w=$( [ ${#rw[@]} -gt 0 ] && median "${rw[@]}" || echo 0)
m_f=$(median "${rf[@]}")
echo "median steps/s: floor-processes=$m_fp plain=$m_p tls=$m_t record=$m_r record+feed=$m_f record+web=$m_w plain-1proc=$m_po tls-1proc=$m_to"
awk -v f="$m_fp" -v p="$m_p" -v t="$m_t" -v r="$m_r" -v w="$m_w" -v rf="$m_f" -v po="$m_po" -v to="$m_to" 'BEGIN { printf "ratio to floor-processes: plain=%.2f tls=%.2f record=%.2f record+feed=%.2f record+web=%.2f plain-1proc=%.2f tls-1proc=%.2f; to plain: tls=%.2f (in one process %.2f) record=%.2f; to record: record+feed=%.2f record+web=%.2f\n", p/f, t/f, r/f, rf/f, w/f, po/f, to/f, t/p, to/po, r/p, rf/r, w/r }'

#!/usr/bin/env bash
# bench-lib.sh: a library sourced by bench-reset.sh, bench-memory.sh, bench-designs.sh, bench-speed.sh and
# bench-python.sh, not a command: reading heaps, following a headless run's progress, a run's rate and its row
# beside a floor (the floors are this repository's own, bench/*.java), and the one table a script writes into a doc.
if [ "${BASH_SOURCE[0]}" = "$0" ]; then
  case ${1:-} in
    -h|--help) sed -nE '2,/^[^#]/s/^# ?//p' "$0"; exit 0 ;;
    *) echo "bench-lib.sh: a library for the bench-*.sh scripts, not a command (given: $*; see --help)" >&2; exit 2 ;;
  esac
fi

# Old-generation size (KB) of JVM $1 after a full GC (SerialGC); empty if there is no such JVM.
tenured() {
  [ -n "$1" ] || return 0
  jcmd "$1" GC.run >/dev/null 2>&1 || true
  jcmd "$1" GC.heap_info 2>/dev/null | sed -nE 's/.*tenured generation +total [0-9]+K, used ([0-9]+)K.*/\1/p' || true
}

# Waits until the --progress log $1 of run $2 shows step $3 or later (or the run ends); prints the step.
await_step() {
  local log=$1 run=$2 target=$3 at=0
  while kill -0 "$run" 2>/dev/null; do
    at=$( (grep -oE '^step [0-9]+' "$log" || true) | tail -n 1 | cut -d' ' -f2); at=${at:-0}
    [ "$at" -ge "$target" ] && break
    sleep 1   # a script, not a test: polling a progress line
  done
  echo "$at"
}

# The pid of the first process whose command line matches $1, or nothing.
pid_of() {
  (pgrep -f "$1" || true) | head -n 1
}

# steps/s from a floor's "steps=S wall=Ws" words (or its steps/s), read on stdin
floor_rate() { awk '{ for (i = 1; i <= NF; i++) { split($i, kv, "="); v[kv[1]] = kv[2] } }
  END { sub(/s$/, "", v["wall"]); if (v["wall"] > 0) printf "%.1f", v["steps"] / v["wall"]; else if (v["steps/s"] > 0) print v["steps/s"] }'; }
# steps/s from headless.sh's summary line, read on stdin
rate() { (grep -oE '(^| )steps_per_s=[0-9.]+' || true) | head -n 1 | sed -E 's/.*=//'; }
# One run beside its floor: appended to $out (sitting $sitting) and printed. Args: variant robots steps rep
# rate floor floor_rate
row() {
  local ratio=""
  [ -n "$5" ] && [ -n "$7" ] && ratio=$(awk -v a="$5" -v b="$7" 'BEGIN { printf "%.3f", a / b }')
  echo "$sitting,$1,$2,$3,$4,$5,$6,$7,$ratio" >> "$out"
  printf '%-26s N=%-5s %9s steps/s   %-13s %9s steps/s   ratio %s\n' "$1" "$2" "$5" "$6" "$7" "$ratio"
}

# Replaces the lines between "<!-- $1: ..." and "<!-- /$1 -->" in the doc $3 with the file $2 (the marks stay);
# fails, changing nothing, when the doc lacks either mark.
replace_marked() {
  local mark=$1 with=$2 doc=$3 tmp
  grep -q "^<!-- $mark:" "$doc" && grep -q "^<!-- /$mark -->" "$doc" \
    || { echo "bench: $doc has no <!-- $mark: ... --> ... <!-- /$mark --> marks" >&2; return 1; }
  tmp=$(mktemp)
  awk -v mark="$mark" -v with="$with" '
    index($0, "<!-- " mark ":") == 1 { print; while ((getline line < with) > 0) print line; skip = 1; next }
    index($0, "<!-- /" mark " -->") == 1 { skip = 0 }
    !skip { print }' "$doc" > "$tmp" && mv "$tmp" "$doc"
}

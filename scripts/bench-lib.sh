#!/usr/bin/env bash
# bench-lib.sh: a library sourced by bench-reset.sh and bench-memory.sh, not a command: reading heaps
# and following a headless run's progress.
if [ "${BASH_SOURCE[0]}" = "$0" ]; then
  case ${1:-} in
    -h|--help) sed -nE '2,/^[^#]/s/^# ?//p' "$0"; exit 0 ;;
    *) echo "bench-lib.sh: a library for bench-reset.sh and bench-memory.sh, not a command (given: $*; see --help)" >&2; exit 2 ;;
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

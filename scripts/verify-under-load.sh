#!/usr/bin/env bash
# Runs the whole test suite (./mvnw verify) several times in a row while stress-ng loads every core,
# and stops at the first red run: a suite that can fail by chance shows it here.
#   scripts/verify-under-load.sh [--runs N] [--cpu WORKERS]    (defaults: 5 runs, 2 CPU workers)
# Each run's log goes to a fresh directory printed at the start; nothing under the repository changes
# except target/ directories. Needs Debian's stress-ng (installed here if missing and we are root).
set -euo pipefail
usage() {
  sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//'
}
runs=5
cpu=2
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --runs) runs=${2:-}; shift 2 || { echo "verify-under-load: --runs needs a number" >&2; exit 2; } ;;
    --cpu) cpu=${2:-}; shift 2 || { echo "verify-under-load: --cpu needs a number" >&2; exit 2; } ;;
    *) echo "verify-under-load: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
[[ "$runs" =~ ^[1-9][0-9]*$ ]] || { echo "verify-under-load: --runs must be a whole number >= 1, got '$runs'" >&2; exit 2; }
[[ "$cpu" =~ ^[1-9][0-9]*$ ]] || { echo "verify-under-load: --cpu must be a whole number >= 1, got '$cpu'" >&2; exit 2; }
cd "$(dirname "${BASH_SOURCE[0]}")/.."
if ! command -v stress-ng >/dev/null; then
  if [ "$(id -u)" = 0 ]; then
    echo "verify-under-load: installing Debian's stress-ng ..." >&2
    apt-get update -qq >/dev/null && apt-get install -y -qq stress-ng >/dev/null
  else
    echo "verify-under-load: needs stress-ng (apt-get install stress-ng)" >&2; exit 2
  fi
fi
logs=$(mktemp -d "${TMPDIR:-/tmp}/robosim-verify-under-load.XXXXXX")
echo "verify-under-load: $runs runs of ./mvnw verify under stress-ng --cpu $cpu; logs in $logs"
stress-ng --cpu "$cpu" --quiet &
stress=$!
trap 'kill "$stress" 2>/dev/null || true; wait "$stress" 2>/dev/null || true' EXIT
for i in $(seq 1 "$runs"); do
  start=$(date +%s)
  if ./mvnw -B -ntp verify >"$logs/run-$i.log" 2>&1; then
    result=green
  else
    result=RED
  fi
  # (a run that never reached the tests, e.g. a compile error, has no such lines: 0 tests)
  tests=$(awk -F'[ ,]+' '/^\[(INFO|ERROR|WARNING)\] Tests run: [0-9]+, Failures/ && !/ -- in / {
      run += $4; failed += $6 + $8 } END { printf "%d tests, %d failed", run, failed }' "$logs/run-$i.log")
  echo "run $i/$runs: $result in $(( $(date +%s) - start )) s ($tests)"
  if [ "$result" = RED ]; then
    grep -E '<<< (FAILURE|ERROR)!' "$logs/run-$i.log" | head -n 10 || true
    echo "verify-under-load: run $i failed; its log: $logs/run-$i.log" >&2
    exit 1
  fi
done
echo "verify-under-load: $runs of $runs runs green under load"

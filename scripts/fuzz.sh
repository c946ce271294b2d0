#!/usr/bin/env bash
# Fuzzes the message decoding for longer than the build does (the build fuzzes for 6 s, module fuzz):
#   scripts/fuzz.sh [DURATION] [--help]     e.g. scripts/fuzz.sh 30m   (default 5m)
# Jazzer (coverage-guided, libFuzzer) feeds bytes through ObjectConnection exactly as every process
# reads its peers. A finding fails the run and is saved as a regression input under
# fuzz/src/test/resources/robosim/protocol/MessageDecodingFuzzTestInputs/ (commit it with the fix);
# the growing corpus stays in fuzz/.cifuzz-corpus/ between runs.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_one_arg DURATION "$@"
duration=$ROBOSIM_ONE
duration=${duration:-5m}
[[ "$duration" =~ ^[0-9]+[smh]?$ ]] || robosim_fail "DURATION must look like 90s, 30m or 2h, got $duration"
cd "$ROBOSIM_HOME"
case $duration in
  *h) seconds=$(( ${duration%h} * 3600 )) ;;
  *m) seconds=$(( ${duration%m} * 60 )) ;;
  *) seconds=${duration%s} ;;
esac
echo "fuzz: fuzzing for $seconds s" >&2
exec ./mvnw -B -ntp -pl fuzz -am test -Dfuzz.seconds="$seconds" -Dtest=MessageDecodingFuzzTest \
  -Dsurefire.failIfNoSpecifiedTests=false

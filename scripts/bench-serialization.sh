#!/usr/bin/env bash
# JMH: Serializable against Externalizable for the same per-step messages (ns per message written
# and read) and bytes per message.
#   scripts/bench-serialization.sh [--write-docs | --out DIR] [--classpath PATH[:PATH...]] [-- JMH options]
# e.g. scripts/bench-serialization.sh --write-docs -- -f 2 -i 8
# Writes serialization.txt and message-sizes.txt into a fresh temporary directory (its path is
# printed), into DIR with --out DIR, or into docs/perf/ (which docs/PERFORMANCE.md quotes and
# bench.sh plots) with --write-docs. Options after -- go to JMH (java -jar ... -h lists them).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
robosim_script_args docs/perf "$@"
[ ${#ROBOSIM_ARGS[@]} = 0 ] || robosim_fail "takes no arguments before --, got '${ROBOSIM_ARGS[0]}' (see --help)"
dir=$(robosim_out_dir)
cd "$ROBOSIM_HOME"
robosim_build_if_stale
if ! ls bench-jmh/target/bench-jmh-*.jar >/dev/null 2>&1; then
  ./mvnw -q -B package -DskipTests -pl protocol,bench-jmh
fi
jar=$(ls bench-jmh/target/bench-jmh-*.jar | head -n 1)
cp="bench-jmh/target/lib/*:$jar${ROBOSIM_CLASSPATH:+:$ROBOSIM_CLASSPATH}"
java -cp "$cp" robosim.bench.MessageSizes | tee "$dir/message-sizes.txt"
java -cp "$cp" org.openjdk.jmh.Main SerializationBenchmark \
  -rf text -rff "$dir/serialization.txt" "${ROBOSIM_PASS[@]}" >/dev/null
cat "$dir/serialization.txt"
echo "bench-serialization: wrote $dir/message-sizes.txt and $dir/serialization.txt"

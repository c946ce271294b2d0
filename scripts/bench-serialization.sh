#!/usr/bin/env bash
# JMH: Serializable against Externalizable for the same per-step messages (ns per message written
# and read) and bytes per message. Writes docs/perf/serialization.txt and docs/perf/message-sizes.txt.
#   scripts/bench-serialization.sh [extra JMH options]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
if ! ls bench-jmh/target/bench-jmh-*.jar >/dev/null 2>&1; then
  ./mvnw -q -B package -DskipTests -pl protocol,bench-jmh
fi
mkdir -p docs/perf
jar=$(ls bench-jmh/target/bench-jmh-*.jar | head -n 1)
java -cp "bench-jmh/target/lib/*:$jar" robosim.bench.MessageSizes | tee docs/perf/message-sizes.txt
java -cp "bench-jmh/target/lib/*:$jar" org.openjdk.jmh.Main SerializationBenchmark \
  -rf text -rff docs/perf/serialization.txt "$@" >/dev/null
cat docs/perf/serialization.txt

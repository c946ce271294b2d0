/** JMH micro-benchmarks of the wire protocol; run by {@code scripts/bench-serialization.sh}, never by the tests. */
package robosim.bench;

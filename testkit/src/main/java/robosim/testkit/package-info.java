/**
 * A whole simulation in the caller's JVM, for testing control code with JUnit ({@link robosim.testkit.Simulation}).
 * It starts no thread of its own: the Environment's ({@code simulation-loop}, {@code connection-watch}, the
 * acceptors of its loopback ports, listed in {@link robosim.environment.net}) and each robot's control thread,
 * {@code control[name]} ({@link robosim.hardware}). The test's thread waits on the loop's answers only.
 */
package robosim.testkit;

/**
 * The simulation host ({@code scripts/simulation-host.sh}): the testkit's simulations served to a tester in another
 * process (Python's {@code robosim.testing}) over the simulation link ({@link robosim.testhost.SimulationLink}).
 * Threads: {@code main} accepts the tester and serves its requests one at a time; each simulation's threads are the
 * testkit's ({@link robosim.testkit}: the Environment's loop and acceptors, each robot's {@code control[name]}),
 * and a Python controller's process is read by the Hardware Simulator's link threads ({@link robosim.hardware.link}).
 */
package robosim.testhost;

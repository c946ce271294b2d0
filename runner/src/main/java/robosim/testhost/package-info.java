/**
 * The simulation host ({@code scripts/simulation-host.sh}): the testkit's simulations served to a tester in another
 * process (Python's {@code robosim.testing}, {@code robosim.run}) over the simulation link
 * ({@link robosim.testhost.SimulationLink}).
 *
 * <table>
 * <caption>threads</caption>
 * <tr><th>thread</th><th>role</th></tr>
 * <tr><td>{@code main}</td><td>accepts connections until one is the tester's, then serves its requests one at a
 * time</td></tr>
 * <tr><td>{@code link-hello[n]}</td><td>daemons, one a connection while the tester is awaited
 * (robosim.protocol.link.FirstHello, at most 16 at once): each reads its connection's hello and answers it</td></tr>
 * <tr><td>{@code link-deadline}</td><td>robosim.protocol.link.LinkFrames: closes a connection whose hello is
 * late</td></tr>
 * <tr><td>{@code run}</td><td>a headless run's runner ({@code robosim.runner.RunHost}), one run at a time, while
 * {@code main} waits for it; with it the run's own threads (robosim.runner, robosim.environment)</td></tr>
 * <tr><td>the testkit's</td><td>each simulation's ({@link robosim.testkit}: the Environment's loop and acceptors,
 * each robot's {@code control[name]}; a Python controller's process read by robosim.hardware.link's threads); a
 * robot the link drives ({@code control="ros2"}, {@link robosim.testhost.DrivenRobot}) runs on its
 * {@code control[name]}, taking each step's command from {@code main} and leaving its senses for it through a
 * one-place queue each way (no lock held while either waits)</td></tr>
 * </table>
 */
package robosim.testhost;

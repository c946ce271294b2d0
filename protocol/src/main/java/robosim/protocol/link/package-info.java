/**
 * What the MessagePack links share (the robot link, robosim.hardware.link; the loop link,
 * robosim.environment.core.LoopScript; the learning link, robosim.rl; the simulation link, robosim.testhost): frames
 * ({@link robosim.protocol.link.LinkFrames}), the hello ({@link robosim.protocol.link.LinkHello}), a host's first peer
 * of many connections ({@link robosim.protocol.link.FirstHello}), and the script a link serves, started and stopped
 * ({@link robosim.protocol.link.ScriptProcess}). Threads:
 *
 * <table>
 * <caption>threads</caption>
 * <tr><th>thread</th><th>role</th></tr>
 * <tr><td>{@code link-deadline}</td><td>a daemon, one per JVM while hellos are awaited (it ends after a second
 * idle; {@link robosim.protocol.link.LinkFrames#hello}): closes a connection whose hello has not come within its
 * deadline, {@link robosim.protocol.link.LinkHello#DEADLINE_MS} (a deadline, not a read timeout)</td></tr>
 * <tr><td>{@code link-hello[n]}</td><td>a daemon, one per connection to a host's port while it awaits its peer
 * ({@link robosim.protocol.link.FirstHello}): reads that connection's hello and answers it, within the hello's
 * deadline</td></tr>
 * <tr><td>{@code script-output[name]}</td><td>a daemon, one per script started ({@link robosim.protocol.link.ScriptProcess}):
 * reads the script's output and logs it line by line, until the script exits</td></tr>
 * </table>
 */
package robosim.protocol.link;

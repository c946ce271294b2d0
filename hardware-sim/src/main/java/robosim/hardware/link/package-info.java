/**
 * The robot link ({@link robosim.hardware.link.RobotLink}; hardware-sim/README.md, "The robot link"): one robot's
 * API served to control code in another process, in any language, as length-prefixed MessagePack frames
 * ({@link robosim.hardware.link.LinkFrames}), one request and one reply per call ({@link robosim.hardware.link.RobotCalls}).
 * It runs on the thread that serves the robot's control code (its {@code control[name]}); threads of its own:
 *
 * <table>
 * <caption>threads</caption>
 * <tr><th>thread</th><th>role</th></tr>
 * <tr><td>{@code link-deadline}</td><td>a daemon, one per JVM while hellos are awaited (it ends after a second
 * idle; {@link robosim.hardware.link.LinkFrames#hello}): closes a connection whose hello has not come within its
 * deadline, {@link robosim.hardware.link.LinkHello#DEADLINE_MS} (a deadline, not a read timeout); the
 * learning link's hellos too (robosim.rl)</td></tr>
 * <tr><td>{@code script-output[name]}</td><td>a daemon, one per script a {@link robosim.hardware.link.ScriptControl}
 * started: reads the script's output and logs it line by line, until the script exits</td></tr>
 * </table>
 */
package robosim.hardware.link;

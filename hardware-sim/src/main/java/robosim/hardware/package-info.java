/**
 * The Hardware Simulator: {@link robosim.hardware.HardwareSimulator} links one robot to the
 * Environment and runs the lock-step exchange on the thread that calls {@code run} (the process's
 * {@code main}, or one thread per robot in {@code robots.sh}); the control code runs on its own
 * thread, {@code control[name]} (a virtual thread on JDK 21+, see {@link robosim.hardware.ControlThreads}). The two take turns through {@link robosim.hardware.ControlLink}: a
 * step's request is built only once the control code is blocked in a simulator call (or has
 * finished), so runs are deterministic, and the {@link robosim.hardware.RobotKnowledge} they share is
 * touched by one of them at a time. Exchange modes, one class each besides the default: many robots
 * of one process over one connection on one {@code exchange} thread ({@link robosim.hardware.SharedLink},
 * {@code robots.sh}'s default), many robots with a socket each on one exchange thread
 * ({@link robosim.hardware.SharedExchange}), and the report's two-thread
 * Hardware Simulator ({@link robosim.hardware.SendReceiveExchange}, whose {@code receiver[name]}
 * thread reads and applies responses). In a one-JVM run a robot is an {@link robosim.hardware.InMemoryRobot}
 * and has no exchange thread: the Environment's {@code simulation-loop} applies its responses and builds
 * the requests of a call that goes on, and its {@code control[name]} thread builds the request of each new
 * call as it makes it ({@link robosim.hardware.ControlLink#onYield}). Robot types ({@link robosim.devices.ArRobot},
 * {@link robosim.devices.Scout}) are one class each.
 */
package robosim.hardware;

/**
 * The Environment's control port: {@link robosim.environment.control.EnvironmentHost} runs one
 * simulation after another on fixed ports, and {@link robosim.environment.control.ControlServer}
 * (netty) lets the Control Panel load, start, stop, pause, resume, step and query it
 * ({@link robosim.environment.control.ControlRequests}: the proof, then the
 * {@link robosim.environment.control.ControlCommands} it serves: {@link
 * robosim.environment.control.EnvironmentCommands}, or a replay's); {@code load} reads only inside the
 * {@link robosim.environment.control.EnvironmentDirectories}. Threads: {@code control-io} (netty's one I/O
 * thread: reads lines, writes replies in each connection's request order), {@code control} (the requests
 * that wait: step, pause, start, load, add, remove; one at a time), {@code control-quick} (status, robots,
 * resume, stop, shutdown), {@code robot-output[name]} (one per robot process {@code add} started with
 * {@code --launch-robots}: {@link robosim.environment.control.RobotLaunches}; blocks reading its output). The
 * host's {@code run} is the caller's thread (the Environment's main).
 */
package robosim.environment.control;

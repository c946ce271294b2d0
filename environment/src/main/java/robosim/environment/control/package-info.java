/**
 * The Environment's control port: {@link robosim.environment.control.EnvironmentHost} runs one
 * simulation after another on fixed ports, and {@link robosim.environment.control.ControlServer}
 * (netty) lets the Control Panel load, start, stop, pause, resume, step and query it
 * ({@link robosim.environment.control.ControlRequests}: the proof, then the
 * {@link robosim.environment.control.ControlCommands} it serves: {@link
 * robosim.environment.control.EnvironmentCommands}, or a replay's); {@code load} reads only inside the
 * {@link robosim.environment.control.EnvironmentDirectories}. Its threads, {@code control-io}, {@code control},
 * {@code control-quick} and {@code robot-output[name]}, are in the Environment's thread table, with what each does
 * and where it blocks ({@code robosim.environment.net}'s package documentation); a replay's control port has the
 * first three too. The host's {@code run} is the caller's thread (the Environment's main).
 */
package robosim.environment.control;

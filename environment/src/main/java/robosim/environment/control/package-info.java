/**
 * The Environment's control port: {@link robosim.environment.control.EnvironmentHost} runs one
 * simulation after another on fixed ports, and {@link robosim.environment.control.ControlServer}
 * (netty) lets the Control Panel load, start, stop, pause, resume, step and query it.
 */
package robosim.environment.control;

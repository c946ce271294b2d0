/**
 * The Hardware Simulator: {@link robosim.hardware.HardwareSimulator} links one robot to the
 * Environment and runs the lock-step exchange on its own thread ({@code hardware[name]}); the
 * control code runs on another ({@code control[name]}). The two pass a baton through
 * {@link robosim.hardware.ControlLink}: a step's request is built only once the control code is
 * blocked in a simulator call (or has finished), so runs are deterministic. Robot types
 * ({@link robosim.hardware.ArRobot}, {@link robosim.hardware.Scout}) are one class each.
 */
package robosim.hardware;

package robosim.environment.run;

/**
 * One robot of the run as the control port lists it ({@code robots}, and in {@code status}).
 *
 * @param state {@code expected} (not connected yet, before the start), {@code connected} (before the
 *     start), {@code running}, {@code held} (lost, standing in the world until a process says hello with
 *     its name: {@code --on-robot-loss HOLD}), {@code waiting} (lost, and the world waits for it:
 *     {@code WAIT}), {@code returning} (a new connection takes over at the next step), {@code gone}
 *     (removed) or {@code added} (added from the control port, its hello not heard yet; listed after the others,
 *     by name)
 * @param sinceStep the step it has been held, waited for or gone since; -1 for the other states
 */
public record RobotState(String name, String state, long sinceStep) {
    /** The state of a robot {@code add} let in that has not said hello: listed after every robot of the world. */
    public static final String ADDED = "added";
}

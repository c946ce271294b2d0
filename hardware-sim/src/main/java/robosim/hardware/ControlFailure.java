package robosim.hardware;

/**
 * What a robot's control code threw out of {@code run} while the simulation went on.
 *
 * @param robot the robot's name
 * @param step the steps it had completed when its control code threw (the number a person is shown:
 *     protocol/README.md, "Step numbers")
 * @param thrown what it threw
 */
public record ControlFailure(String robot, long step, Throwable thrown) {
    /** Its class and message on one line (a runner reads it from stderr). */
    public String summary() {
        return thrown.toString().replaceAll("\\s+", " "); // (a Throwable's: its class and message; a controller's: its own)
    }
}

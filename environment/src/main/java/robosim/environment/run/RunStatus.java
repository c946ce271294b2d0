package robosim.environment.run;

import java.util.List;

/**
 * What the control port reports.
 *
 * @param state where the run is
 * @param connected robots whose connection is open and who take part (or wait for the start)
 * @param left robots that were in this simulation and whose connection has closed or who were removed
 * @param geometry {@code in-process} (no Geometry process: {@code --no-geometry}, or going on without
 *     a lost one), {@code attached}, {@code waiting} (for a Geometry process) or {@code none} (ended)
 * @param viewers viewers connected now
 * @param states every robot in the world and its state ({@link RobotState}), in world order
 */
public record RunStatus(State state, long step, double stepsPerSecond, List<String> robots, List<String> connected,
        List<String> left, String geometry, String reason, int viewers, List<RobotState> states) {
    /** Waiting for its clients; running; paused (held by pause or step N); ended. */
    public enum State { WAITING, RUNNING, PAUSED, ENDED }
}

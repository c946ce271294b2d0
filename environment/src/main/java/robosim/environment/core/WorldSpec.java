package robosim.environment.core;

import java.util.List;
import robosim.protocol.Arena;
import robosim.protocol.ObstacleShape;

/**
 * An environment as loaded from its file, in world millimetres and degrees: immutable.
 *
 * @param source the file it came from, for messages
 */
public record WorldSpec(String source, String name, long timeStepMs, long seed, Arena arena,
        List<ObstacleShape> obstacles, List<RobotSpec> robots) {
    public WorldSpec {
        if (timeStepMs <= 0) {
            throw new IllegalArgumentException("time step must be > 0 ms, got " + timeStepMs);
        }
        obstacles = List.copyOf(obstacles);
        robots = List.copyOf(robots);
    }

    /** Index of the robot with this name, or -1. */
    public int indexOf(String robotName) {
        for (int i = 0; i < robots.size(); i++) {
            if (robots.get(i).name().equals(robotName)) {
                return i;
            }
        }
        return -1;
    }

    /**
     * One robot named in the file.
     *
     * @param control the control class the headless runner starts for it (may be empty)
     */
    public record RobotSpec(String name, String type, String control, double xMm, double yMm, double headingDeg) {
    }
}

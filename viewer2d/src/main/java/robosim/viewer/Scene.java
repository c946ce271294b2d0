package robosim.viewer;

import java.util.List;
import robosim.protocol.Arena;
import robosim.protocol.ObstacleShape;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotProperties;

/**
 * Everything one frame shows, immutable: the static world, the newest poses and sonar ranges, each
 * robot's trail (x, y pairs in mm, oldest first) and the status line's facts. Shared between the
 * network thread that builds it and the Swing thread that draws it.
 *
 * @param stepsPerSecond measured from the updates while running; NaN until measured
 * @param status the run's state as the viewer knows it (see {@link StatusLine})
 */
public record Scene(Arena arena, List<ObstacleShape> obstacles, List<String> names, List<RobotProperties> robots,
        PoseUpdate poses, double[][] trails, double stepsPerSecond, ViewedRun status) {

    public int robotCount() {
        return names.size();
    }

    /** The step the poses belong to (-1 before the first). */
    public long step() {
        return poses.step();
    }

    public Scene withStatus(ViewedRun newStatus) {
        return new Scene(arena, obstacles, names, robots, poses, trails, stepsPerSecond, newStatus);
    }
}

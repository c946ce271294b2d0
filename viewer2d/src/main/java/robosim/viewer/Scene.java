package robosim.viewer;

import java.awt.image.BufferedImage;
import java.util.List;
import robosim.protocol.Arena;
import robosim.protocol.Floor;
import robosim.protocol.ObstacleShape;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotProperties;
import robosim.protocol.Scenery;

/**
 * Everything one frame shows, immutable: the static world, the newest poses and sonar ranges, each
 * robot's trail (x, y pairs in mm, oldest first) and the status line's facts, and the scenery (floor, lights,
 * objects; where the objects stand and the robots' LEDs are in the poses). Shared between the
 * network thread that builds it and the Swing thread that draws it.
 *
 * @param stepsPerSecond measured from the updates while running; NaN until measured
 * @param status the run's state as the viewer knows it (see {@link StatusLine})
 * @param floorImage the floor's image, drawn once from the scenery's (null for none)
 */
public record Scene(Arena arena, List<ObstacleShape> obstacles, List<String> names, List<RobotProperties> robots,
        PoseUpdate poses, double[][] trails, double stepsPerSecond, ViewedRun status, Scenery scenery,
        BufferedImage floorImage) {

    /** A world without floor, lights and objects. */
    public Scene(Arena arena, List<ObstacleShape> obstacles, List<String> names, List<RobotProperties> robots,
            PoseUpdate poses, double[][] trails, double stepsPerSecond, ViewedRun status) {
        this(arena, obstacles, names, robots, poses, trails, stepsPerSecond, status, Scenery.NONE, null);
    }

    public int robotCount() {
        return names.size();
    }

    /** The step the poses belong to (-1 before the first). */
    public long step() {
        return poses.step();
    }

    public Scene withStatus(ViewedRun newStatus) {
        return new Scene(arena, obstacles, names, robots, poses, trails, stepsPerSecond, newStatus, scenery,
                floorImage);
    }

    /** {@code image} as a picture to draw (its top row first), or null for none. */
    public static BufferedImage picture(Floor.Image image) {
        if (image == null) {
            return null;
        }
        BufferedImage b = new BufferedImage(image.width(), image.height(), BufferedImage.TYPE_INT_RGB);
        b.setRGB(0, 0, image.width(), image.height(), image.rgb(), 0, image.width());
        return b;
    }
}

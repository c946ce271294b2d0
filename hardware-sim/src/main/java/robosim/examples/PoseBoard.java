package robosim.examples;

import java.util.HashMap;
import java.util.Map;
import robosim.api.Message;
import robosim.api.Robot;

/**
 * Robots telling each other where they are: {@link #announce} broadcasts "pose x y" (mm);
 * {@link #listen} reads every waiting message and keeps each sender's newest pose. Other messages
 * are handed to {@link #other}.
 */
class PoseBoard {
    static final String PREFIX = "pose ";

    final Map<String, double[]> poses = new HashMap<>();

    static void announce(Robot robot) {
        robot.broadcast(PREFIX + robot.xMm() + " " + robot.yMm());
    }

    void listen(Robot robot) {
        for (Message m = robot.receive(); m != null; m = robot.receive()) {
            if (m.text().startsWith(PREFIX)) {
                String[] p = m.text().substring(PREFIX.length()).split(" ");
                try {
                    poses.put(m.from(), new double[] {Double.parseDouble(p[0]), Double.parseDouble(p[1])});
                } catch (ArrayIndexOutOfBoundsException | NumberFormatException malformed) {
                    other(m);
                }
            } else {
                other(m);
            }
        }
    }

    /** A message that is not a pose; ignored here. */
    void other(Message m) {
    }

    /** Degrees to turn (in (-180, 180]) to face the point from the robot's pose. */
    static double bearingTo(Robot robot, double x, double y) {
        double to = Math.toDegrees(Math.atan2(y - robot.yMm(), x - robot.xMm()));
        return Surroundings.normalise(to - robot.headingDeg());
    }
}

package robosim.examples;

import java.util.HashSet;
import java.util.Set;
import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * The first robot chases; the others wander and broadcast their poses every step. The chaser heads
 * for the nearest robot it has not tagged yet and tags when it is within 1.4 m, roughly ahead (after
 * a miss it closes in before trying again); a tagged robot is left alone, and only robots count.
 * When all are tagged the chaser stops.
 */
public final class TagChase implements RobotControl {
    @Override
    public void run(Robot robot) throws InterruptedException {
        String chaser = robot.robotNames().get(0);
        if (!robot.name().equals(chaser)) {
            new AnnouncingWander().run(robot);
            return;
        }
        PoseBoard board = new PoseBoard();
        Set<String> tagged = new HashSet<>();
        boolean missed = false;
        robot.sleep(1);
        while (tagged.size() < robot.robotNames().size() - 1) {
            board.listen(robot);
            String prey = null;
            double nearest = Double.POSITIVE_INFINITY;
            for (var e : board.poses.entrySet()) {
                double d = Math.hypot(e.getValue()[0] - robot.xMm(), e.getValue()[1] - robot.yMm());
                if (!tagged.contains(e.getKey()) && d < nearest) {
                    nearest = d;
                    prey = e.getKey();
                }
            }
            if (prey == null) {
                robot.sleep(1);
                continue;
            }
            double[] p = board.poses.get(prey);
            double bearing = PoseBoard.bearingTo(robot, p[0], p[1]);
            if (Math.abs(bearing) > 20) {
                robot.turn(Math.max(-45, Math.min(45, bearing)));
            } else if (nearest < 1400 && !missed) {
                String hit = robot.tag();
                if (robot.robotNames().contains(hit)) {
                    tagged.add(hit);
                }
                missed = hit.isEmpty();
            } else {
                robot.move(Math.min(Wander.LEG_MM, Math.max(Wander.LEG_MM / 5, nearest - 700)));
                missed = false;
            }
        }
        while (true) {
            robot.sleep(1000);
        }
    }
}

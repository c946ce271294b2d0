package robosim.examples;

import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * The first robot in the world leads: it wanders slowly (250 mm/s) and broadcasts its pose before
 * every leg or turn (a 250 mm leg takes it two steps). Every other robot follows: each step it turns towards the leader's newest pose if that lies
 * more than 20 degrees off its heading, and otherwise drives towards it, stopping {@link #GAP_MM}
 * short.
 */
public final class FollowTheLeader implements RobotControl {
    /** How close a follower drives to the leader, centre to centre, mm. */
    public static final double GAP_MM = 1500;

    @Override
    public void run(Robot robot) throws InterruptedException {
        String leader = robot.robotNames().get(0);
        if (robot.name().equals(leader)) {
            robot.setVelocity(250);
            new AnnouncingWander().run(robot);
            return;
        }
        PoseBoard board = new PoseBoard();
        robot.sleep(1);
        while (true) {
            board.listen(robot);
            double[] target = board.poses.get(leader);
            if (target == null) {
                robot.sleep(1);
                continue;
            }
            double distance = Math.hypot(target[0] - robot.xMm(), target[1] - robot.yMm());
            double bearing = PoseBoard.bearingTo(robot, target[0], target[1]);
            if (distance <= GAP_MM) {
                robot.sleep(1);
            } else if (Math.abs(bearing) > 20) {
                robot.turn(Math.max(-45, Math.min(45, bearing)));
            } else {
                robot.move(Math.min(Wander.LEG_MM, distance - GAP_MM));
            }
        }
    }
}

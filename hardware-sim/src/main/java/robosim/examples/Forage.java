package robosim.examples;

import robosim.api.Colours;
import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * Foraging with a foot-bot (examples/python/forage.py is the same robot in Python; test-envs/foraging.xml its world):
 * it drives on its wheels, steering away from what its proximity ring sees on either side, up to what it sees straight
 * ahead, where it tries its gripper (a wall, a robot, or a can already in the nest: it backs off and turns away). A
 * can it takes it carries towards the light over the nest, steering by its light ring, until its ground sensors all
 * read the nest's grey; there it lets go, reports {@code delivered}, backs off and turns away. Its LEDs say what it is
 * doing: green searching, red carrying. Without chance, and with nothing but sums and comparisons of its
 * readings, so the Java and the Python robot give byte-identical pose logs.
 */
public final class Forage implements RobotControl {
    /** Cruising speed, mm/s. */
    public static final double SPEED = 150;
    /** A proximity reading above this is something close (0 nothing in range, 1 contact). */
    public static final double NEAR = 0.3;
    /** A front reading above this is within the gripper's 10 mm: time to try it. */
    public static final double AHEAD = 0.99;
    /** A ground reading below this is the nest's grey (the floor is white, 1). */
    public static final double NEST = 0.75;
    /** Steps it backs off and then turns after a drop or a failed grip. */
    public static final int BACK_STEPS = 5;
    public static final int TURN_STEPS = 8;

    @Override
    public void run(Robot robot) throws InterruptedException {
        int delivered = 0;
        robot.setLeds(Colours.GREEN);
        robot.step(); // (readings come with a step: none before the first)
        while (true) {
            double[] near = robot.sensor("proximity");
            boolean home = nest(robot.sensor("ground"));
            boolean carrying = !robot.gripped().isEmpty();
            if (!carrying && Math.max(near[0], near[23]) > AHEAD) {
                if (home || robot.grip().isEmpty()) {
                    turnAway(robot, near);
                } else {
                    robot.setLeds(Colours.RED);
                }
                continue;
            }
            if (carrying && home) {
                robot.setWheelSpeeds(0, 0);
                robot.release();
                robot.report("delivered", ++delivered);
                robot.setLeds(Colours.GREEN);
                turnAway(robot, near);
                continue;
            }
            if (!carrying && Math.max(near[0], near[23]) > NEAR) {
                robot.setWheelSpeeds(SPEED, SPEED); // (something straight ahead: up to it, to try the gripper)
                robot.step();
                continue;
            }
            // what is close on either side; carrying, the can in its gripper fills the front: the sides only
            double left = 0;
            double right = 0;
            for (int k = carrying ? 3 : 1; k < 6; k++) {
                left += near[k];
                right += near[23 - k];
            }
            if (Math.max(left, right) > NEAR) {
                robot.setWheelSpeeds(left > right ? SPEED : -SPEED, left > right ? -SPEED : SPEED);
            } else if (carrying) {
                double[] light = robot.sensor("light");
                double toLeft = 0;
                double toRight = 0;
                for (int k = 0; k < 12; k++) {
                    toLeft += light[k];
                    toRight += light[12 + k];
                }
                double sum = toLeft + toRight;
                double d = sum > 0 ? (toLeft - toRight) / sum : 1; // (no light in sight: turn till it is)
                robot.setWheelSpeeds(SPEED * (1 - d), SPEED * (1 + d));
            } else {
                robot.setWheelSpeeds(SPEED, SPEED);
            }
            robot.step();
        }
    }

    /** True when every ground sensor reads the nest's grey. */
    public static boolean nest(double[] ground) {
        for (double g : ground) {
            if (!(g < NEST)) {
                return false;
            }
        }
        return true;
    }

    /** Backs off, then turns away from the side more crowded by {@code near}. */
    private static void turnAway(Robot robot, double[] near) throws InterruptedException {
        robot.setWheelSpeeds(-SPEED, -SPEED);
        for (int s = 0; s < BACK_STEPS; s++) {
            robot.step();
        }
        double left = near[0] + near[1] + near[2];
        double right = near[23] + near[22] + near[21];
        robot.setWheelSpeeds(left > right ? SPEED : -SPEED, left > right ? -SPEED : SPEED);
        for (int s = 0; s < TURN_STEPS; s++) {
            robot.step();
        }
    }
}

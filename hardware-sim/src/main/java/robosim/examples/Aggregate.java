package robosim.examples;

import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * Aggregation by range-and-bearing (test-envs/aggregation.xml, e-pucks): every robot sends a message each step; each
 * steers towards where it hears most of the others (the sum of a unit vector a message, by its bearing) and stops once
 * the nearest is within {@code stopMm} (120 mm by default), turning away from what its proximity ring sees close on
 * either side. Hearing no one, it drives straight on (and turns at walls). Each step it reports {@code nearestMm}, how
 * far the nearest it hears is (the e-puck's range, 800 mm, when it hears no one).
 */
public final class Aggregate implements RobotControl {
    /** Cruising speed, mm/s: twice it, a wheel's fastest in a turn, within an e-puck's 129 mm/s. */
    public static final double SPEED = 60;
    /** A proximity reading above this is something close. */
    public static final double NEAR = 0.5;
    /** How far an e-puck's messages carry, mm. */
    private static final double RANGE_MM = 800;
    /** The range-and-bearing message's fields before its bytes: range, bearing. */
    private static final int HEAD = 2;

    @Override
    public void run(Robot robot) throws InterruptedException {
        double stopMm = robot.parameter("stopMm", 120.0);
        robot.setRabData(1, 0); // (an e-puck's message: 2 bytes)
        robot.step(); // (readings come with a step: none before the first)
        while (true) {
            double[] heard = robot.sensor("rab");
            double[] near = robot.sensor("proximity");
            int width = HEAD + 2; // (an e-puck's message: 2 bytes)
            double x = 0;
            double y = 0;
            double nearest = Double.POSITIVE_INFINITY;
            int n = heard.length / width;
            for (int m = 0; m < n; m++) {
                double bearing = Math.toRadians(heard[m * width + 1]);
                x += Math.cos(bearing);
                y += Math.sin(bearing);
                nearest = Math.min(nearest, heard[m * width]);
            }
            robot.report("nearestMm", n == 0 ? RANGE_MM : nearest);
            int half = near.length / 2;
            double left = 0;
            double right = 0;
            for (int k = 0; k < half; k++) { // (the e-puck's rays: the left half first, then the right)
                left = Math.max(left, near[k]);
                right = Math.max(right, near[near.length - 1 - k]);
            }
            if (nearest < stopMm) {
                robot.setWheelSpeeds(0, 0);
            } else if (Math.max(left, right) > NEAR) {
                robot.setWheelSpeeds(left > right ? SPEED : -SPEED, left > right ? -SPEED : SPEED);
            } else if (n == 0) {
                robot.setWheelSpeeds(SPEED, SPEED);
            } else {
                double turn = Math.atan2(y, x) / Math.PI; // (-1 .. 1: right round to left round)
                robot.setWheelSpeeds(SPEED * (1 - turn), SPEED * (1 + turn));
            }
            robot.step();
        }
    }
}

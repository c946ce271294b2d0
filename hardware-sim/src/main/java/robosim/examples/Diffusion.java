package robosim.examples;

import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * ARGoS's footbot_diffusion (its examples' obstacle avoidance), on a foot-bot: the mean of its proximity
 * ring's readings as vectors (each its value along its ray's angle); while that vector's angle is within {@code alpha}
 * degrees of ahead (7.5 by default) and its length under {@code delta} (0.1), straight on at {@code velocity} mm/s
 * (50, ARGoS's 5 cm/s) on both wheels, else a turn away on one wheel (the obstacle on the left: the left wheel
 * drives). Without chance. It sends a range-and-bearing message every step where it has the device (the bench's
 * foot-bots: bench/footbots-100.xml, where ARGoS runs the same world, bench/footbots-100.argos).
 */
public final class Diffusion implements RobotControl {
    /** A foot-bot's message size, bytes. */
    private static final int RAB_BYTES = 10;
    /** The first proximity ray's angle (the foot-bot's: 7.5 degrees, then every 360 / count). */
    private static final double ANGLE0_DEG = 7.5;

    @Override
    public void run(Robot robot) throws InterruptedException {
        double alpha = Math.toRadians(robot.parameter("alpha", 7.5));
        double delta = robot.parameter("delta", 0.1);
        double v = robot.parameter("velocity", 50.0);
        if (robot.actuatorNames().contains("rab")) {
            robot.actuate("rab", new double[RAB_BYTES]); // (zeros, as ARGoS's device sends before it is set)
        }
        robot.step(); // (readings come with a step: none before the first)
        while (true) {
            double[] near = robot.sensor("proximity");
            double x = 0;
            double y = 0;
            for (int k = 0; k < near.length; k++) {
                double a = Math.toRadians(ANGLE0_DEG + k * 360.0 / near.length);
                x += near[k] * Math.cos(a);
                y += near[k] * Math.sin(a);
            }
            x /= near.length;
            y /= near.length;
            double angle = Math.atan2(y, x);
            if (Math.abs(angle) <= alpha && Math.hypot(x, y) < delta) {
                robot.setWheelSpeeds(v, v);
            } else if (angle > 0) {
                robot.setWheelSpeeds(v, 0);
            } else {
                robot.setWheelSpeeds(0, v);
            }
            robot.step();
        }
    }
}

package robosim.examples;

import robosim.api.Colours;
import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * Kilobots finding a light by run and tumble (test-envs/kilobots.xml): a kilobot has one ambient light sensor and no
 * sense of direction, so it drives straight on while the light grows and, when it fades (or has not grown for a
 * while: something in the way), turns in place for a while (a number of steps of its own, from its name) before
 * trying again. Within {@code arriveAt} (600 of 1024 by default)
 * it stops and lights its LED green; on the way it is red. Each step it reports {@code light}.
 */
public final class Phototaxis implements RobotControl {
    /** Steps a tumble takes at least; a robot's own adds up to as many again. */
    public static final int TUMBLE_STEPS = 10;
    /** How far below the brightest since the last tumble the light may fall before it tumbles (its ADC's steps). */
    public static final double FADE = 2;
    /** Steps without a brighter reading before it tumbles (a wall or another kilobot in the way). */
    public static final int STALE_STEPS = 30;

    @Override
    public void run(Robot robot) throws InterruptedException {
        double arriveAt = robot.parameter("arriveAt", 600.0);
        int tumble = TUMBLE_STEPS + Math.floorMod(robot.name().hashCode(), TUMBLE_STEPS);
        double top = robot.velocity();
        robot.setLeds(Colours.RED);
        robot.step(); // (readings come with a step: none before the first)
        double best = -1;
        int stale = 0;
        while (true) {
            double light = robot.sensor("light")[0];
            robot.report("light", light);
            if (light >= arriveAt) {
                robot.setWheelSpeeds(0, 0);
                robot.setLeds(Colours.GREEN);
            } else if (light > best) { // (brighter: on)
                best = light;
                stale = 0;
                robot.setWheelSpeeds(top, top);
            } else if (light < best - FADE || ++stale > STALE_STEPS) { // (fading, or stuck: tumble)
                robot.setWheelSpeeds(top, -top);
                for (int s = 0; s < tumble; s++) {
                    robot.step();
                }
                robot.setWheelSpeeds(top, top);
                best = -1;
                stale = 0;
            }
            robot.step();
        }
    }
}

package robosim.examples;

import robosim.api.Colours;
import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * Kilobots finding a light by run and tumble (test-envs/kilobots.xml): a kilobot has one ambient light sensor and no
 * sense of direction, so it drives straight on while the light grows and, when it fades, turns in place for a while
 * (a number of steps of its own, from its name) before trying again. Within {@code arriveAt} (600 of 1024 by default)
 * it stops and lights its LED green; on the way it is red. Each step it reports {@code light}.
 */
public final class Phototaxis implements RobotControl {
    /** Steps a tumble takes at least; a robot's own adds up to as many again. */
    public static final int TUMBLE_STEPS = 10;

    @Override
    public void run(Robot robot) throws InterruptedException {
        double arriveAt = robot.parameter("arriveAt", 600.0);
        int tumble = TUMBLE_STEPS + Math.floorMod(robot.name().hashCode(), TUMBLE_STEPS);
        double top = robot.velocity();
        robot.setLeds(Colours.RED);
        robot.step(); // (readings come with a step: none before the first)
        double before = robot.sensor("light")[0];
        while (true) {
            double light = robot.sensor("light")[0];
            robot.report("light", light);
            if (light >= arriveAt) {
                robot.setWheelSpeeds(0, 0);
                robot.setLeds(Colours.GREEN);
            } else if (light >= before) {
                robot.setWheelSpeeds(top, top);
            } else {
                robot.setWheelSpeeds(top, -top);
                for (int s = 0; s < tumble; s++) {
                    robot.step();
                }
                robot.setWheelSpeeds(top, top);
            }
            before = light;
            robot.step();
        }
    }
}

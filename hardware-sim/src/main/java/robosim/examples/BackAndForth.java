package robosim.examples;

import robosim.api.Robot;
import robosim.api.RobotControl;

/** The original report's benchmark: forward 10 m, turn 180 degrees, back 10 m, forever. */
public final class BackAndForth implements RobotControl {
    public static final double LEG_MM = 10_000;

    @Override
    public void run(Robot robot) throws InterruptedException {
        while (true) {
            robot.move(LEG_MM);
            robot.turn(180);
        }
    }
}

package robosim.runner;

import robosim.api.Robot;
import robosim.api.RobotControl;

/** Control code that stands still, taking the parameter {@code dawdle_ms} of real time over each step. */
public final class Dawdler implements RobotControl {
    @Override
    public void run(Robot robot) throws InterruptedException {
        long ms = (long) robot.parameter("dawdle_ms", 0.0);
        while (true) {
            Thread.sleep(ms);
            robot.sleep(1);
        }
    }
}

package robosim.runner;

import robosim.api.Robot;
import robosim.api.RobotControl;

/** Test control code with a bug: its first step's decision throws out of {@code run}. */
public final class ThrowsAtOnce implements RobotControl {
    @Override
    public void run(Robot robot) throws InterruptedException {
        robot.sleep(1);
        throw new IllegalStateException("a bug in " + robot.name() + "'s control code");
    }
}

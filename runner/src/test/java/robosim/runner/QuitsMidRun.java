package robosim.runner;

import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * Control code that drives 40 steps and then ends its whole robot process at once, as a crash would:
 * the Environment sees the connection close mid-run and removes the robot.
 */
public final class QuitsMidRun implements RobotControl {
    static final int MOVES = 40;

    @Override
    public void run(Robot robot) throws InterruptedException {
        for (int i = 0; i < MOVES; i++) {
            robot.move(10);
        }
        Runtime.getRuntime().halt(0);
    }
}

package robosim.runner;

import java.util.concurrent.CountDownLatch;
import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * Control code that drives 10 steps and then never calls the robot again (stuck in a computation of
 * its own): robots sharing its process go on, and the Environment removes it after the step timeout.
 */
public final class StopsYielding implements RobotControl {
    @Override
    public void run(Robot robot) throws InterruptedException {
        for (int i = 0; i < 10; i++) {
            robot.move(10);
        }
        new CountDownLatch(1).await(); // until the end of the run interrupts it
    }
}

package robosim.runner;

import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * Control code with static state: the n-th run of this class in a JVM moves its robot n times 100 mm, then stands.
 * In a JVM of its own every run is the first; a warm JVM's runs must be too (their classes are loaded afresh).
 */
public final class CountsItsRuns implements RobotControl {
    private static int runs;

    @Override
    public void run(Robot robot) throws InterruptedException {
        int n = ++runs;
        robot.move(100 * n);
        while (true) {
            robot.sleep(1);
        }
    }
}

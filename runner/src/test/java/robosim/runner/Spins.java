package robosim.runner;

import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * Control code that drives 3 steps and then computes without calling the robot again, for up to 60 s of real time
 * (its JVM ends before that): on one carrier of virtual threads it keeps everything else off it, the loop included.
 */
public final class Spins implements RobotControl {
    private static volatile long sink;

    @Override
    public void run(Robot robot) throws InterruptedException {
        for (int i = 0; i < 3; i++) {
            robot.move(10);
        }
        long until = System.nanoTime() + 60_000_000_000L;
        long x = 1;
        while (System.nanoTime() < until) {
            x ^= x << 13;
            x ^= x >>> 7;
            x ^= x << 17;
        }
        sink = x;
    }
}

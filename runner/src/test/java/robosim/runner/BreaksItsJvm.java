package robosim.runner;

import java.util.concurrent.locks.LockSupport;
import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * Control code that breaks the JVM it runs in when its parameter {@code mode} says so: {@code exit} calls
 * {@code System.exit(7)} in its first step, {@code leave} starts a thread that never ends; anything else stands
 * still, as a good run does.
 */
public final class BreaksItsJvm implements RobotControl {
    @Override
    public void run(Robot robot) throws InterruptedException {
        String mode = robot.parameter("mode", "stand");
        robot.sleep(1);
        if (mode.equals("exit")) {
            System.exit(7);
        } else if (mode.equals("leave")) {
            Thread left = new Thread(() -> {
                while (true) {
                    LockSupport.park();
                }
            }, "never-ends");
            left.start();
        }
        while (true) {
            robot.sleep(1);
        }
    }
}

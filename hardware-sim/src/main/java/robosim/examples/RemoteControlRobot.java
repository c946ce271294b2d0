package robosim.examples;

import robosim.api.Message;
import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * A robot a person or a program drives: it waits for commands and carries them out one by one.
 * Commands arrive as text, "forward MM", "back MM", "left DEG", "right DEG", "stop"; here from any
 * robot's messages (the Remote Control's network link feeds the same commands). An unknown command
 * is ignored. The robot reports each finished command to its sender as "done COMMAND".
 */
public final class RemoteControlRobot implements RobotControl {
    @Override
    public void run(Robot robot) throws InterruptedException {
        while (true) {
            Message m = robot.waitForMessage(60_000);
            if (m == null) {
                continue;
            }
            if (execute(robot, m.text())) {
                robot.send(m.from(), "done " + m.text());
            }
        }
    }

    /** Carries out one command; false if it is not one. */
    static boolean execute(Robot robot, String command) throws InterruptedException {
        String[] w = command.trim().split("\\s+");
        try {
            switch (w[0]) {
                case "forward" -> robot.move(Double.parseDouble(w[1]));
                case "back" -> robot.move(-Double.parseDouble(w[1]));
                case "left" -> robot.turn(Double.parseDouble(w[1]));
                case "right" -> robot.turn(-Double.parseDouble(w[1]));
                case "stop" -> robot.sleep(1);
                default -> {
                    return false;
                }
            }
        } catch (ArrayIndexOutOfBoundsException | IllegalArgumentException e) {
            return false; // missing, not a number, or not finite ("forward NaN"): not a command
        }
        return true;
    }
}

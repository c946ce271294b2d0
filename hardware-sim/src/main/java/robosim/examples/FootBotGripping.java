package robosim.examples;

import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * ARGoS's footbot_gripping (examples/argos/gripping.xml), by its step counter: 69 steps forward at 5 cm/s to the
 * cylinder ahead, then in step 70 it stops and grips, 49 steps back dragging the cylinder, 50 more back having let
 * it go, then it stops for good. It reports {@code gripped} (1 while it holds something, else 0) every step.
 */
public final class FootBotGripping implements RobotControl {
    /** ARGoS's 5 cm/s, mm/s. */
    static final double SPEED = 50;

    @Override
    public void run(Robot robot) throws InterruptedException {
        for (int counter = 1; ; counter++) {
            if (counter < 70) {
                robot.setWheelSpeeds(SPEED, SPEED);
            } else if (counter == 70) {
                robot.setWheelSpeeds(0, 0);
                robot.grip(); // (its step is this counter's)
                robot.report("gripped", robot.gripped().isEmpty() ? 0 : 1);
                continue;
            } else if (counter < 120) {
                robot.setWheelSpeeds(-SPEED, -SPEED);
            } else if (counter == 120) {
                robot.release(); // (the backwards motion goes on: its step is this counter's)
                robot.report("gripped", 0);
                continue;
            } else if (counter >= 170) {
                robot.setWheelSpeeds(0, 0);
            }
            robot.step();
            robot.report("gripped", robot.gripped().isEmpty() ? 0 : 1);
        }
    }
}

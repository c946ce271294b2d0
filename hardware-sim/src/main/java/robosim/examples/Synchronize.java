package robosim.examples;

import robosim.api.Colours;
import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * Fireflies (ARGoS's synchronization example, test-envs/synchronization.xml): each foot-bot counts the steps of a
 * period ({@code period}, 30 by default) from a start of its own (its name's), flashes its LEDs yellow for the step its
 * count is 0, and, seeing another's flash in its camera in the second half of its count, takes that flash for its own
 * (its count goes on from it). The flashes fall into step within a few periods. Meanwhile it drives straight on,
 * turning away from what its proximity ring sees; each step it reports {@code flashing} (1 or 0), so a recording's
 * reports show the flashes come together.
 */
public final class Synchronize implements RobotControl {
    /** Cruising speed, mm/s. */
    public static final double SPEED = 100;
    /** A proximity reading above this, summed over a side, is something close. */
    public static final double NEAR = 0.3;

    @Override
    public void run(Robot robot) throws InterruptedException {
        int period = (int) robot.parameter("period", 30.0);
        int count = Math.floorMod(robot.name().hashCode(), period);
        robot.step(); // (readings come with a step: none before the first)
        while (true) {
            double[] blobs = robot.sensor("camera"); // (colour, distance, angle) a blob
            boolean seen = false;
            for (int b = 0; b + 2 < blobs.length; b += 3) {
                seen |= (int) blobs[b] == Colours.YELLOW;
            }
            count = seen && count > period / 2 ? 1 : (count + 1) % period; // (seen: in step with that flash)
            robot.setLeds(count == 0 ? Colours.YELLOW : Colours.BLACK);
            robot.report("flashing", count == 0 ? 1 : 0);
            double[] near = robot.sensor("proximity");
            double left = 0;
            double right = 0;
            for (int k = 0; k < 6; k++) {
                left += near[k];
                right += near[23 - k];
            }
            if (Math.max(left, right) > NEAR) {
                robot.setWheelSpeeds(left > right ? SPEED : -SPEED, left > right ? -SPEED : SPEED);
            } else {
                robot.setWheelSpeeds(SPEED, SPEED);
            }
            robot.step();
        }
    }
}

package robosim.examples;

import java.util.SplittableRandom;
import robosim.api.Colours;
import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * ARGoS's footbot_synchronization (examples/argos/synchronization.xml): a counter that starts anywhere in [0, 100)
 * (from the robot's seed), grows by one a step, or by a tenth of itself in a step whose camera sees a red blob (a
 * flash of another's: Strogatz's jump, as ARGoS's example simplifies it); past {@code countMax} (100) the robot lights
 * its LEDs red for one step and starts again from 0. Standing still, the robots' flashes fall into step. Each step
 * it reports {@code flashing} (1 in the step it lights, else 0).
 */
public final class FootBotSynchronization implements RobotControl {
    @Override
    public void run(Robot robot) throws InterruptedException {
        int most = (int) robot.parameter("countMax", 100.0);
        int counter = new SplittableRandom(robot.seed()).nextInt(most);
        robot.step(); // (readings come with a step: none before the first)
        while (true) {
            double[] blobs = robot.sensor("camera"); // (colour, distance, angle) a blob
            boolean flashed = false;
            for (int b = 0; b + 2 < blobs.length && !flashed; b += 3) {
                flashed = (int) blobs[b] == Colours.RED;
            }
            counter += flashed ? counter / 10 : 1;
            boolean flash = counter > most;
            if (flash) {
                counter = 0;
            }
            robot.setLeds(flash ? Colours.RED : Colours.BLACK);
            robot.report("flashing", flash ? 1 : 0);
            robot.step();
        }
    }
}

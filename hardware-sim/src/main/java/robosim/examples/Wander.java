package robosim.examples;

import java.util.Random;
import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * Sonar-based obstacle avoidance: drive ahead in legs of {@link #LEG_MM}; when a sonar facing within 60
 * degrees of ahead reads closer than {@link #CLEARANCE_MM}, turn away towards the more open side by
 * 30 to 90 degrees. The turn sizes come from a generator seeded by {@link Robot#seed()} (the run's seed and the
 * robot's name), so runs with the same seed repeat. Its speed is the parameter {@code speed} (mm/s, e.g.
 * {@code <param name="speed" value="300"/>}; default: the robot's set velocity). It reports how often it has
 * turned away ({@code turns}, for a sweep's table). Subclasses may act once a step ({@link #everyStep}).
 */
public class Wander implements RobotControl {
    /** How close an obstacle ahead may come before the robot turns away, mm (from the sonar). */
    public static final double CLEARANCE_MM = 600;
    /** Length of one leg ahead, mm: one step at 500 mm/s and 500 ms steps. */
    public static final double LEG_MM = 250;

    @Override
    public void run(Robot robot) throws InterruptedException {
        Random random = new Random(robot.seed());
        robot.setVelocity(robot.parameter("speed", robot.velocity()));
        double[] angles = robot.sonarAnglesDeg();
        robot.sleep(1);
        int turns = 0;
        while (true) {
            everyStep(robot);
            Surroundings around = Surroundings.of(angles, robot.sonarRanges());
            if (around.aheadMm() < CLEARANCE_MM) {
                double by = 30 + random.nextInt(61);
                robot.turn(around.leftMm() >= around.rightMm() ? by : -by);
                robot.report("turns", ++turns);
            } else {
                robot.move(LEG_MM);
            }
        }
    }

    /** Called once before each step's decision; does nothing here. */
    protected void everyStep(Robot robot) throws InterruptedException {
    }
}

package robosim.examples;

import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * Drives ahead in legs of {@link #LEG_MM} and, when a sonar facing within 60 degrees of ahead reads closer than
 * {@link #CLEARANCE_MM}, turns {@link #TURN_DEG} towards the more open side: {@link Wander} without chance, so one
 * world gives one run whatever the seed. Written twice, here and in Python ({@code examples/python/bounce.py}), as
 * the same robot in two languages: the two give byte-identical pose logs (the runner's {@code PythonControlIT}).
 * It reports how often it has turned ({@code turns}).
 */
public final class Bounce implements RobotControl {
    /** How close an obstacle ahead may come before the robot turns, mm. */
    public static final double CLEARANCE_MM = 600;
    /** Length of one leg ahead, mm. */
    public static final double LEG_MM = 250;
    /** How far it turns away, degrees. */
    public static final double TURN_DEG = 45;

    @Override
    public void run(Robot robot) throws InterruptedException {
        robot.setVelocity(robot.parameter("speed", robot.velocity()));
        double[] angles = robot.sonarAnglesDeg();
        int turns = 0;
        while (true) {
            Surroundings around = Surroundings.of(angles, robot.sonarRanges());
            if (around.aheadMm() < CLEARANCE_MM) {
                robot.turn(around.leftMm() >= around.rightMm() ? TURN_DEG : -TURN_DEG);
                robot.report("turns", ++turns);
            } else {
                robot.move(LEG_MM);
            }
        }
    }
}

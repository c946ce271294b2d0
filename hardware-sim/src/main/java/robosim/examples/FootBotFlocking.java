package robosim.examples;

import robosim.api.Colours;
import robosim.api.Robot;
import robosim.api.RobotControl;

/**
 * ARGoS's footbot_flocking (examples/argos/flocking.xml): each foot-bot lights its beacon red and drives along the sum
 * of two vectors: toward the light (a quarter of its top speed long) and the flocking vector, the mean over the red
 * blobs its omnidirectional camera sees nearer than 1.8 target distances of a generalized Lennard-Jones pull or push,
 * {@code -gain / d * ((target / d)^(2 exponent) - (target / d)^exponent)}, clamped to its top speed; the wheels as
 * ARGoS's SetWheelSpeedsFromVector sets them (no turn, soft turn, hard turn, with hysteresis). Worked in ARGoS's units
 * (cm, cm/s), so its parameters are the ARGoS file's by the same names ({@code <param>}: {@code max_speed} 10,
 * {@code target_distance} 75, {@code gain} 1000, {@code exponent} 2, the turning thresholds 90, 70, 10 degrees); the
 * wheels are set in mm/s ({@code exponent} a whole number). Readings: light, 24 from 7.5 degrees every 15; camera
 * blobs (colour, mm, degrees). Its angles and lengths are {@link PortableMath}'s, so that its Python twin,
 * {@code examples/python/argos_flocking.py}, gives the same pose log.
 */
public final class FootBotFlocking implements RobotControl {
    private static final int BEACON = 12;
    private static final double MM_PER_CM = 10;

    @Override
    public void run(Robot robot) throws InterruptedException {
        WheelTurning wheels = new WheelTurning(robot, 10.0, MM_PER_CM);
        double maxSpeed = wheels.maxSpeed();
        double target = robot.parameter("target_distance", 75.0);
        double gain = robot.parameter("gain", 1000.0);
        double exponent = robot.parameter("exponent", 2.0);
        if (exponent != Math.rint(exponent) || exponent < 0) {
            throw new IllegalArgumentException("exponent is a whole number >= 0 here, got " + exponent);
        }
        robot.setLed(BEACON, Colours.RED);
        robot.step(); // (readings come with a step: none before the first)
        while (true) {
            double[] light = FootBotRing.sum(robot.sensor("light"));
            double lx = light[0];
            double ly = light[1];
            double ll = PortableMath.length(lx, ly);
            if (ll > 0) {
                lx *= 0.25 * maxSpeed / ll;
                ly *= 0.25 * maxSpeed / ll;
            }
            double[] blobs = robot.sensor("camera"); // (colour, distance mm, angle deg) a blob
            double fx = 0;
            double fy = 0;
            int seen = 0;
            for (int b = 0; b + 2 < blobs.length; b += 3) {
                double d = blobs[b + 1] / MM_PER_CM;
                if ((int) blobs[b] == Colours.RED && d < target * 1.80) {
                    double norm = PortableMath.power(target / d, (int) exponent);
                    double lj = -gain / d * (norm * norm - norm);
                    double a = PortableMath.RADIANS_PER_DEGREE * blobs[b + 2];
                    fx += lj * PortableMath.cos(a);
                    fy += lj * PortableMath.sin(a);
                    seen++;
                }
            }
            if (seen > 0) {
                fx /= seen;
                fy /= seen;
                double fl = PortableMath.length(fx, fy);
                if (fl > maxSpeed) {
                    fx *= maxSpeed / fl;
                    fy *= maxSpeed / fl;
                }
            }
            wheels.drive(robot, lx + fx, ly + fy);
            robot.step();
        }
    }
}

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
    private static final double ANGLE0_DEG = 7.5;
    private static final double STEP_DEG = 15;
    private static final int BEACON = 12;
    private static final double MM_PER_CM = 10;

    private enum Turning { NO_TURN, SOFT_TURN, HARD_TURN }

    /** The direction of each light reading, ARGoS's: from 7.5 degrees every 15. */
    private static final double[] COS = new double[24];
    private static final double[] SIN = new double[24];

    static {
        for (int k = 0; k < 24; k++) {
            COS[k] = PortableMath.cos(PortableMath.RADIANS_PER_DEGREE * (ANGLE0_DEG + k * STEP_DEG));
            SIN[k] = PortableMath.sin(PortableMath.RADIANS_PER_DEGREE * (ANGLE0_DEG + k * STEP_DEG));
        }
    }

    private Turning turning = Turning.NO_TURN;

    @Override
    public void run(Robot robot) throws InterruptedException {
        double hardTurn = PortableMath.RADIANS_PER_DEGREE * robot.parameter("hard_turn_angle_threshold", 90.0);
        double softTurn = PortableMath.RADIANS_PER_DEGREE * robot.parameter("soft_turn_angle_threshold", 70.0);
        double noTurn = PortableMath.RADIANS_PER_DEGREE * robot.parameter("no_turn_angle_threshold", 10.0);
        double maxSpeed = robot.parameter("max_speed", 10.0);
        double target = robot.parameter("target_distance", 75.0);
        double gain = robot.parameter("gain", 1000.0);
        double exponent = robot.parameter("exponent", 2.0);
        if (exponent != Math.rint(exponent) || exponent < 0) {
            throw new IllegalArgumentException("exponent is a whole number >= 0 here, got " + exponent);
        }
        robot.setLed(BEACON, Colours.RED);
        robot.step(); // (readings come with a step: none before the first)
        while (true) {
            double[] light = robot.sensor("light");
            double lx = 0;
            double ly = 0;
            for (int k = 0; k < light.length; k++) {
                lx += light[k] * COS[k];
                ly += light[k] * SIN[k];
            }
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
            wheels(robot, lx + fx, ly + fy, maxSpeed, hardTurn, softTurn, noTurn);
            robot.step();
        }
    }

    /** ARGoS's SetWheelSpeedsFromVector, in cm/s, set in mm/s. */
    private void wheels(Robot robot, double x, double y, double maxSpeed, double hardTurn, double softTurn,
            double noTurn) {
        double angle = PortableMath.angle(y, x);
        double base = Math.min(PortableMath.length(x, y), maxSpeed);
        double a = Math.abs(angle);
        if (turning == Turning.HARD_TURN && a <= softTurn) {
            turning = Turning.SOFT_TURN;
        }
        if (turning == Turning.SOFT_TURN) {
            if (a > hardTurn) {
                turning = Turning.HARD_TURN;
            } else if (a <= noTurn) {
                turning = Turning.NO_TURN;
            }
        }
        if (turning == Turning.NO_TURN) {
            if (a > hardTurn) {
                turning = Turning.HARD_TURN;
            } else if (a > noTurn) {
                turning = Turning.SOFT_TURN;
            }
        }
        double speed1;
        double speed2;
        switch (turning) {
            case NO_TURN -> {
                speed1 = base;
                speed2 = base;
            }
            case SOFT_TURN -> {
                double factor = (hardTurn - a) / hardTurn;
                speed1 = base - base * (1 - factor);
                speed2 = base + base * (1 - factor);
            }
            default -> {
                speed1 = -maxSpeed;
                speed2 = maxSpeed;
            }
        }
        if (angle > 0) {
            robot.setWheelSpeeds(speed1 * MM_PER_CM, speed2 * MM_PER_CM);
        } else {
            robot.setWheelSpeeds(speed2 * MM_PER_CM, speed1 * MM_PER_CM);
        }
    }
}

package robosim.examples;

import robosim.api.Robot;

/**
 * ARGoS's SetWheelSpeedsFromVector, as its foraging and flocking foot-bots steer: toward a vector (x ahead, y left),
 * at its length up to the top speed, with no turn, a soft turn (one wheel slower, one faster) or a hard turn (the
 * wheels opposite, at the top speed), switching between them with hysteresis at ARGoS's thresholds. One per robot: it
 * keeps the turning mechanism it is in. Its angles and lengths are {@link PortableMath}'s, so that its Python twin
 * ({@code examples/python/argos_wheels.py}) sets the same speeds.
 */
public final class WheelTurning {
    private enum Mechanism { NO_TURN, SOFT_TURN, HARD_TURN }

    private final double hardTurn;
    private final double softTurn;
    private final double noTurn;
    private final double maxSpeed;
    private final double scale;
    private Mechanism mechanism = Mechanism.NO_TURN;

    /**
     * The thresholds from the robot's parameters by ARGoS's names ({@code hard_turn_angle_threshold} 90,
     * {@code soft_turn_angle_threshold} 70, {@code no_turn_angle_threshold} 10, degrees) and its top speed
     * {@code max_speed} ({@code defaultMaxSpeed} when the world gives none), in the controller's units; {@code scale}:
     * mm/s a unit of them (1 for mm/s, 10 for ARGoS's cm/s).
     */
    public WheelTurning(Robot robot, double defaultMaxSpeed, double scale) {
        this.hardTurn = PortableMath.RADIANS_PER_DEGREE * robot.parameter("hard_turn_angle_threshold", 90.0);
        this.softTurn = PortableMath.RADIANS_PER_DEGREE * robot.parameter("soft_turn_angle_threshold", 70.0);
        this.noTurn = PortableMath.RADIANS_PER_DEGREE * robot.parameter("no_turn_angle_threshold", 10.0);
        this.maxSpeed = robot.parameter("max_speed", defaultMaxSpeed);
        this.scale = scale;
    }

    /** The top speed, in the controller's units. */
    public double maxSpeed() {
        return maxSpeed;
    }

    /** Sets {@code robot}'s wheels to steer toward (x, y). */
    public void drive(Robot robot, double x, double y) {
        double angle = PortableMath.angle(y, x);
        double base = Math.min(PortableMath.length(x, y), maxSpeed);
        double a = Math.abs(angle);
        if (mechanism == Mechanism.HARD_TURN && a <= softTurn) {
            mechanism = Mechanism.SOFT_TURN;
        }
        if (mechanism == Mechanism.SOFT_TURN) {
            if (a > hardTurn) {
                mechanism = Mechanism.HARD_TURN;
            } else if (a <= noTurn) {
                mechanism = Mechanism.NO_TURN;
            }
        }
        if (mechanism == Mechanism.NO_TURN) {
            if (a > hardTurn) {
                mechanism = Mechanism.HARD_TURN;
            } else if (a > noTurn) {
                mechanism = Mechanism.SOFT_TURN;
            }
        }
        double speed1;
        double speed2;
        switch (mechanism) {
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
            robot.setWheelSpeeds(speed1 * scale, speed2 * scale);
        } else {
            robot.setWheelSpeeds(speed2 * scale, speed1 * scale);
        }
    }
}

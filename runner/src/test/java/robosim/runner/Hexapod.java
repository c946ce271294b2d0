package robosim.runner;

import robosim.devices.Body;
import robosim.devices.RobotType;

/** A robot type that exists only in the tests, named by its class: radius 300 mm, six sonars all round. */
public final class Hexapod extends RobotType {
    static final double RADIUS_MM = 300;

    public Hexapod() {
        this(RADIUS_MM);
    }

    Hexapod(double radiusMm) {
        super(Hexapod.class.getName(), "a test's six-legged robot", new Body(radiusMm, 600, 120),
                ring(radiusMm, 20, 4000, 0, 60, 120, 180, 240, 300));
    }
}

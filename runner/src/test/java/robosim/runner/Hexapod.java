package robosim.runner;

import java.util.ArrayList;
import java.util.List;
import robosim.hardware.RobotType;
import robosim.protocol.RobotProperties;
import robosim.protocol.SonarSpec;

/** A robot type that exists only in the tests: one class, radius 300 mm, six sonars all round. */
public final class Hexapod extends RobotType {
    static final double RADIUS_MM = 300;

    private final double radiusMm;

    public Hexapod() {
        this(RADIUS_MM);
    }

    Hexapod(double radiusMm) {
        this.radiusMm = radiusMm;
    }

    @Override
    public RobotProperties properties() {
        List<SonarSpec> sonars = new ArrayList<>();
        for (int i = 0; i < 6; i++) {
            sonars.add(SonarSpec.onRim(radiusMm, i * 60, 20, 4000));
        }
        return new RobotProperties(Hexapod.class.getName(), radiusMm, 600, 120, sonars);
    }
}

package robosim.devices;

import com.google.auto.service.AutoService;
import java.util.List;

/**
 * {@code bump}: which sides of the robot touch something at the end of the step, a wall, an obstacle or another
 * robot within {@code toleranceMm} of its rim. Front is within 45 degrees of the heading, left 45 to 135 degrees
 * counter-clockwise, and so on; a contact exactly at 45 degrees counts as front.
 */
@AutoService(RobotSensor.class)
public final class BumpSensor extends RobotSensor {
    private static final Attribute TOLERANCE = Attribute.number("toleranceMm", 1, "mm", "how near the rim a touch "
            + "counts").atLeast(0);
    private static final Attribute NOISE = Attribute.noise("");

    private double toleranceMm;
    private double noise;
    private final double[] directions = new double[64];

    public BumpSensor() {
        super(new SensorInfo("bump", "which sides of the robot touch something", List.of(TOLERANCE, NOISE),
                "four values, front, left, back and right: 1 touching, 0 not", "", false, SensorInfo.Display.SIDES));
        configure(new Attributes(java.util.Map.of()));
    }

    @Override
    protected void configure(Attributes a) {
        toleranceMm = TOLERANCE.read(a);
        noise = NOISE.read(a);
    }

    @Override
    public SensorValues values() {
        return new SensorValues(4, 0, 1, "");
    }

    @Override
    public double[] generateSensorResponse(SensorContext c) {
        double[] sides = new double[4];
        int n = c.touching(toleranceMm, directions);
        for (int k = 0; k < n; k++) {
            double rel = (directions[k] - c.headingDeg()) % 360;
            if (rel > 180) {
                rel -= 360;
            } else if (rel <= -180) {
                rel += 360;
            }
            int side = Math.abs(rel) <= 45 ? 0 : rel > 45 && rel < 135 ? 1 : rel < -45 && rel > -135 ? 3 : 2;
            sides[side] = 1;
        }
        for (int s = 0; s < 4; s++) {
            sides[s] = noisy(sides[s], noise, c, 0, 1);
        }
        return sides;
    }
}

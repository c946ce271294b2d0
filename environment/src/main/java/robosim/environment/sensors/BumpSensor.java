package robosim.environment.sensors;

/**
 * Which sides of the robot touch something at the end of the step, a wall, an obstacle or another
 * robot within {@code toleranceMm} (default 1 mm) of its rim: values {front, left, back, right}, 1 for
 * touching, 0 for not. Front is within 45 degrees of the heading, left 45 to 135 degrees
 * counter-clockwise, and so on; a contact exactly at 45 degrees counts as front.
 */
public final class BumpSensor extends RobotSensor {
    private double toleranceMm;
    private final double[] directions = new double[64];

    public BumpSensor() {
        configure(new SensorParameters(java.util.Map.of()));
    }

    @Override
    protected void configure(SensorParameters p) {
        toleranceMm = p.number("toleranceMm", 1);
        if (!(toleranceMm >= 0)) {
            throw new IllegalArgumentException("toleranceMm must be >= 0, got " + toleranceMm);
        }
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
        return sides;
    }
}

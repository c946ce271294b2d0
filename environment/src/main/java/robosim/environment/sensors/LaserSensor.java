package robosim.environment.sensors;

/**
 * A laser range finder at the robot's centre: one beam every {@code resolutionDeg} across
 * {@code fovDeg} centred on the heading (defaults 1 and 180, so 181 beams), each reading the
 * distance in mm to the first wall or robot, capped at {@code rangeM} (default 8 m). Values run from
 * the rightmost beam (heading - fov/2) to the leftmost.
 */
public final class LaserSensor extends RobotSensor {
    private double fovDeg;
    private double resolutionDeg;
    private double rangeMm;
    private int beams;

    @Override
    protected void configure(SensorParameters p) {
        fovDeg = p.number("fovDeg", 180);
        resolutionDeg = p.number("resolutionDeg", 1);
        rangeMm = p.number("rangeM", 8) * 1000;
        if (!(fovDeg > 0 && fovDeg <= 360)) {
            throw new IllegalArgumentException("fovDeg must be in (0, 360], got " + fovDeg);
        }
        if (!(resolutionDeg > 0)) {
            throw new IllegalArgumentException("resolutionDeg must be > 0, got " + resolutionDeg);
        }
        if (!(rangeMm > 0)) {
            throw new IllegalArgumentException("rangeM must be > 0, got " + rangeMm / 1000);
        }
        double count = Math.floor(fovDeg / resolutionDeg + 1e-9) + (fovDeg >= 360 ? 0 : 1);
        if (count > robosim.protocol.Limits.MAX_SENSOR_VALUES) {
            throw new IllegalArgumentException("fovDeg / resolutionDeg gives " + (long) count + " beams, more than "
                    + robosim.protocol.Limits.MAX_SENSOR_VALUES);
        }
        beams = (int) count;
    }

    public LaserSensor() {
        configure(new SensorParameters(java.util.Map.of()));
    }

    @Override
    public double[] generateSensorResponse(SensorContext c) {
        double[] ranges = new double[beams];
        double first = c.headingDeg() - fovDeg / 2;
        for (int b = 0; b < beams; b++) {
            ranges[b] = c.ray(first + b * resolutionDeg, rangeMm);
        }
        return ranges;
    }
}

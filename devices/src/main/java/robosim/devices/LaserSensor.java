package robosim.devices;

import com.google.auto.service.AutoService;
import java.util.List;
import robosim.protocol.Limits;

/**
 * {@code laser}: a laser range finder at the robot's centre: one beam every {@code resolutionDeg} across
 * {@code fovDeg} centred on the heading, each reading the distance to the first wall, obstacle or robot, capped at
 * {@code rangeM}. Values run from the rightmost beam (heading - fov/2) to the leftmost.
 */
@AutoService(RobotSensor.class)
public final class LaserSensor extends RobotSensor {
    private static final Attribute FOV = Attribute.number("fovDeg", 180, "deg", "the field of view, centred on the "
            + "heading").above(0).atMost(360);
    private static final Attribute RESOLUTION = Attribute.number("resolutionDeg", 1, "deg", "the angle between beams")
            .above(0);
    private static final Attribute RANGE = Attribute.number("rangeM", 8, "m", "the farthest a beam reads").above(0);
    private static final Attribute NOISE = Attribute.noise("mm");

    private double fovDeg;
    private double resolutionDeg;
    private double rangeMm;
    private double noiseMm;
    private int beams;

    public LaserSensor() {
        super(new SensorInfo("laser", "a laser range finder at the robot's centre", List.of(FOV, RESOLUTION, RANGE,
                NOISE), "the distance along each beam to the first wall, obstacle or robot, mm, from the rightmost beam "
                + "(heading - fovDeg/2) to the leftmost, one every resolutionDeg (181 by default)", "mm", false,
                SensorInfo.Display.RANGES));
        configure(new Attributes(java.util.Map.of()));
    }

    @Override
    protected void configure(Attributes a) {
        fovDeg = FOV.read(a);
        resolutionDeg = RESOLUTION.read(a);
        rangeMm = RANGE.read(a) * 1000;
        noiseMm = NOISE.read(a);
        double count = Math.floor(fovDeg / resolutionDeg + 1e-9) + (fovDeg >= 360 ? 0 : 1);
        if (count > Limits.MAX_SENSOR_VALUES) {
            throw new IllegalArgumentException("fovDeg / resolutionDeg gives " + (long) count + " beams, more than "
                    + Limits.MAX_SENSOR_VALUES);
        }
        beams = (int) count;
    }

    @Override
    public SensorValues values() {
        return new SensorValues(beams, 0, rangeMm, "mm");
    }

    @Override
    public double[] generateSensorResponse(SensorContext c) {
        double[] ranges = new double[beams];
        double first = c.headingDeg() - fovDeg / 2;
        for (int b = 0; b < beams; b++) {
            ranges[b] = noisy(c.ray(first + b * resolutionDeg, rangeMm), noiseMm, c, 0, rangeMm);
        }
        return ranges;
    }
}

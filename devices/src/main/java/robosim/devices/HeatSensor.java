package robosim.devices;

import com.google.auto.service.AutoService;
import java.util.List;

/**
 * {@code heat}: the heat at the robot's centre: the sum, over every heat source the robot can see (no obstacle on
 * the straight line between them), of {@code intensity / (1 + d^2)} with d the distance in metres. At the source a
 * reading equals the intensity; at 1 m it is half; behind a wall it is zero.
 */
@AutoService(RobotSensor.class)
public final class HeatSensor extends RobotSensor {
    private static final Attribute NOISE = Attribute.noise("heat");

    private double noise;

    public HeatSensor() {
        super(new SensorInfo("heat", "the heat of the sources in sight, at the robot's centre", List.of(NOISE),
                "one value: the sum over the heat sources in sight of intensity / (1 + d^2), d in m (0 or more)",
                "heat", false, SensorInfo.Display.VALUES));
    }

    @Override
    protected void configure(Attributes a) {
        noise = NOISE.read(a);
    }

    @Override
    public SensorValues values() {
        return new SensorValues(1, 0, Double.POSITIVE_INFINITY, "heat");
    }

    @Override
    public double[] generateSensorResponse(SensorContext c) {
        double heat = 0;
        for (HeatSource h : c.heatSources()) {
            if (c.clearTo(h.xMm(), h.yMm())) {
                double dM = Math.hypot(h.xMm() - c.xMm(), h.yMm() - c.yMm()) / 1000;
                heat += h.intensity() / (1 + dM * dM);
            }
        }
        return new double[] {noisy(heat, noise, c, 0, Double.POSITIVE_INFINITY)};
    }
}

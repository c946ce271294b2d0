package robosim.devices;

import com.google.auto.service.AutoService;
import java.util.List;
import robosim.protocol.RobotProperties;

/**
 * {@code proximity}: a ring of short-range infrared sensors, one a ray of the robot's type (its {@code RaySpec}s: where
 * on the rim, which way, how far), cast by the Geometry process as sonar is. Each reads 0 with nothing along its ray
 * and rises towards 1 as something comes near, by its model's law (d the distance from the sensor, m):
 * {@code foot-bot} (ARGoS's {@code footbot_proximity}): 1 under 0.009889556 m, else {@code 0.0100527 / (d +
 * 0.000163144)}; {@code e-puck} (ARGoS's {@code epuck_proximity}): {@code 298.701 d^2 - 36.8961 d + 1.08212} within
 * 0.05 m, else 0; each held to [0, 1], Gaussian noise included.
 */
@AutoService(RobotSensor.class)
public final class ProximitySensor extends RobotSensor {
    private static final Attribute MODEL = Attribute.choice("model", "whose law turns a distance into a reading",
            "foot-bot", "e-puck");
    private static final Attribute NOISE = Attribute.noise("");

    private boolean footBot;
    private double noise;
    private int count;
    private double[] rangeMm = new double[0];

    public ProximitySensor() {
        super(new SensorInfo("proximity", "short-range infrared sensors round the robot, one a ray of its type",
                List.of(MODEL, NOISE), "one reading a ray, in the type's order: 0 for nothing in range, rising towards "
                + "1 at contact", "", true, SensorInfo.Display.VALUES));
    }

    @Override
    protected void configure(Attributes a) {
        footBot = MODEL.choose(a).equals("foot-bot");
        noise = NOISE.read(a);
    }

    @Override
    protected void mount(RobotProperties robot) {
        count = robot == null ? 0 : robot.rays().size();
        rangeMm = new double[count];
        for (int k = 0; k < count; k++) {
            rangeMm[k] = robot.rays().get(k).rangeMm();
        }
    }

    @Override
    public SensorValues values() {
        return new SensorValues(count, 0, 1, "");
    }

    @Override
    public double[] generateSensorResponse(SensorContext c) {
        double[] out = new double[count];
        for (int k = 0; k < count; k++) {
            double d = c.rayRange(k);
            out[k] = noisy(d >= rangeMm[k] ? 0 : reading(d / 1000), noise, c, 0, 1);
        }
        return out;
    }

    /**
     * The distance, m, that a reading of model {@code model} ({@code foot-bot} or {@code e-puck}) says, by its law
     * turned round (for those who want ranges, as ROS's {@code sensor_msgs/Range}): +infinity for 0 (nothing in
     * range), the law's nearest distance for a reading at or above the law's largest (at contact); noise makes it
     * approximate. An unknown model is an IllegalArgumentException.
     */
    public static double distanceM(String model, double reading) {
        if (!(reading > 0)) {
            return Double.POSITIVE_INFINITY;
        }
        switch (model) {
            case "foot-bot" -> {
                return reading >= 1 ? 0.009889556 : Math.max(0.009889556, 0.0100527 / reading - 0.000163144);
            }
            case "e-puck" -> { // (the quadratic falls from 1.08212 at 0 to 0 at 0.0479 m: one root there)
                double c = 1.08212 - Math.min(reading, 1.08212);
                double d = (36.8961 - Math.sqrt(36.8961 * 36.8961 - 4 * 298.701 * c)) / (2 * 298.701);
                return Math.min(0.05, Math.max(0, d));
            }
            default -> throw new IllegalArgumentException("no proximity model " + model + " (foot-bot, e-puck)");
        }
    }

    /** The reading at {@code m} metres from the sensor, by the model's law. */
    private double reading(double m) {
        if (footBot) {
            return m < 0.009889556 ? 1 : 0.0100527 / (m + 0.000163144);
        }
        return m > 0.05 ? 0 : Math.max(0, Math.min(1, 298.701 * m * m - 36.8961 * m + 1.08212));
    }
}

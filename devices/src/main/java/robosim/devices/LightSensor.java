package robosim.devices;

import com.google.auto.service.AutoService;
import java.util.List;
import robosim.protocol.Light;
import robosim.protocol.RobotProperties;

/**
 * {@code light}: the lights a robot sees, by its model (ARGoS's laws; d the distance in 3-D to a light of intensity
 * I, m; a light behind an obstacle, an object or another robot taller than the line of sight where it passes gives
 * nothing; one that is off or of intensity 0 never shines). {@code foot-bot} ({@code footbot_light}): 24 readings
 * round the rim from 7.5 degrees every 15, each the sum over the lights of {@code exp(-2 d / I) (1 - 2 a / pi)} for a
 * sensor within a = pi/2 of the light's direction (0 beyond d / I = 2.5), seen from the robot's centre on the floor.
 * {@code e-puck} ({@code light}): 8 readings from 22.5 degrees every 45, each the sum of {@code I^2 / d^2} with d from
 * the sensor, 60 mm up. {@code kilobot} ({@code kilobot_light}): one ambient reading, {@code floor(1024 exp(-2 d / I)
 * (1 - a / pi))} from a sensor facing 100 degrees left of ahead, 0 to 1024. Readings in [0, 1] (kilobot: [0, 1024]),
 * Gaussian noise included.
 */
@AutoService(RobotSensor.class)
public final class LightSensor extends RobotSensor {
    private static final Attribute MODEL = Attribute.choice("model", "whose ring and law", "foot-bot", "e-puck",
            "kilobot");
    private static final Attribute NOISE = Attribute.noise("");
    /** Where the e-puck's ring sits over the floor, mm. */
    private static final double EPUCK_RING_Z_MM = 60;

    private String model;
    private double noise;
    private double[] anglesDeg = new double[0];
    private double radiusMm;

    public LightSensor() {
        super(new SensorInfo("light", "the lights in sight, by the robot's model's law", List.of(MODEL, NOISE),
                "foot-bot: 24 readings from 7.5 degrees every 15, e-puck: 8 from 22.5 every 45, each 0 to 1; kilobot: one "
                        + "ambient reading, 0 to 1024", "", false, SensorInfo.Display.VALUES));
    }

    @Override
    protected void configure(Attributes a) {
        model = MODEL.choose(a);
        noise = NOISE.read(a);
        anglesDeg = switch (model) {
            case "foot-bot" -> RobotType.evenly(24, 7.5);
            case "e-puck" -> RobotType.evenly(8, 22.5);
            default -> new double[] {100};
        };
    }

    @Override
    protected void mount(RobotProperties robot) {
        radiusMm = robot == null ? 0 : robot.radiusMm();
    }

    private double most() {
        return model.equals("kilobot") ? 1024 : 1;
    }

    @Override
    public SensorValues values() {
        return new SensorValues(anglesDeg.length, 0, most(), "");
    }

    @Override
    public double[] generateSensorResponse(SensorContext c) {
        double[] out = new double[anglesDeg.length];
        for (Light l : c.lights()) {
            if (!l.shines()) {
                continue;
            }
            double dx = l.xMm() - c.xMm();
            double dy = l.yMm() - c.yMm();
            double toLight = Math.toDegrees(Math.atan2(dy, dx)) - c.headingDeg();
            switch (model) {
                case "foot-bot" -> {
                    double r = Math.sqrt(dx * dx + dy * dy + l.heightMm() * l.heightMm()) / 1000 / l.intensity();
                    if (r > 2.5 || !c.sight(0, l.xMm(), l.yMm(), l.heightMm(), -1)) {
                        continue;
                    }
                    double e = Math.exp(-2 * r);
                    for (int k = 0; k < out.length; k++) {
                        double a = Math.toRadians(apart(toLight, anglesDeg[k]));
                        if (a <= Math.PI / 2) {
                            out[k] += e * (1 - 2 * a / Math.PI);
                        }
                    }
                }
                case "e-puck" -> {
                    if (!c.sight(EPUCK_RING_Z_MM, l.xMm(), l.yMm(), l.heightMm(), -1)) {
                        continue;
                    }
                    double h = Math.toRadians(c.headingDeg());
                    for (int k = 0; k < out.length; k++) {
                        double s = h + Math.toRadians(anglesDeg[k]);
                        double sx = l.xMm() - (c.xMm() + radiusMm * Math.cos(s));
                        double sy = l.yMm() - (c.yMm() + radiusMm * Math.sin(s));
                        double sz = l.heightMm() - EPUCK_RING_Z_MM;
                        double d2 = (sx * sx + sy * sy + sz * sz) / 1e6;
                        out[k] += l.intensity() * l.intensity() / d2;
                    }
                }
                default -> {
                    double r = Math.sqrt(dx * dx + dy * dy + l.heightMm() * l.heightMm()) / 1000 / l.intensity();
                    if (r < 2.5 && c.sight(0, l.xMm(), l.yMm(), l.heightMm(), -1)) {
                        double a = Math.toRadians(apart(toLight, anglesDeg[0]));
                        out[0] += Math.floor(1024 * Math.exp(-2 * r) * (1 - a / Math.PI));
                    }
                }
            }
        }
        for (int k = 0; k < out.length; k++) {
            out[k] = noisy(out[k], noise, c, 0, most());
        }
        return out;
    }

    /** How far apart two directions are, degrees, 0 to 180. */
    static double apart(double aDeg, double bDeg) {
        double d = (aDeg - bDeg) % 360;
        if (d < 0) {
            d += 360;
        }
        return d > 180 ? 360 - d : d;
    }
}

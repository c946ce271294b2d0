package robosim.devices;

import com.google.auto.service.AutoService;
import java.util.List;
import robosim.api.Colours;

/**
 * {@code ground}: points under the robot, each reading the floor's grey level there, 0 (black) to 1 (white)
 * ({@code (0.299 R + 0.587 G + 0.114 B) / 255}), Gaussian noise included, at its model's offsets in the robot's frame
 * (x forward, y left, mm): {@code foot-bot} (ARGoS's {@code footbot_motor_ground}): (63, 11.6), (-63, 11.6), (-63,
 * -11.6), (63, -11.6); {@code e-puck}: (30, -9), (30, 0), (30, 9).
 */
@AutoService(RobotSensor.class)
public final class GroundSensor extends RobotSensor {
    private static final Attribute MODEL = Attribute.choice("model", "whose points", "foot-bot", "e-puck");
    private static final Attribute READ = Attribute.choice("read", "what a point reads: its grey level, or its colour",
            "grey", "colour");
    private static final Attribute NOISE = Attribute.noise("");
    private static final double[] FOOT_BOT = {63, 11.6, -63, 11.6, -63, -11.6, 63, -11.6};
    private static final double[] E_PUCK = {30, -9, 30, 0, 30, 9};

    private double[] points = FOOT_BOT;
    private double noise;
    private boolean colour;

    public GroundSensor() {
        super(new SensorInfo("ground", "the floor's grey level at points under the robot", List.of(MODEL, READ, NOISE),
                "one grey level a point, 0 (black) to 1 (white), or with read=\"colour\" its colour (0xRRGGBB, no "
                        + "noise); foot-bot: front-left, back-left, back-right, front-right; e-puck: right, middle, left",
                "", false, SensorInfo.Display.VALUES));
    }

    @Override
    protected void configure(Attributes a) {
        points = MODEL.choose(a).equals("foot-bot") ? FOOT_BOT : E_PUCK;
        colour = READ.choose(a).equals("colour");
        noise = NOISE.read(a);
    }

    @Override
    public SensorValues values() {
        return new SensorValues(points.length / 2, 0, colour ? 0xFFFFFF : 1, "");
    }

    @Override
    public double[] generateSensorResponse(SensorContext c) {
        double h = Math.toRadians(c.headingDeg());
        double cos = Math.cos(h);
        double sin = Math.sin(h);
        double[] out = new double[points.length / 2];
        for (int k = 0; k < out.length; k++) {
            double px = points[2 * k];
            double py = points[2 * k + 1];
            int rgb = c.floorColour(c.xMm() + px * cos - py * sin, c.yMm() + px * sin + py * cos);
            out[k] = colour ? rgb : noisy(Colours.grey(rgb), noise, c, 0, 1);
        }
        return out;
    }
}

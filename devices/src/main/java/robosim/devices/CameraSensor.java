package robosim.devices;

import com.google.auto.service.AutoService;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import robosim.protocol.Light;

/**
 * {@code camera}: an omnidirectional camera on top of the robot that sees coloured blobs: every lit LED of the other
 * robots and every shining light within its range (on the floor's plane) and in sight of its eye (a line clear of
 * anything taller than it where it passes; the LED's own robot hides the LEDs on its far side), each as its colour
 * ({@code 0xRRGGBB}), its distance (mm, on the floor's plane) and its angle (degrees from the heading,
 * counter-clockwise, in (-180, 180]), nearest first. The foot-bot's (ARGoS's {@code colored_blob_omnidirectional_camera}
 * with its default 70 degree aperture) sees 793 mm; ARGoS's field is a square of that half-side, this one a disc.
 * Gaussian noise on the distance.
 */
@AutoService(RobotSensor.class)
public final class CameraSensor extends RobotSensor {
    private static final Attribute RANGE = Attribute.number("rangeMm", 793.2, "mm", "the farthest a blob is seen, "
            + "on the floor's plane").above(0);
    private static final Attribute EYE = Attribute.number("heightMm", 288.7, "mm", "how high its eye is over the "
            + "floor").atLeast(0);
    private static final Attribute MAX = Attribute.number("maxBlobs", 32, "", "the most blobs a step reads (the "
            + "nearest)").atLeast(1).atMost(1024);
    private static final Attribute NOISE = Attribute.noise("mm");

    private double rangeMm;
    private double eyeMm;
    private int most;
    private double noise;

    public CameraSensor() {
        super(new SensorInfo("camera", "an omnidirectional camera: the other robots' lit LEDs and the lights in sight",
                List.of(RANGE, EYE, MAX, NOISE), "per blob, nearest first: its colour (0xRRGGBB), its distance (mm) "
                + "and its angle (deg)", "", false, SensorInfo.Display.VALUES));
    }

    @Override
    protected void configure(Attributes a) {
        rangeMm = RANGE.read(a);
        eyeMm = EYE.read(a);
        most = (int) MAX.read(a);
        noise = NOISE.read(a);
    }

    @Override
    public SensorValues values() {
        return SensorValues.groups(most, new double[] {0, 0, -180}, new double[] {0xFFFFFF, rangeMm, 180}, "");
    }

    /** One blob: its colour, distance and angle; {@code order}: when it was found (ties keep it). */
    private record Blob(int rgb, double distance, double angle, int order) {
    }

    /** Nearest first; at one distance, the one found first. */
    private static final Comparator<Blob> NEAREST = Comparator.comparingDouble(Blob::distance)
            .thenComparingInt(Blob::order);

    @Override
    public double[] generateSensorResponse(SensorContext c) {
        List<Blob> blobs = new ArrayList<>();
        c.leds(rangeMm, (robot, x, y, z, rgb) -> {
            double dx = x - c.xMm();
            double dy = y - c.yMm();
            double d = Math.sqrt(dx * dx + dy * dy); // (Math.hypot's care of overflow costs a crowd's camera dearly)
            if (d <= rangeMm && c.sight(eyeMm, x, y, z, -1)) {
                blobs.add(new Blob(rgb, d, angle(c, x, y), blobs.size()));
            }
        });
        for (Light l : c.lights()) {
            double d = Math.hypot(l.xMm() - c.xMm(), l.yMm() - c.yMm());
            if (l.shines() && d <= rangeMm && c.sight(eyeMm, l.xMm(), l.yMm(), l.heightMm(), -1)) {
                blobs.add(new Blob(l.rgb(), d, angle(c, l.xMm(), l.yMm()), blobs.size()));
            }
        }
        blobs.sort(NEAREST);
        int n = Math.min(most, blobs.size());
        double[] out = new double[3 * n];
        for (int b = 0; b < n; b++) {
            Blob blob = blobs.get(b);
            out[3 * b] = blob.rgb();
            out[3 * b + 1] = noisy(blob.distance(), noise, c, 0, rangeMm);
            out[3 * b + 2] = blob.angle();
        }
        return out;
    }

    /** The direction to (x, y) from the robot, degrees from its heading, in (-180, 180]. */
    private static double angle(SensorContext c, double x, double y) {
        double a = Math.toDegrees(Math.atan2(y - c.yMm(), x - c.xMm())) - c.headingDeg();
        a = a % 360;
        if (a > 180) {
            a -= 360;
        } else if (a <= -180) {
            a += 360;
        }
        return a;
    }
}

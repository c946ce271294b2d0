package robosim.devices;

import com.google.auto.service.AutoService;
import java.util.List;
import robosim.protocol.SonarSpec;

/**
 * {@code sonar}: a robot's sonar ring, the one its type carries ({@link RobotType}), computed by the Geometry process
 * (each transducer's cone against walls, obstacles and robots). Its noise is the robot's {@code sonarNoiseMm}: Gaussian,
 * a reading floored at 0 and, as it always was (so that every noisy world runs as it did), not held to the farthest
 * range (a learner sees it held there).
 */
@AutoService(RobotSensor.class)
public final class SonarSensor extends RobotSensor {
    /** The robot's {@code sonarNoiseMm}: the sonar has no {@code <sensor>} of its own, it comes with the type. */
    private static final Attribute NOISE = Attribute.number("sonarNoiseMm", 0, "mm", "on the <robot>: the standard "
            + "deviation of Gaussian noise on every range, from the world's seed").atLeast(0);

    private int count;
    private double farthestMm;
    private double noiseMm;

    public SonarSensor() {
        super(new SensorInfo("sonar", "the robot's sonar ring, as its type carries it", List.of(NOISE),
                "one range a transducer, mm, in the type's order (Robot.sonarAnglesDeg), measured from the transducer "
                        + "on the rim; a transducer's farthest range when nothing is in its cone", "mm", true,
                SensorInfo.Display.RANGES));
    }

    /** The sonar of a robot with {@code ring}, its noise {@code noiseMm} (the file's {@code sonarNoiseMm}). */
    public static SonarSensor of(List<SonarSpec> ring, double noiseMm) {
        SonarSensor s = new SonarSensor();
        s.configure(new Attributes(java.util.Map.of(NOISE.name(), Double.toString(noiseMm))));
        s.count = ring.size();
        s.farthestMm = ring.stream().mapToDouble(SonarSpec::maxRangeMm).max().orElse(0);
        return s;
    }

    @Override
    protected void configure(Attributes a) {
        noiseMm = NOISE.read(a);
    }

    @Override
    public SensorValues values() {
        return new SensorValues(count, 0, farthestMm, "mm");
    }

    @Override
    public double[] generateSensorResponse(SensorContext c) {
        double[] ranges = new double[count];
        for (int s = 0; s < count; s++) {
            double r = c.sonarRange(s);
            ranges[s] = noiseMm > 0 ? Math.max(0, r + noiseMm * c.gaussian()) : r;
        }
        return ranges;
    }
}

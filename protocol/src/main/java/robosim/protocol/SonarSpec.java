package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * One sonar transducer, in the robot's own frame (x forward, y to the left, millimetres).
 * Written inline inside {@link RobotProperties}, never as an object of its own.
 *
 * @param xMm position forward of the robot's centre
 * @param yMm position to the left of the robot's centre
 * @param angleDeg direction of the beam's axis, counter-clockwise from the robot's heading
 * @param coneDeg full width of the beam; a surface counts when any part of it is inside the cone
 * @param maxRangeMm reading when nothing is inside the cone
 */
public record SonarSpec(double xMm, double yMm, double angleDeg, double coneDeg, double maxRangeMm) {
    public SonarSpec {
        if (!(coneDeg > 0 && coneDeg < 180)) {
            throw new IllegalArgumentException("sonar coneDeg must be in (0, 180), got " + coneDeg);
        }
        if (!(maxRangeMm > 0) || Double.isInfinite(maxRangeMm)) {
            throw new IllegalArgumentException("sonar maxRangeMm must be > 0, got " + maxRangeMm);
        }
        if (!Double.isFinite(xMm) || !Double.isFinite(yMm) || !Double.isFinite(angleDeg)) {
            throw new IllegalArgumentException("sonar position and angle must be finite numbers");
        }
    }

    /** A transducer on the rim of a round robot of {@code radiusMm}, facing outwards at {@code angleDeg}. */
    public static SonarSpec onRim(double radiusMm, double angleDeg, double coneDeg, double maxRangeMm) {
        double a = Math.toRadians(angleDeg);
        return new SonarSpec(radiusMm * Math.cos(a), radiusMm * Math.sin(a), angleDeg, coneDeg, maxRangeMm);
    }

    void write(ObjectOutput out) throws IOException {
        out.writeDouble(xMm);
        out.writeDouble(yMm);
        out.writeDouble(angleDeg);
        out.writeDouble(coneDeg);
        out.writeDouble(maxRangeMm);
    }

    static SonarSpec read(ObjectInput in) throws IOException {
        double x = in.readDouble();
        double y = in.readDouble();
        double angle = in.readDouble();
        double cone = in.readDouble();
        double range = in.readDouble();
        try {
            return new SonarSpec(x, y, angle, cone, range);
        } catch (IllegalArgumentException e) {
            throw new ProtocolException(e.getMessage());
        }
    }
}

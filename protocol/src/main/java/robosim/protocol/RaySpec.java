package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * One ray a robot's short-range sensor casts (a proximity sensor's infrared beam), in the robot's own frame (x forward,
 * y to the left, millimetres): where it starts, which way it points and how far it reaches. The Geometry process
 * measures the distance along it to the first wall, obstacle, object or other robot, as it does sonar. Written inline
 * inside {@link RobotProperties}.
 */
public record RaySpec(double xMm, double yMm, double angleDeg, double rangeMm) {
    public RaySpec {
        if (!Double.isFinite(xMm) || !Double.isFinite(yMm) || !Double.isFinite(angleDeg)) {
            throw new IllegalArgumentException("a ray's start and angle must be finite numbers");
        }
        if (!(rangeMm > 0) || Double.isInfinite(rangeMm)) {
            throw new IllegalArgumentException("a ray's range must be > 0 mm, got " + rangeMm);
        }
    }

    /** A ray from the rim of a round robot of {@code radiusMm}, pointing straight out at {@code angleDeg}. */
    public static RaySpec onRim(double radiusMm, double angleDeg, double rangeMm) {
        double a = Math.toRadians(angleDeg);
        return new RaySpec(radiusMm * Math.cos(a), radiusMm * Math.sin(a), angleDeg, rangeMm);
    }

    void write(ObjectOutput out) throws IOException {
        out.writeDouble(xMm);
        out.writeDouble(yMm);
        out.writeDouble(angleDeg);
        out.writeDouble(rangeMm);
    }

    static RaySpec read(ObjectInput in) throws IOException {
        try {
            return new RaySpec(in.readDouble(), in.readDouble(), in.readDouble(), in.readDouble());
        } catch (IllegalArgumentException e) {
            throw new ProtocolException(e.getMessage());
        }
    }
}

package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * Where one of a robot's LEDs sits, in the robot's own frame (x forward, y to the left, z up from the floor,
 * millimetres): where cameras see it and viewers draw it. Written inline inside {@link RobotProperties}.
 */
public record LedSpec(double xMm, double yMm, double zMm) {
    public LedSpec {
        if (!Double.isFinite(xMm) || !Double.isFinite(yMm) || !(zMm >= 0) || Double.isInfinite(zMm)) {
            throw new IllegalArgumentException("an LED's place must be finite, at or above the floor");
        }
    }

    /** {@code count} LEDs in a ring of {@code radiusMm} at height {@code zMm}, the first at {@code firstDeg}. */
    public static java.util.List<LedSpec> ring(int count, double radiusMm, double zMm, double firstDeg) {
        LedSpec[] ring = new LedSpec[count];
        for (int i = 0; i < count; i++) {
            double a = Math.toRadians(firstDeg + 360.0 * i / count);
            ring[i] = new LedSpec(radiusMm * Math.cos(a), radiusMm * Math.sin(a), zMm);
        }
        return java.util.List.of(ring);
    }

    void write(ObjectOutput out) throws IOException {
        out.writeDouble(xMm);
        out.writeDouble(yMm);
        out.writeDouble(zMm);
    }

    static LedSpec read(ObjectInput in) throws IOException {
        try {
            return new LedSpec(in.readDouble(), in.readDouble(), in.readDouble());
        } catch (IllegalArgumentException e) {
            throw new ProtocolException(e.getMessage());
        }
    }
}

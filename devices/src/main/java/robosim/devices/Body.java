package robosim.devices;

/**
 * A robot's round body and differential drive: its radius, height and mass, the distance between its wheels, its
 * speed limits, and the velocities {@code move} and {@code turn} start with. A robot on wheels turns at
 * {@code (right - left) / wheelBase} radians a second and moves at {@code (left + right) / 2}.
 */
public record Body(double radiusMm, double heightMm, double massKg, double wheelBaseMm, double maxSpeedMmPerS,
        double maxTurnDegPerS, double velocityMmPerS, double rotVelocityDegPerS) {
    public Body {
        if (!(radiusMm > 0) || !(heightMm > 0) || !(massKg > 0) || !(wheelBaseMm > 0) || !(maxSpeedMmPerS > 0)
                || !(maxTurnDegPerS > 0) || !(velocityMmPerS > 0) || !(rotVelocityDegPerS > 0)) {
            throw new IllegalArgumentException("a body's sizes, mass, limits and velocities are all > 0");
        }
    }

    /** A body whose drive starts at 500 mm/s and 90 deg/s (within its limits). */
    public Body(double radiusMm, double heightMm, double massKg, double wheelBaseMm, double maxSpeedMmPerS,
            double maxTurnDegPerS) {
        this(radiusMm, heightMm, massKg, wheelBaseMm, maxSpeedMmPerS, maxTurnDegPerS, Math.min(500, maxSpeedMmPerS),
                Math.min(90, maxTurnDegPerS));
    }

    /** A body of the first kind: as tall as its radius, 10 kg, wheels its diameter apart. */
    public Body(double radiusMm, double maxSpeedMmPerS, double maxTurnDegPerS) {
        this(radiusMm, radiusMm, 10, 2 * radiusMm, maxSpeedMmPerS, maxTurnDegPerS);
    }
}

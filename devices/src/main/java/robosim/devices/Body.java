package robosim.devices;

/**
 * A robot's round body and differential drive: its radius, its speed limits, and the velocities {@code move} and
 * {@code turn} start with.
 */
public record Body(double radiusMm, double maxSpeedMmPerS, double maxTurnDegPerS, double velocityMmPerS,
        double rotVelocityDegPerS) {
    /** A body whose drive starts at 500 mm/s and 90 deg/s (within its limits). */
    public Body(double radiusMm, double maxSpeedMmPerS, double maxTurnDegPerS) {
        this(radiusMm, maxSpeedMmPerS, maxTurnDegPerS, Math.min(500, maxSpeedMmPerS), Math.min(90, maxTurnDegPerS));
    }
}

package robosim.testkit;

/** Where a robot stands: its centre in world millimetres and its heading in degrees (counter-clockwise from +x). */
public record Pose(double xMm, double yMm, double headingDeg) {
    /** The distance from this pose's centre to {@code other}'s, mm. */
    public double distanceMm(Pose other) {
        return Math.hypot(other.xMm - xMm, other.yMm - yMm);
    }
}

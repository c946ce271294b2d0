package robosim.geometry;

/** One edge of a static obstacle or of the arena boundary, world mm; immutable. */
final class Segment {
    final double ax;
    final double ay;
    final double bx;
    final double by;
    /** {@code GeometryStepResponse.CONTACT_OBSTACLE} or {@code CONTACT_ARENA}. */
    final byte ownerKind;
    /** Index of the obstacle in the world, or 0 for the arena. */
    final int ownerIndex;

    Segment(double ax, double ay, double bx, double by, byte ownerKind, int ownerIndex) {
        this.ax = ax;
        this.ay = ay;
        this.bx = bx;
        this.by = by;
        this.ownerKind = ownerKind;
        this.ownerIndex = ownerIndex;
    }
}

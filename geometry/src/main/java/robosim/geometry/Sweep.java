package robosim.geometry;

/**
 * Exact first-contact distances for a round robot moving in a straight line: the robot's centre
 * is a point moving along a unit direction, and a wall segment grown by the robot's radius is a
 * capsule; another robot grown by both radii is a circle. Only approach counts: a robot already
 * touching something may move away or along it, never further in.
 */
final class Sweep {
    static final double NEVER = Double.POSITIVE_INFINITY;

    private Sweep() {
    }

    /**
     * Distance the point P may travel along unit (ux, uy) before it comes within {@code r} of the
     * point C while getting closer; 0 if already within and approaching; {@link #NEVER} otherwise.
     */
    static double toCircle(double px, double py, double ux, double uy, double r, double cx, double cy) {
        double dx = px - cx;
        double dy = py - cy;
        double b = dx * ux + dy * uy;
        if (b >= 0) {
            return NEVER;
        }
        double c = dx * dx + dy * dy - r * r;
        if (c <= 0) {
            return 0;
        }
        double disc = b * b - c;
        if (disc < 0) {
            return NEVER;
        }
        return Math.max(0, -b - Math.sqrt(disc));
    }

    /** As {@link #toCircle}, for the capsule of radius {@code r} around segment AB. */
    static double toCapsule(double px, double py, double ux, double uy, double r, Segment s) {
        return toCapsule(px, py, ux, uy, r, s.ax, s.ay, s.bx, s.by);
    }

    /**
     * As {@link #toCircle}, for the capsule of radius {@code r} around segment (ax, ay)-(bx, by); with {@code r} 0,
     * the distance a point travels before it meets the segment (a corner of a moving box, a wall's end).
     */
    static double toCapsule(double px, double py, double ux, double uy, double r, double ax, double ay, double bx,
            double by) {
        double ex = bx - ax;
        double ey = by - ay;
        double len = Math.sqrt(ex * ex + ey * ey);
        double best = Math.min(toCircle(px, py, ux, uy, r, ax, ay), toCircle(px, py, ux, uy, r, bx, by));
        if (len == 0) {
            return best;
        }
        ex /= len;
        ey /= len;
        double nx = -ey;
        double ny = ex;
        double s0 = (px - ax) * nx + (py - ay) * ny;
        double sv = ux * nx + uy * ny;
        if (s0 * sv >= 0) {
            return best;
        }
        double side = Math.abs(s0);
        double t = side <= r ? 0 : (side - r) / Math.abs(sv);
        double along = (px + t * ux - ax) * ex + (py + t * uy - ay) * ey;
        if (along >= 0 && along <= len) {
            best = Math.min(best, t);
        }
        return best;
    }
}

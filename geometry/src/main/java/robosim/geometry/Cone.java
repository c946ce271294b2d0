package robosim.geometry;

/**
 * Exact nearest distances inside a sonar cone: the wedge of half-angle below 90 degrees around a
 * unit axis, from an origin. A wall segment is clipped to the wedge first; a round robot counts
 * where its disc meets the wedge. Distances are from the origin; {@link Sweep#NEVER} for a miss.
 * A mutable scratch object, re-aimed with {@code aim} so the per-step path allocates nothing.
 */
final class Cone {
    double ox;
    double oy;
    private double clipLo;
    private double clipHi;
    /** Unit vectors of the wedge's two boundary rays (left = counter-clockwise of the axis). */
    double lx;
    double ly;
    double rx;
    double ry;
    double axisX;
    double axisY;

    /**
     * Aims the wedge from an origin with its unit vectors (axis, left and right edges) given in a frame
     * turned by the angle whose cosine and sine are {@code c} and {@code s}: a rotation, no trigonometry,
     * for sonars whose vectors in the robot's frame are worked out once ({@link #beam}).
     */
    Cone aim(double originX, double originY, double c, double s, double[] beam) {
        this.ox = originX;
        this.oy = originY;
        axisX = c * beam[0] - s * beam[1];
        axisY = s * beam[0] + c * beam[1];
        lx = c * beam[2] - s * beam[3];
        ly = s * beam[2] + c * beam[3];
        rx = c * beam[4] - s * beam[5];
        ry = s * beam[4] + c * beam[5];
        return this;
    }

    /** A sonar's unit vectors in the robot's frame, for {@link #aim(double, double, double, double, double[])}. */
    static double[] beam(double axisDeg, double halfDeg) {
        double a = Math.toRadians(axisDeg);
        double h = Math.toRadians(halfDeg);
        return new double[] {Math.cos(a), Math.sin(a), Math.cos(a + h), Math.sin(a + h), Math.cos(a - h),
            Math.sin(a - h)};
    }

    /** True when the point lies inside the wedge (boundary included). */
    boolean contains(double px, double py) {
        double vx = px - ox;
        double vy = py - oy;
        return rx * vy - ry * vx >= 0 && vx * ly - vy * lx >= 0;
    }

    /** Nearest distance from the origin to the part of segment AB inside the wedge. */
    double toSegment(double ax, double ay, double bx, double by) {
        clipLo = 0;
        clipHi = 1;
        // right boundary: cross(r, X - O) >= 0
        if (!clip(rx * (ay - oy) - ry * (ax - ox), rx * (by - oy) - ry * (bx - ox))) {
            return Sweep.NEVER;
        }
        // left boundary: cross(X - O, l) >= 0
        if (!clip((ax - ox) * ly - (ay - oy) * lx, (bx - ox) * ly - (by - oy) * lx)) {
            return Sweep.NEVER;
        }
        double ex = bx - ax;
        double ey = by - ay;
        double sx = ax + clipLo * ex;
        double sy = ay + clipLo * ey;
        double tx = ax + clipHi * ex;
        double ty = ay + clipHi * ey;
        return pointToSegment(ox, oy, sx, sy, tx, ty);
    }

    /** Narrows [clipLo, clipHi] to where f(s) = fa + s (fb - fa) >= 0; false when nothing is left. */
    private boolean clip(double fa, double fb) {
        if (fa >= 0 && fb >= 0) {
            return true;
        }
        if (fa < 0 && fb < 0) {
            return false;
        }
        double s = fa / (fa - fb);
        if (fa < 0) {
            clipLo = Math.max(clipLo, s);
        } else {
            clipHi = Math.min(clipHi, s);
        }
        return clipLo <= clipHi;
    }

    /** Nearest distance from the origin to the disc of radius r about C, inside the wedge. */
    double toDisc(double cx, double cy, double r) {
        double dx = cx - ox;
        double dy = cy - oy;
        double d = Math.sqrt(dx * dx + dy * dy);
        if (d <= r) {
            return 0;
        }
        if (contains(cx, cy)) {
            return d - r;
        }
        return Math.min(Sweep.toCircle(ox, oy, lx, ly, r, cx, cy), Sweep.toCircle(ox, oy, rx, ry, r, cx, cy));
    }

    static double pointToSegment(double px, double py, double ax, double ay, double bx, double by) {
        double ex = bx - ax;
        double ey = by - ay;
        double len2 = ex * ex + ey * ey;
        double t = len2 == 0 ? 0 : ((px - ax) * ex + (py - ay) * ey) / len2;
        t = Math.max(0, Math.min(1, t));
        double qx = ax + t * ex - px;
        double qy = ay + t * ey - py;
        return Math.sqrt(qx * qx + qy * qy);
    }
}

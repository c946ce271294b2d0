package robosim.geometry;

import java.util.List;
import org.locationtech.jts.geom.Envelope;
import robosim.protocol.WorldObject;

/**
 * The world's objects (boxes and cylinders) as they stand: each one's outline at its current pose, and the exact
 * questions moves and sensors ask of them. A box is its four corners and edges ({@link WorldObject#corners}), a cylinder its
 * disc. Sweeps follow {@link Sweep}: the distance something may travel in a straight line before it touches, only
 * approach counting ({@link Sweep#NEVER} when it never does). Objects are few next to walls and robots, so a query
 * looks at each one, its bounding box first. Not thread-safe to change: the engine moves objects on one thread; the
 * sonar passes only read it.
 */
public final class ObjectLayer {
    private static final double EPS = 1e-9;

    private final WorldObject[] objects;
    private final boolean[] box;
    /** A cylinder's radius; a box's bounding radius (around its centre). */
    private final double[] radius;
    private final double[] x;
    private final double[] y;
    private final double[] heading;
    /** Each box's corners in the world, x0, y0, ... x3, y3 (a cylinder's unused). */
    private final double[] corners;
    private final double[] scratch = new double[2];
    /** Objects out of the world (a world's loop functions removed them): nothing meets, sees or holds them. */
    private final boolean[] gone;

    /** The objects of a world, each at its start pose. */
    public ObjectLayer(List<WorldObject> objects) {
        int n = objects.size();
        this.objects = objects.toArray(new WorldObject[0]);
        this.box = new boolean[n];
        this.radius = new double[n];
        this.x = new double[n];
        this.y = new double[n];
        this.heading = new double[n];
        this.corners = new double[8 * n];
        this.gone = new boolean[n];
        for (int o = 0; o < n; o++) {
            WorldObject w = this.objects[o];
            box[o] = w.shape() == WorldObject.Shape.BOX;
            radius[o] = w.reachMm();
            place(o, w.xMm(), w.yMm(), w.headingDeg());
        }
        placed = true;
    }

    /** True once every object has been placed (its corners worked out) at least once. */
    private boolean placed;

    public int count() {
        return objects.length;
    }

    public WorldObject object(int o) {
        return objects[o];
    }

    public double x(int o) {
        return x[o];
    }

    public double y(int o) {
        return y[o];
    }

    public double heading(int o) {
        return heading[o];
    }

    /** Object {@code o} now stands at (x, y), heading {@code h}. */
    public void place(int o, double px, double py, double h) {
        if (px == x[o] && py == y[o] && h == heading[o] && placed) {
            return; // (most objects stand still, most steps)
        }
        x[o] = px;
        y[o] = py;
        heading[o] = h;
        if (box[o]) {
            objects[o].corners(px, py, h, corners, 8 * o);
        }
    }

    /** Object {@code o} is out of the world ({@code gone}) or in it. */
    public void gone(int o, boolean out) {
        gone[o] = out;
    }

    /** True if object {@code o} is out of the world. */
    public boolean gone(int o) {
        return gone[o];
    }

    /**
     * The cheap test first: object {@code o}'s bounding box misses {@code area}, or it is out of the world (every
     * query of what meets, sees or holds an object asks this first).
     */
    boolean outside(int o, Envelope area) {
        if (gone[o]) {
            return true;
        }
        double r = radius[o];
        return x[o] + r < area.getMinX() || x[o] - r > area.getMaxX() || y[o] + r < area.getMinY()
                || y[o] - r > area.getMaxY();
    }

    /** Object {@code o}'s bounding box, grown by {@code margin}, into {@code out}. */
    void envelope(int o, double margin, Envelope out) {
        double r = radius[o] + margin;
        out.init(x[o] - r, x[o] + r, y[o] - r, y[o] + r);
    }

    private double cx(int o, int k) {
        return corners[8 * o + 2 * (k & 3)];
    }

    private double cy(int o, int k) {
        return corners[8 * o + 2 * (k & 3) + 1];
    }

    // ---- sweeps ---------------------------------------------------------------------------------------------

    /** How far a disc of radius {@code r} at P may move along unit u before it touches object {@code o}. */
    double discTo(int o, double px, double py, double ux, double uy, double r) {
        if (!box[o]) {
            return Sweep.toCircle(px, py, ux, uy, r + radius[o], x[o], y[o]);
        }
        double best = Sweep.NEVER;
        for (int k = 0; k < 4; k++) {
            best = Math.min(best, Sweep.toCapsule(px, py, ux, uy, r, cx(o, k), cy(o, k), cx(o, k + 1), cy(o, k + 1)));
        }
        return best;
    }

    /** How far object {@code o} may move along unit u before it touches the still segment AB. */
    double toSegment(int o, double ux, double uy, double ax, double ay, double bx, double by) {
        if (!box[o]) {
            return Sweep.toCapsule(x[o], y[o], ux, uy, radius[o], ax, ay, bx, by);
        }
        double best = Sweep.NEVER;
        for (int k = 0; k < 4; k++) {
            best = Math.min(best, Sweep.toCapsule(cx(o, k), cy(o, k), ux, uy, 0, ax, ay, bx, by));
            double ex0 = cx(o, k);
            double ey0 = cy(o, k);
            double ex1 = cx(o, k + 1);
            double ey1 = cy(o, k + 1);
            best = Math.min(best, Sweep.toCapsule(ax, ay, -ux, -uy, 0, ex0, ey0, ex1, ey1));
            best = Math.min(best, Sweep.toCapsule(bx, by, -ux, -uy, 0, ex0, ey0, ex1, ey1));
        }
        return best;
    }

    /** How far object {@code o} may move along unit u before it touches the still disc of radius r about C. */
    double toDisc(int o, double ux, double uy, double cx, double cy, double r) {
        if (!box[o]) {
            return Sweep.toCircle(x[o], y[o], ux, uy, radius[o] + r, cx, cy);
        }
        double best = Sweep.NEVER;
        for (int k = 0; k < 4; k++) {
            best = Math.min(best, Sweep.toCapsule(cx, cy, -ux, -uy, r, cx(o, k), cy(o, k), cx(o, k + 1), cy(o, k + 1)));
        }
        return best;
    }

    /** How far object {@code o} may move along unit u before it touches object {@code p}, which stands still. */
    double toObject(int o, int p, double ux, double uy) {
        if (!box[p]) {
            return toDisc(o, ux, uy, x[p], y[p], radius[p]);
        }
        double best = Sweep.NEVER;
        if (!box[o]) {
            for (int k = 0; k < 4; k++) {
                best = Math.min(best, Sweep.toCapsule(x[o], y[o], ux, uy, radius[o], cx(p, k), cy(p, k), cx(p, k + 1),
                        cy(p, k + 1)));
            }
            return best;
        }
        for (int k = 0; k < 4; k++) {
            best = Math.min(best, toSegment(o, ux, uy, cx(p, k), cy(p, k), cx(p, k + 1), cy(p, k + 1)));
        }
        return best;
    }

    // ---- sensing --------------------------------------------------------------------------------------------

    /** Distance from O along unit u to object {@code o}'s outline ({@link Sweep#NEVER} if the ray misses it). */
    double ray(int o, double ox, double oy, double ux, double uy) {
        if (!box[o]) {
            return Sweep.toCircle(ox, oy, ux, uy, radius[o], x[o], y[o]);
        }
        double best = Sweep.NEVER;
        for (int k = 0; k < 4; k++) {
            best = Math.min(best, Sweep.toCapsule(ox, oy, ux, uy, 0, cx(o, k), cy(o, k), cx(o, k + 1), cy(o, k + 1)));
        }
        return best;
    }

    /** Nearest distance from the cone's origin to object {@code o} inside the cone (a sonar's echo). */
    double cone(Cone cone, int o) {
        if (!box[o]) {
            return cone.toDisc(x[o], y[o], radius[o]);
        }
        double best = Double.POSITIVE_INFINITY;
        for (int k = 0; k < 4; k++) {
            best = Math.min(best, cone.toSegment(cx(o, k), cy(o, k), cx(o, k + 1), cy(o, k + 1)));
        }
        return best;
    }

    /**
     * The point of object {@code o}'s outline nearest to P, into {@code out} (x, y); P itself when inside a box.
     * Returns the distance (0 inside).
     */
    double nearest(int o, double px, double py, double[] out) {
        if (!box[o]) {
            double dx = px - x[o];
            double dy = py - y[o];
            double d = Math.sqrt(dx * dx + dy * dy);
            if (d <= radius[o]) {
                out[0] = px;
                out[1] = py;
                return 0;
            }
            out[0] = x[o] + dx / d * radius[o];
            out[1] = y[o] + dy / d * radius[o];
            return d - radius[o];
        }
        if (insideBox(o, px, py)) {
            out[0] = px;
            out[1] = py;
            return 0;
        }
        double best = Double.POSITIVE_INFINITY;
        for (int k = 0; k < 4; k++) {
            double ax = cx(o, k);
            double ay = cy(o, k);
            double ex = cx(o, k + 1) - ax;
            double ey = cy(o, k + 1) - ay;
            double len2 = ex * ex + ey * ey;
            double t = Math.max(0, Math.min(1, ((px - ax) * ex + (py - ay) * ey) / len2));
            double qx = ax + t * ex;
            double qy = ay + t * ey;
            double d = Math.hypot(px - qx, py - qy);
            if (d < best) {
                best = d;
                out[0] = qx;
                out[1] = qy;
            }
        }
        return best;
    }

    private boolean insideBox(int o, double px, double py) {
        for (int k = 0; k < 4; k++) {
            double ex = cx(o, k + 1) - cx(o, k);
            double ey = cy(o, k + 1) - cy(o, k);
            if (ex * (py - cy(o, k)) - ey * (px - cx(o, k)) < 0) {
                return false; // (corners run counter-clockwise: inside is to the left of every edge)
            }
        }
        return true;
    }

    /**
     * Where segment A-B runs inside object {@code o}: the fractions [in, out] of the way from A to B, into
     * {@code out}; false when it does not enter it.
     */
    boolean crossing(int o, double ax, double ay, double bx, double by, double[] out) {
        double dx = bx - ax;
        double dy = by - ay;
        if (!box[o]) {
            double fx = ax - x[o];
            double fy = ay - y[o];
            double a = dx * dx + dy * dy;
            double b = 2 * (fx * dx + fy * dy);
            double c = fx * fx + fy * fy - radius[o] * radius[o];
            double disc = b * b - 4 * a * c;
            if (a == 0 || disc <= 0) {
                return false;
            }
            double root = Math.sqrt(disc);
            double t0 = Math.max(0, (-b - root) / (2 * a));
            double t1 = Math.min(1, (-b + root) / (2 * a));
            out[0] = t0;
            out[1] = t1;
            return t0 < t1;
        }
        double t0 = 0;
        double t1 = 1;
        for (int k = 0; k < 4; k++) { // (Cyrus-Beck against the box's four half-planes)
            double ex = cx(o, k + 1) - cx(o, k);
            double ey = cy(o, k + 1) - cy(o, k);
            double num = ex * (ay - cy(o, k)) - ey * (ax - cx(o, k));
            double den = ex * dy - ey * dx;
            if (den == 0) {
                if (num < 0) {
                    return false;
                }
            } else {
                double t = -num / den;
                if (den > 0) {
                    t0 = Math.max(t0, t);
                } else {
                    t1 = Math.min(t1, t);
                }
            }
        }
        out[0] = t0;
        out[1] = t1;
        return t0 < t1;
    }

    // ---- overlap --------------------------------------------------------------------------------------------

    /** True when object {@code o} overlaps segment AB (not merely touching it). */
    boolean overlapsSegment(int o, double ax, double ay, double bx, double by) {
        if (!box[o]) {
            return Cone.pointToSegment(x[o], y[o], ax, ay, bx, by) < radius[o] - EPS;
        }
        return crossing(o, ax, ay, bx, by, scratch) && (scratch[1] - scratch[0]) * Math.hypot(bx - ax, by - ay) > EPS;
    }

    /** True when object {@code o} overlaps the disc of radius r about C. */
    boolean overlapsDisc(int o, double cx, double cy, double r) {
        if (!box[o]) {
            return Math.hypot(cx - x[o], cy - y[o]) < radius[o] + r - EPS;
        }
        return nearest(o, cx, cy, scratch) < r - EPS;
    }

    /** True when objects {@code o} and {@code p} overlap. */
    boolean overlapsObject(int o, int p) {
        if (!box[p]) {
            return overlapsDisc(o, x[p], y[p], radius[p]);
        }
        if (!box[o]) {
            return overlapsDisc(p, x[o], y[o], radius[o]);
        }
        for (int k = 0; k < 4; k++) {
            if (overlapsSegment(o, cx(p, k), cy(p, k), cx(p, k + 1), cy(p, k + 1))) {
                return true;
            }
        }
        return insideBox(o, x[p], y[p]) || insideBox(p, x[o], y[o]);
    }
}

package robosim.geometry;

import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.index.ItemVisitor;

/**
 * Questions sensors ask about the world as it stands (static walls, the objects at their poses, robot discs at given
 * poses, mm): the first thing a ray hits (laser), whether a straight line is clear of obstacles (heat), whether a line
 * of sight between two heights is clear of everything taller than it where it passes (light, camera,
 * range-and-bearing), and which directions a robot is touching something in (bump). Reuses scratch state: one thread
 * at a time.
 */
public final class WorldQueries {
    private final StaticWorld world;
    private final ObjectLayer things;
    private final Envelope area = new Envelope();
    private final RayVisitor rayVisitor = new RayVisitor();
    private final SightVisitor sightVisitor = new SightVisitor();
    private final TouchVisitor touchVisitor = new TouchVisitor();
    private final double[] scratch = new double[2];

    /** A world without objects. */
    public WorldQueries(StaticWorld world) {
        this(world, new ObjectLayer(java.util.List.of()));
    }

    /** {@code things}: the world's objects, kept where they stand by the caller ({@link ObjectLayer#place}). */
    public WorldQueries(StaticWorld world, ObjectLayer things) {
        this.world = world;
        this.things = things;
    }

    /**
     * Distance from (ox, oy) along {@code angleDeg} to the first wall, object or robot disc, capped at
     * {@code maxMm}; robot {@code exclude} (the one asking) is ignored.
     */
    public double ray(double ox, double oy, double angleDeg, double maxMm, double[] x, double[] y, double[] r,
            int exclude) {
        double a = Math.toRadians(angleDeg);
        double ux = Math.cos(a);
        double uy = Math.sin(a);
        double ex = ox + ux * maxMm;
        double ey = oy + uy * maxMm;
        area.init(Math.min(ox, ex), Math.max(ox, ex), Math.min(oy, ey), Math.max(oy, ey));
        RayVisitor v = rayVisitor;
        v.begin(ox, oy, ux, uy, maxMm);
        world.query(area, v);
        for (int j = 0; j < x.length; j++) {
            double dx = x[j] - ox;
            double dy = y[j] - oy;
            double reach = v.best + r[j];
            if (j != exclude && dx * dx + dy * dy <= reach * reach) {
                v.best = Math.min(v.best, Sweep.toCircle(ox, oy, ux, uy, r[j], x[j], y[j]));
            }
        }
        for (int o = 0; o < things.count(); o++) {
            if (!things.outside(o, area)) {
                v.best = Math.min(v.best, things.ray(o, ox, oy, ux, uy));
            }
        }
        return v.best;
    }

    /**
     * True when the straight line from A, {@code az} over the floor, to B, {@code bz} over it, passes nothing as tall
     * as the line where it passes: obstacles (as tall as any line), objects and robots (each as tall as it is; robots
     * {@code excludeA} and {@code excludeB}, whose own the ends are, -1 for none, are passed through).
     *
     * @param height each robot's height, mm
     */
    public boolean sight(double ax, double ay, double az, double bx, double by, double bz, double[] x, double[] y,
            double[] r, double[] height, int excludeA, int excludeB) {
        return sight(ax, ay, az, bx, by, bz, x, y, r, height, excludeA, excludeB, null, x.length);
    }

    /**
     * As {@link #sight(double, double, double, double, double, double, double[], double[], double[], double[], int,
     * int)}, looking only at the robots {@code among[0 .. count)} (null: every robot, {@code count} of them): the
     * caller's index has left out those whose bodies cannot reach the line's box.
     */
    public boolean sight(double ax, double ay, double az, double bx, double by, double bz, double[] x, double[] y,
            double[] r, double[] height, int excludeA, int excludeB, int[] among, int count) {
        // (the robots first: in a crowd they block most often, and they cost least to look at; none where the line
        // runs over the tallest of them all the way, as a camera's over the others' beacons does)
        if (Math.min(az, bz) >= tallest(height)) {
            count = 0;
        }
        double minX = Math.min(ax, bx);
        double maxX = Math.max(ax, bx);
        double minY = Math.min(ay, by);
        double maxY = Math.max(ay, by);
        double dx = bx - ax;
        double dy = by - ay;
        double len2 = dx * dx + dy * dy;
        for (int k = 0; k < count && len2 > 0; k++) {
            int j = among == null ? k : among[k];
            double rj = r[j];
            if (j == excludeA || j == excludeB || x[j] + rj < minX || x[j] - rj > maxX || y[j] + rj < minY
                    || y[j] - rj > maxY) {
                continue;
            }
            double fx = ax - x[j];
            double fy = ay - y[j];
            double b = 2 * (fx * dx + fy * dy);
            double c = fx * fx + fy * fy - rj * rj;
            double disc = b * b - 4 * len2 * c;
            if (disc <= 0) {
                continue;
            }
            double root = Math.sqrt(disc);
            double t0 = Math.max(0, (-b - root) / (2 * len2));
            double t1 = Math.min(1, (-b + root) / (2 * len2));
            if (t0 < t1 && below(az, bz, t0, t1, height[j])) {
                return false;
            }
        }
        if (!clear(ax, ay, bx, by)) {
            return false;
        }
        area.init(minX, maxX, minY, maxY);
        for (int o = 0; o < things.count(); o++) {
            if (!things.outside(o, area) && things.crossing(o, ax, ay, bx, by, scratch)
                    && below(az, bz, scratch[0], scratch[1], things.object(o).heightMm())) {
                return false;
            }
        }
        return true;
    }

    private double[] heightsSeen;
    private double tallest;

    /** The greatest of {@code height} (worked out again only when it is another array: robots joined). */
    private double tallest(double[] height) {
        if (height != heightsSeen) {
            double most = 0;
            for (double h : height) {
                most = Math.max(most, h);
            }
            heightsSeen = height;
            tallest = most;
        }
        return tallest;
    }

    /** True when the line from height az to bz runs lower than {@code top} somewhere between fractions t0 and t1. */
    private static boolean below(double az, double bz, double t0, double t1, double top) {
        return Math.min(az + (bz - az) * t0, az + (bz - az) * t1) < top;
    }

    /** True when the straight line from A to B crosses no obstacle edge (the arena's edges do not count). */
    public boolean clear(double ax, double ay, double bx, double by) {
        area.init(Math.min(ax, bx), Math.max(ax, bx), Math.min(ay, by), Math.max(ay, by));
        SightVisitor v = sightVisitor;
        v.begin(ax, ay, bx, by);
        world.queryObstacles(area, v);
        return !v.blocked;
    }

    /**
     * Directions (degrees, world frame) from robot {@code i}'s centre to everything within
     * {@code toleranceMm} of its rim: walls, obstacles and other robots. At most {@code out.length};
     * returns how many.
     */
    public int touching(int i, double[] x, double[] y, double[] r, double toleranceMm, double[] out) {
        double reach = r[i] + toleranceMm;
        area.init(x[i] - reach, x[i] + reach, y[i] - reach, y[i] + reach);
        TouchVisitor v = touchVisitor;
        v.begin(x[i], y[i], reach, out);
        world.query(area, v);
        for (int j = 0; j < x.length && v.count < out.length; j++) {
            if (j != i && Math.hypot(x[j] - x[i], y[j] - y[i]) <= reach + r[j]) {
                out[v.count++] = Math.toDegrees(Math.atan2(y[j] - y[i], x[j] - x[i]));
            }
        }
        for (int o = 0; o < things.count() && v.count < out.length; o++) {
            if (!things.outside(o, area) && things.nearest(o, x[i], y[i], scratch) <= reach) {
                out[v.count++] = Math.toDegrees(Math.atan2(scratch[1] - y[i], scratch[0] - x[i]));
            }
        }
        return v.count;
    }

    /** Nearest ray hit on a wall segment. */
    private static final class RayVisitor implements ItemVisitor {
        private double ox;
        private double oy;
        private double ux;
        private double uy;
        double best;

        void begin(double ox, double oy, double ux, double uy, double max) {
            this.ox = ox;
            this.oy = oy;
            this.ux = ux;
            this.uy = uy;
            best = max;
        }

        @Override
        public void visitItem(Object item) {
            Segment s = (Segment) item;
            double ex = s.bx - s.ax;
            double ey = s.by - s.ay;
            double denom = ux * ey - uy * ex;
            if (denom == 0) {
                return;
            }
            double qx = s.ax - ox;
            double qy = s.ay - oy;
            double t = (qx * ey - qy * ex) / denom;
            double u = (qx * uy - qy * ux) / denom;
            if (t >= 0 && u >= 0 && u <= 1 && t < best) {
                best = t;
            }
        }
    }

    /** Whether a segment crosses an obstacle edge. */
    private static final class SightVisitor implements ItemVisitor {
        private double ax;
        private double ay;
        private double bx;
        private double by;
        boolean blocked;

        void begin(double ax, double ay, double bx, double by) {
            this.ax = ax;
            this.ay = ay;
            this.bx = bx;
            this.by = by;
            blocked = false;
        }

        @Override
        public void visitItem(Object item) {
            Segment s = (Segment) item;
            if (blocked || s.ownerKind != robosim.protocol.GeometryStepResponse.CONTACT_OBSTACLE) {
                return;
            }
            // blocked when the edge meets the sight line and the line's ends lie strictly on both sides
            // of the edge: a point on the surface itself (a heat source on a wall) stays in sight
            blocked = orient(ax, ay, bx, by, s.ax, s.ay) * orient(ax, ay, bx, by, s.bx, s.by) <= 0
                    && orient(s.ax, s.ay, s.bx, s.by, ax, ay) * orient(s.ax, s.ay, s.bx, s.by, bx, by) < 0;
        }
    }

    /** The side of line P-Q that R lies on: 1 left, -1 right, 0 on it. */
    private static int orient(double px, double py, double qx, double qy, double rx, double ry) {
        return (int) Math.signum((qx - px) * (ry - py) - (qy - py) * (rx - px));
    }

    /** Directions to the wall points within reach of a robot's centre. */
    private static final class TouchVisitor implements ItemVisitor {
        private double cx;
        private double cy;
        private double reach;
        private double[] out;
        int count;

        void begin(double cx, double cy, double reach, double[] out) {
            this.cx = cx;
            this.cy = cy;
            this.reach = reach;
            this.out = out;
            count = 0;
        }

        @Override
        public void visitItem(Object item) {
            Segment s = (Segment) item;
            if (count >= out.length) {
                return;
            }
            double ex = s.bx - s.ax;
            double ey = s.by - s.ay;
            double len2 = ex * ex + ey * ey;
            double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((cx - s.ax) * ex + (cy - s.ay) * ey) / len2));
            double px = s.ax + t * ex;
            double py = s.ay + t * ey;
            if (Math.hypot(px - cx, py - cy) <= reach) {
                out[count++] = Math.toDegrees(Math.atan2(py - cy, px - cx));
            }
        }
    }
}

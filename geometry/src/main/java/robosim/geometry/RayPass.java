package robosim.geometry;

import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.index.ItemVisitor;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.RaySpec;

/**
 * Reads the rays of the robots' proximity sensors in the world as it stands after a step's moves: for each ray, the
 * distance from where it starts to the first wall, obstacle, object or other robot along it, or its range when
 * nothing is that near. Looks at the walls, robots and objects whose boxes meet the ray's (the wall index, the
 * {@link RobotGrid}, each object's bounding box) and tests only those exactly. One per thread.
 */
final class RayPass {
    private final StaticWorld world;
    private final RobotGrid grid;
    private final RobotGrid.Cursor cells;
    private final double[] x;
    private final double[] y;
    private final double[] heading;
    private final double[] radius;
    private final RaySpec[][] rays;
    private final ObjectLayer things;
    private final Envelope area = new Envelope();
    private final Nearest nearest = new Nearest();

    RayPass(StaticWorld world, RobotGrid grid, double[] x, double[] y, double[] heading, double[] radius,
            RaySpec[][] rays, ObjectLayer things) {
        this.world = world;
        this.grid = grid;
        this.cells = grid.new Cursor();
        this.x = x;
        this.y = y;
        this.heading = heading;
        this.radius = radius;
        this.rays = rays;
        this.things = things;
    }

    /** Every ray of every robot that asked for them, in robot order and each robot's ray order, into {@code out}. */
    void read(GeometryStepRequest in, GeometryStepResponse out) {
        for (int i = 0; i < rays.length; i++) {
            if (!in.wantsRays(i)) {
                continue;
            }
            double h = Math.toRadians(heading[i]);
            double c = Math.cos(h);
            double s = Math.sin(h);
            for (RaySpec ray : rays[i]) {
                double ox = x[i] + ray.xMm() * c - ray.yMm() * s;
                double oy = y[i] + ray.xMm() * s + ray.yMm() * c;
                double a = Math.toRadians(heading[i] + ray.angleDeg());
                out.addRay(range(i, ox, oy, Math.cos(a), Math.sin(a), ray.rangeMm()));
            }
        }
    }

    /** Robot i's ray from O along unit u, no further than {@code max}. */
    private double range(int i, double ox, double oy, double ux, double uy, double max) {
        double ex = ox + ux * max;
        double ey = oy + uy * max;
        area.init(Math.min(ox, ex), Math.max(ox, ex), Math.min(oy, ey), Math.max(oy, ey));
        Nearest v = nearest;
        v.begin(ox, oy, ux, uy, max);
        world.query(area, v);
        cells.select(area);
        for (int g = cells.nextCell(); g >= 0; g = cells.nextCell()) {
            for (int j = grid.first(g); j >= 0; j = grid.next(j)) {
                if (j != i && !SonarPass.outside(area, x[j], y[j], radius[j])) {
                    v.best = Math.min(v.best, Sweep.toCircle(ox, oy, ux, uy, radius[j], x[j], y[j]));
                }
            }
        }
        for (int o = 0; o < things.count(); o++) {
            if (!things.outside(o, area)) {
                v.best = Math.min(v.best, things.ray(o, ox, oy, ux, uy));
            }
        }
        return v.best;
    }

    /** The nearest wall along the current ray; reused, so a query allocates nothing. */
    private static final class Nearest implements ItemVisitor {
        private double ox;
        private double oy;
        private double ux;
        private double uy;
        double best;

        void begin(double px, double py, double dx, double dy, double max) {
            ox = px;
            oy = py;
            ux = dx;
            uy = dy;
            best = max;
        }

        @Override
        public void visitItem(Object item) {
            Segment s = (Segment) item;
            best = Math.min(best, Sweep.toCapsule(ox, oy, ux, uy, 0, s));
        }
    }
}

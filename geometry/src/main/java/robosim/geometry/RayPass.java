package robosim.geometry;

import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.index.ItemVisitor;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.RaySpec;

/**
 * Reads the rays of the robots' proximity sensors in the world as it stands after a step's moves: for each ray, the
 * distance from where it starts to the first wall, obstacle, object or other robot along it, or its range when
 * nothing is that near. Looks once per robot for the walls, robots and objects whose boxes meet the box its rays reach
 * (the wall index, the {@link RobotGrid}, each object's bounding box), then tests each ray exactly against those
 * alone. One per thread.
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
            gather(i);
            double h = Math.toRadians(heading[i]);
            double c = Math.cos(h);
            double s = Math.sin(h);
            for (RaySpec ray : rays[i]) {
                double ox = x[i] + ray.xMm() * c - ray.yMm() * s;
                double oy = y[i] + ray.xMm() * s + ray.yMm() * c;
                double a = Math.toRadians(heading[i] + ray.angleDeg());
                out.addRay(range(ox, oy, Math.cos(a), Math.sin(a), ray.rangeMm()));
            }
        }
    }

    /**
     * What robot i's rays may meet, looked up once for all of them (a foot-bot has 24): the walls, robots and objects
     * whose boxes meet the box its rays reach, into {@link #walls}, {@link #robots} and {@link #objects}.
     */
    private void gather(int i) {
        double reach = 0;
        for (RaySpec ray : rays[i]) {
            reach = Math.max(reach, Math.sqrt(ray.xMm() * ray.xMm() + ray.yMm() * ray.yMm()) + ray.rangeMm());
        }
        reach += 1; // (a ray's end may lie a rounding beyond it: what more comes in changes no range)
        area.init(x[i] - reach, x[i] + reach, y[i] - reach, y[i] + reach);
        collected.count = 0;
        world.query(area, collected);
        robotCount = 0;
        cells.select(area);
        for (int g = cells.nextCell(); g >= 0; g = cells.nextCell()) {
            for (int j = grid.first(g); j >= 0; j = grid.next(j)) {
                if (j != i && !SonarPass.outside(area, x[j], y[j], radius[j])) {
                    if (robotCount == robots.length) {
                        robots = java.util.Arrays.copyOf(robots, 2 * robotCount);
                    }
                    robots[robotCount++] = j;
                }
            }
        }
        objectCount = 0;
        for (int o = 0; o < things.count(); o++) {
            if (!things.outside(o, area)) {
                if (objectCount == objects.length) {
                    objects = java.util.Arrays.copyOf(objects, 2 * objectCount);
                }
                objects[objectCount++] = o;
            }
        }
    }

    /** The ray from O along unit u, no further than {@code max}, against what {@link #gather} found. */
    private double range(double ox, double oy, double ux, double uy, double max) {
        double best = max;
        for (int k = 0; k < collected.count; k++) {
            best = Math.min(best, Sweep.toCapsule(ox, oy, ux, uy, 0, collected.walls[k]));
        }
        for (int k = 0; k < robotCount; k++) {
            int j = robots[k];
            best = Math.min(best, Sweep.toCircle(ox, oy, ux, uy, radius[j], x[j], y[j]));
        }
        for (int k = 0; k < objectCount; k++) {
            best = Math.min(best, things.ray(objects[k], ox, oy, ux, uy));
        }
        return best;
    }

    private int[] robots = new int[16];
    private int robotCount;
    private int[] objects = new int[16];
    private int objectCount;
    private final Walls collected = new Walls();

    /** The walls a robot's rays may meet; reused, so a robot's look-up allocates nothing once it has grown. */
    private static final class Walls implements ItemVisitor {
        Segment[] walls = new Segment[16];
        int count;

        @Override
        public void visitItem(Object item) {
            if (count == walls.length) {
                walls = java.util.Arrays.copyOf(walls, 2 * count);
            }
            walls[count++] = (Segment) item;
        }
    }
}

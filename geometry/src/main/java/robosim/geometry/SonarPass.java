package robosim.geometry;

import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.index.ItemVisitor;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.SonarSpec;

/**
 * Reads sonars in the world as it stands after a step's moves: for each transducer, the nearest wall,
 * robot or object inside its cone, up to its range. Looks at the walls, robots and objects whose boxes meet the
 * cone's box (the wall index, the {@link RobotGrid}, each object's bounding box) and tests only those exactly. One per thread: its cone, box,
 * visitor and grid walk are its own, and it writes only the ranges of the robots it is given, so two
 * passes over halves of the robots give the ranges one pass would, bit for bit.
 */
final class SonarPass {
    private final StaticWorld world;
    private final RobotGrid.Cursor cells;
    private final RobotGrid grid;
    private final double[] x;
    private final double[] y;
    private final double[] heading;
    private final double[] radius;
    private final SonarSpec[][] sonars;
    private final ObjectLayer things;
    /** Each sonar's cone vectors in its robot's frame, worked out once ({@link Cone#beam}). */
    private final double[][][] beams;
    private final Envelope area = new Envelope();
    private final Cone cone = new Cone();
    private final Nearest nearest = new Nearest();

    SonarPass(StaticWorld world, RobotGrid grid, double[] x, double[] y, double[] heading, double[] radius,
            SonarSpec[][] sonars, ObjectLayer things) {
        this.things = things;
        this.world = world;
        this.grid = grid;
        this.cells = grid.new Cursor();
        this.x = x;
        this.y = y;
        this.heading = heading;
        this.radius = radius;
        this.sonars = sonars;
        this.beams = new double[sonars.length][][];
        for (int i = 0; i < sonars.length; i++) {
            beams[i] = new double[sonars[i].length][];
            for (int k = 0; k < sonars[i].length; k++) {
                beams[i][k] = Cone.beam(sonars[i][k].angleDeg(), sonars[i][k].coneDeg() / 2);
            }
        }
    }

    /** Reads every sonar of robots {@code from} to {@code to} (exclusive) that asked, each robot's at its offset. */
    void read(GeometryStepRequest in, int from, int to, int[] offset, double[] ranges) {
        for (int i = from; i < to; i++) {
            if (in.wantsSonar(i)) {
                double h = Math.toRadians(heading[i]);
                double c = Math.cos(h);
                double sn = Math.sin(h);
                int k = offset[i];
                for (int b = 0; b < sonars[i].length; b++) {
                    ranges[k++] = range(i, sonars[i][b], beams[i][b], c, sn);
                }
            }
        }
    }

    /** Robot i's sonar {@code s} ({@code beam}: its cone's vectors in the robot's frame; c, sn: the heading's). */
    private double range(int i, SonarSpec s, double[] beam, double c, double sn) {
        double ox = x[i] + s.xMm() * c - s.yMm() * sn;
        double oy = y[i] + s.xMm() * sn + s.yMm() * c;
        double max = s.maxRangeMm();
        cone.aim(ox, oy, c, sn, beam);
        sectorEnvelope(max);
        Nearest v = nearest;
        v.best = max;
        world.query(area, v);
        cells.select(area);
        for (int g = cells.nextCell(); g >= 0; g = cells.nextCell()) {
            for (int j = grid.first(g); j >= 0; j = grid.next(j)) {
                if (j != i && !outside(area, x[j], y[j], radius[j])) {
                    v.best = Math.min(v.best, cone.toDisc(x[j], y[j], radius[j]));
                }
            }
        }
        for (int o = 0; o < things.count(); o++) {
            if (!things.outside(o, area)) {
                v.best = Math.min(v.best, things.cone(cone, o));
            }
        }
        return v.best;
    }

    /** The cheap test first: a disc's bounding box misses {@code area}. */
    static boolean outside(Envelope area, double cx, double cy, double r) {
        return cx + r < area.getMinX() || cx - r > area.getMaxX() || cy + r < area.getMinY() || cy - r > area.getMaxY();
    }

    /** Sets {@link #area} to the bounding box of the cone cut off at {@code range}. */
    private void sectorEnvelope(double range) {
        Cone k = cone;
        double x0 = Math.min(k.ox, Math.min(k.ox + range * k.lx, Math.min(k.ox + range * k.rx, k.ox + range * k.axisX)));
        double x1 = Math.max(k.ox, Math.max(k.ox + range * k.lx, Math.max(k.ox + range * k.rx, k.ox + range * k.axisX)));
        double y0 = Math.min(k.oy, Math.min(k.oy + range * k.ly, Math.min(k.oy + range * k.ry, k.oy + range * k.axisY)));
        double y1 = Math.max(k.oy, Math.max(k.oy + range * k.ly, Math.max(k.oy + range * k.ry, k.oy + range * k.axisY)));
        if (k.contains(k.ox + 1, k.oy)) {
            x1 = Math.max(x1, k.ox + range);
        }
        if (k.contains(k.ox, k.oy + 1)) {
            y1 = Math.max(y1, k.oy + range);
        }
        if (k.contains(k.ox - 1, k.oy)) {
            x0 = Math.min(x0, k.ox - range);
        }
        if (k.contains(k.ox, k.oy - 1)) {
            y0 = Math.min(y0, k.oy - range);
        }
        area.init(x0, x1, y0, y1);
    }

    /** Finds the nearest wall inside the current cone; reused, so a query allocates nothing. */
    private final class Nearest implements ItemVisitor {
        double best;

        @Override
        public void visitItem(Object item) {
            Segment s = (Segment) item;
            best = Math.min(best, cone.toSegment(s.ax, s.ay, s.bx, s.by));
        }
    }
}

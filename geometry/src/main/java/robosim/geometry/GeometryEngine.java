package robosim.geometry;

import java.util.List;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.index.ItemVisitor;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.RobotProperties;
import robosim.protocol.SonarSpec;

/**
 * Resolves one step for every robot: each robot in world order turns (a round body can always
 * turn in place), then moves along its new heading until the distance asked for is covered or it
 * touches a wall, the arena's edge or another robot (at that robot's position so far this step);
 * then every sonar that was asked for reads the world as it stands after all the moves. A robot
 * that touches something stops {@link #CONTACT_GAP_MM} short of it, so shapes never overlap. A robot
 * marked absent (it has left the simulation) is not in the world at all.
 *
 * <p>Deterministic: the same request gives the same response, bit for bit. Not thread-safe (it
 * reuses scratch state); one instance per thread.
 */
public final class GeometryEngine {
    /** How far short of exact contact a blocked robot stops, mm. */
    public static final double CONTACT_GAP_MM = 1e-6;

    private final StaticWorld world;
    private final int robots;
    private final double[] radius;
    private final SonarSpec[][] sonars;
    private final int maxRanges;
    private final double[] x;
    private final double[] y;
    private final double[] heading;
    private final boolean[] absent;
    private final Envelope area = new Envelope();
    private final MoveVisitor moveVisitor = new MoveVisitor();
    private final SonarVisitor sonarVisitor = new SonarVisitor();
    private final Cone cone = new Cone();
    private final RobotGrid grid;

    public GeometryEngine(StaticWorld world, List<RobotProperties> robots) {
        this.world = world;
        this.robots = robots.size();
        this.radius = new double[this.robots];
        this.sonars = new SonarSpec[this.robots][];
        int ranges = 0;
        for (int i = 0; i < this.robots; i++) {
            radius[i] = robots.get(i).radiusMm();
            sonars[i] = robots.get(i).sonars().toArray(new SonarSpec[0]);
            ranges += sonars[i].length;
        }
        this.maxRanges = ranges;
        this.x = new double[this.robots];
        this.y = new double[this.robots];
        this.heading = new double[this.robots];
        this.absent = new boolean[this.robots];
        double maxRadius = 0;
        for (double r : radius) {
            maxRadius = Math.max(maxRadius, r);
        }
        this.grid = new RobotGrid(this.robots, maxRadius);
    }

    public int robotCount() {
        return robots;
    }

    /** A response sized for this world, to be reused with {@link #step}. */
    public GeometryStepResponse newResponse() {
        return new GeometryStepResponse(robots, maxRanges);
    }

    /** Resolves one step into {@code out}, which must come from {@link #newResponse()}. */
    public void step(GeometryStepRequest in, GeometryStepResponse out) {
        if (in.count() != robots) {
            throw new IllegalArgumentException("step batch has " + in.count() + " robots, world has " + robots);
        }
        out.begin(in.step());
        for (int i = 0; i < robots; i++) {
            x[i] = in.xMm(i);
            y[i] = in.yMm(i);
            heading[i] = in.headingDeg(i);
        }
        for (int i = 0; i < robots; i++) {
            absent[i] = in.isAbsent(i);
        }
        grid.rebuild(x, y, absent);
        for (int i = 0; i < robots; i++) {
            if (absent[i]) {
                out.setMotion(i, 0, 0, GeometryStepResponse.CONTACT_NONE, -1);
                continue;
            }
            heading[i] = Kinematics.turn(heading[i], in.turnDeg(i));
            double move = in.moveMm(i);
            double moved = 0;
            byte kind = GeometryStepResponse.CONTACT_NONE;
            int index = -1;
            if (move != 0) {
                double sign = Math.signum(move);
                double dist = Math.abs(move);
                double h = Math.toRadians(heading[i]);
                double t = firstContact(i, sign * Math.cos(h), sign * Math.sin(h), dist);
                if (t <= dist) {
                    moved = Math.max(0, t - CONTACT_GAP_MM);
                    kind = moveVisitor.kind;
                    index = moveVisitor.index;
                } else {
                    moved = dist;
                }
                moved *= sign;
                x[i] += Kinematics.dx(heading[i], moved);
                y[i] += Kinematics.dy(heading[i], moved);
                grid.moved(i, x[i], y[i]);
            }
            out.setMotion(i, moved, in.turnDeg(i), kind, index);
        }
        for (int i = 0; i < robots; i++) {
            if (in.wantsSonar(i)) {
                for (SonarSpec s : sonars[i]) {
                    out.addRange(sonarRange(i, s));
                }
            }
        }
    }

    /** Distance robot i may travel along unit (ux, uy) before first contact; its contact in moveVisitor. */
    private double firstContact(int i, double ux, double uy, double dist) {
        double r = radius[i];
        double px = x[i];
        double py = y[i];
        double ex = px + ux * dist;
        double ey = py + uy * dist;
        area.init(Math.min(px, ex) - r, Math.max(px, ex) + r, Math.min(py, ey) - r, Math.max(py, ey) + r);
        MoveVisitor v = moveVisitor;
        v.begin(px, py, ux, uy, r);
        world.query(area, v);
        grid.select(area);
        for (int c = grid.nextCell(); c >= 0; c = grid.nextCell()) {
            for (int j = grid.first(c); j >= 0; j = grid.next(j)) {
                if (j == i || outsideArea(j)) {
                    continue;
                }
                double t = Sweep.toCircle(px, py, ux, uy, r + radius[j], x[j], y[j]);
                // walls win ties, then the robot first in world order, whatever order the grid gives
                if (t < v.best || (t == v.best && v.kind == GeometryStepResponse.CONTACT_ROBOT && j < v.index)) {
                    v.best = t;
                    v.kind = GeometryStepResponse.CONTACT_ROBOT;
                    v.index = j;
                }
            }
        }
        return v.best;
    }

    private double sonarRange(int i, SonarSpec s) {
        double h = Math.toRadians(heading[i]);
        double c = Math.cos(h);
        double sn = Math.sin(h);
        double ox = x[i] + s.xMm() * c - s.yMm() * sn;
        double oy = y[i] + s.xMm() * sn + s.yMm() * c;
        double max = s.maxRangeMm();
        cone.aim(ox, oy, heading[i] + s.angleDeg(), s.coneDeg() / 2);
        sectorEnvelope(max);
        SonarVisitor v = sonarVisitor;
        v.best = max;
        world.query(area, v);
        grid.select(area);
        for (int g = grid.nextCell(); g >= 0; g = grid.nextCell()) {
            for (int j = grid.first(g); j >= 0; j = grid.next(j)) {
                if (j != i && !outsideArea(j)) {
                    v.best = Math.min(v.best, cone.toDisc(x[j], y[j], radius[j]));
                }
            }
        }
        return v.best;
    }

    /** The cheap test first: robot j's bounding box misses {@link #area}. */
    private boolean outsideArea(int j) {
        double rj = radius[j];
        return x[j] + rj < area.getMinX() || x[j] - rj > area.getMaxX()
                || y[j] + rj < area.getMinY() || y[j] - rj > area.getMaxY();
    }

    /** Sets {@link #area} to the bounding box of the cone cut off at {@code range}. */
    private void sectorEnvelope(double range) {
        Cone k = cone;
        area.init(k.ox, k.ox, k.oy, k.oy);
        area.expandToInclude(k.ox + range * k.lx, k.oy + range * k.ly);
        area.expandToInclude(k.ox + range * k.rx, k.oy + range * k.ry);
        area.expandToInclude(k.ox + range * k.axisX, k.oy + range * k.axisY);
        if (k.contains(k.ox + 1, k.oy)) {
            area.expandToInclude(k.ox + range, k.oy);
        }
        if (k.contains(k.ox, k.oy + 1)) {
            area.expandToInclude(k.ox, k.oy + range);
        }
        if (k.contains(k.ox - 1, k.oy)) {
            area.expandToInclude(k.ox - range, k.oy);
        }
        if (k.contains(k.ox, k.oy - 1)) {
            area.expandToInclude(k.ox, k.oy - range);
        }
    }

    /** Finds the first wall a moving robot would touch; reused, so it allocates nothing per query. */
    private static final class MoveVisitor implements ItemVisitor {
        double px;
        double py;
        double ux;
        double uy;
        double r;
        double best;
        byte kind;
        int index;

        void begin(double px, double py, double ux, double uy, double r) {
            this.px = px;
            this.py = py;
            this.ux = ux;
            this.uy = uy;
            this.r = r;
            best = Sweep.NEVER;
            kind = GeometryStepResponse.CONTACT_NONE;
            index = -1;
        }

        @Override
        public void visitItem(Object item) {
            Segment s = (Segment) item;
            double t = Sweep.toCapsule(px, py, ux, uy, r, s);
            if (t < best) {
                best = t;
                kind = s.ownerKind;
                index = s.ownerIndex;
            }
        }
    }

    /** Finds the nearest wall inside the current cone. */
    private final class SonarVisitor implements ItemVisitor {
        double best;

        @Override
        public void visitItem(Object item) {
            Segment s = (Segment) item;
            best = Math.min(best, cone.toSegment(s.ax, s.ay, s.bx, s.by));
        }
    }
}

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
 * <p>Deterministic: the same request gives the same response, bit for bit, whether the sonar pass
 * runs on one core or two ({@link SonarPass}). Not thread-safe (it reuses scratch state); one instance
 * per thread.
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
    private final RobotGrid grid;
    private final RobotGrid.Cursor cells;
    /** The sonar pass on this thread, and the one a second core runs on the other part of the robots. */
    private final SonarPass sonarPass;
    private final SonarPass helperPass;
    /** Robots asking for sonar from which the pass is split over two cores (0: never). */
    private final int parallelFrom;
    /** Where each robot's ranges begin in {@link #ranges}, this step. */
    private final int[] offset;
    private final double[] ranges;

    /**
     * Robots asking for sonar from which a step's sonar pass is split over two cores by default (when the
     * machine has two): below it the hand-off costs about what it saves (measured with GeometrySteps: 20 robots
     * no gain, 30 a little, 50 a third less; docs/PERFORMANCE.md).
     */
    public static final int DEFAULT_PARALLEL_FROM = 40;

    public GeometryEngine(StaticWorld world, List<RobotProperties> robots) {
        this(world, robots, Runtime.getRuntime().availableProcessors() > 1 ? DEFAULT_PARALLEL_FROM : 0);
    }

    /**
     * @param parallelFrom split the sonar pass over two cores (this thread and one of the common fork-join
     *     pool's) when at least this many robots ask for sonar; 0 never does. The ranges are the same either way.
     */
    public GeometryEngine(StaticWorld world, List<RobotProperties> robots, int parallelFrom) {
        this.parallelFrom = parallelFrom;
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
        this.cells = grid.new Cursor();
        this.offset = new int[this.robots];
        this.ranges = new double[ranges];
        this.sonarPass = new SonarPass(world, grid, x, y, heading, radius, sonars);
        this.helperPass = parallelFrom > 0 ? new SonarPass(world, grid, x, y, heading, radius, sonars) : null;
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
        readSonars(in);
        for (int k = 0; k < rangeCount; k++) {
            out.addRange(ranges[k]);
        }
    }

    private int rangeCount;

    /**
     * Every sonar asked for, into {@link #ranges} in world order: on this thread, or with enough robots
     * asking, the robots after the middle range on a second core while this thread reads the rest.
     */
    private void readSonars(GeometryStepRequest in) {
        int total = 0;
        int asking = 0;
        for (int i = 0; i < robots; i++) {
            offset[i] = total;
            if (in.wantsSonar(i)) {
                total += sonars[i].length;
                asking++;
            }
        }
        rangeCount = total;
        if (parallelFrom <= 0 || asking < parallelFrom) {
            sonarPass.read(in, 0, robots, offset, ranges);
            return;
        }
        int middle = 0;
        while (middle < robots && offset[middle] < total / 2) {
            middle++;
        }
        int split = middle;
        java.util.concurrent.ForkJoinTask<?> other = java.util.concurrent.ForkJoinPool.commonPool()
                .submit(() -> helperPass.read(in, split, robots, offset, ranges));
        try {
            sonarPass.read(in, 0, split, offset, ranges);
        } finally {
            other.join(); // (never left writing into the ranges)
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
        cells.select(area);
        for (int c = cells.nextCell(); c >= 0; c = cells.nextCell()) {
            for (int j = grid.first(c); j >= 0; j = grid.next(j)) {
                if (j == i || SonarPass.outside(area, x[j], y[j], radius[j])) {
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
}

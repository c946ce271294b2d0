package robosim.geometry;

import java.util.List;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.index.ItemVisitor;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.GeometryWorld;
import robosim.protocol.RaySpec;
import robosim.protocol.RobotProperties;
import robosim.protocol.SonarSpec;
import robosim.protocol.WorldObject;

/**
 * Resolves one step for every robot: each robot in world order turns (a round body can always turn in place; with an
 * object in its gripper, as far as the object turns free), then moves along its new heading until the distance asked
 * for is covered or it touches a wall, the arena's edge, another robot (at that robot's position so far this step) or
 * an object that does not give way; a movable object it runs into is pushed ahead of it ({@link #pushFactor}); then
 * every gripper that was asked takes what is in reach, and every sonar and proximity ray that was asked for reads the
 * world as it stands after all the moves. Whatever touches something stops {@link #CONTACT_GAP_MM} short of it, so
 * shapes never overlap. A robot marked absent (it has left the simulation) is not in the world at all.
 *
 * <p>Objects: quasi-static and two-dimensional. An object moves only while something pushes it, and then straight along
 * the pusher's motion, never turning and never into a wall, an obstacle, a robot or an object that does not give way;
 * objects push the movable objects in their way in turn. A robot pushing objects covers
 * {@code m / (m + sum of mu_k m_k)} of its move (m its mass, m_k and mu_k each pushed object's mass and friction): the
 * heavier the load, the slower. An object in a robot's gripper moves and turns with the robot as part of it, blocks
 * and pushes as the robot does; another robot cannot push it.
 *
 * <p>Deterministic: the same request gives the same response, bit for bit, whether the sonar pass
 * runs on one core or two ({@link SonarPass}). Not thread-safe (it reuses scratch state); one instance
 * per thread.
 */
public final class GeometryEngine {
    /** How far short of exact contact a blocked robot or object stops, mm. */
    public static final double CONTACT_GAP_MM = 1e-6;
    /** The most objects one robot pushes at once, in a row; more, and the last one blocks. */
    static final int MAX_PUSHED = 16;

    private final StaticWorld world;
    private final int robots;
    private final double[] radius;
    private final double[] mass;
    private final SonarSpec[][] sonars;
    private final RobotProperties.Gripper[] grippers;
    private final int maxRanges;
    private final int maxRays;
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
    private final RayPass rayPass;
    /** Robots asking for sonar from which the pass is split over two cores (0: never). */
    private final int parallelFrom;
    /** Where each robot's ranges begin in {@link #ranges}, this step. */
    private final int[] offset;
    private final double[] ranges;
    private final ObjectLayer things;
    /** The robot carrying each object this step, or -1. */
    private final int[] carrier;
    /** The objects being pushed by the robot that moves, and how far each has gone along its push. */
    private final int[] pushed = new int[MAX_PUSHED];
    private int pushedCount;
    private final double[] scratch = new double[2];

    /** The world as a Geometry process receives it ({@link GeometryWorld}): walls, robots and objects. */
    public GeometryEngine(GeometryWorld world, int parallelFrom) {
        this(new StaticWorld(world.arena(), world.obstacles()), world.robots(), world.objects(), parallelFrom);
    }

    public GeometryEngine(StaticWorld world, List<RobotProperties> robots) {
        this(world, robots, Runtime.getRuntime().availableProcessors() > 1 ? DEFAULT_PARALLEL_FROM : 0);
    }

    /**
     * Robots asking for sonar from which a step's sonar pass is split over two cores by default (when the
     * machine has two): below it the hand-off costs about what it saves (measured with GeometrySteps: 20 robots
     * no gain, 30 a little, 50 a third less; docs/PERFORMANCE.md).
     */
    public static final int DEFAULT_PARALLEL_FROM = 40;

    public GeometryEngine(StaticWorld world, List<RobotProperties> robots, int parallelFrom) {
        this(world, robots, List.of(), parallelFrom);
    }

    /**
     * @param objects the world's objects, world order (their poses come with each step)
     * @param parallelFrom split the sonar pass over two cores (this thread and one of the common fork-join
     *     pool's) when at least this many robots ask for sonar; 0 never does. The ranges are the same either way.
     */
    public GeometryEngine(StaticWorld world, List<RobotProperties> robots, List<WorldObject> objects,
            int parallelFrom) {
        this.parallelFrom = parallelFrom;
        this.world = world;
        this.robots = robots.size();
        this.radius = new double[this.robots];
        this.mass = new double[this.robots];
        this.sonars = new SonarSpec[this.robots][];
        this.grippers = new RobotProperties.Gripper[this.robots];
        RaySpec[][] rays = new RaySpec[this.robots][];
        int ranges = 0;
        int rayTotal = 0;
        for (int i = 0; i < this.robots; i++) {
            RobotProperties p = robots.get(i);
            radius[i] = p.radiusMm();
            mass[i] = p.massKg();
            sonars[i] = p.sonars().toArray(new SonarSpec[0]);
            rays[i] = p.rays().toArray(new RaySpec[0]);
            grippers[i] = p.gripper();
            ranges += sonars[i].length;
            rayTotal += rays[i].length;
        }
        this.maxRanges = ranges;
        this.maxRays = rayTotal;
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
        this.things = new ObjectLayer(objects);
        this.carrier = new int[objects.size()];
        this.sonarPass = new SonarPass(world, grid, x, y, heading, radius, sonars, things);
        this.helperPass = parallelFrom > 0 ? new SonarPass(world, grid, x, y, heading, radius, sonars, things) : null;
        this.rayPass = new RayPass(world, grid, x, y, heading, radius, rays, things);
    }

    public int robotCount() {
        return robots;
    }

    /** A response sized for this world, to be reused with {@link #step}. */
    public GeometryStepResponse newResponse() {
        return new GeometryStepResponse(robots, maxRanges, maxRays, things.count());
    }

    /** Resolves one step into {@code out}, which must come from {@link #newResponse()}. */
    public void step(GeometryStepRequest in, GeometryStepResponse out) {
        if (in.count() != robots || in.objectCount() != things.count()) {
            throw new IllegalArgumentException("step batch has " + in.count() + " robots and " + in.objectCount()
                    + " objects, world has " + robots + " and " + things.count());
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
        for (int o = 0; o < things.count(); o++) {
            things.place(o, in.objectXMm(o), in.objectYMm(o), in.objectHeadingDeg(o));
            int c = in.carrier(o);
            things.gone(o, c == GeometryStepRequest.GONE);
            carrier[o] = c >= 0 && absent[c] ? -1 : Math.max(c, -1);
        }
        grid.rebuild(x, y, absent);
        for (int i = 0; i < robots; i++) {
            if (absent[i]) {
                out.setMotion(i, 0, 0, GeometryStepResponse.CONTACT_NONE, -1);
                continue;
            }
            double turned = turn(i, in.turnDeg(i));
            double move = in.moveMm(i);
            double moved = 0;
            byte kind = GeometryStepResponse.CONTACT_NONE;
            int index = -1;
            if (move != 0) {
                double sign = Math.signum(move);
                double h = Math.toRadians(heading[i]);
                moved = sign * push(i, sign * Math.cos(h), sign * Math.sin(h), Math.abs(move));
                kind = moveVisitor.kind;
                index = moveVisitor.index;
                x[i] += Kinematics.dx(heading[i], moved);
                y[i] += Kinematics.dy(heading[i], moved);
                double left = Math.abs(move) - Math.abs(moved);
                if (in.slides(i) && kind != GeometryStepResponse.CONTACT_NONE && pushedCount == 0 && left > 0
                        && !carries(i) && slide(i, sign * Math.cos(h), sign * Math.sin(h), left, kind, index)) {
                    x[i] += slideX;
                    y[i] += slideY;
                    out.addSlide(i, slideX, slideY);
                }
                grid.moved(i, x[i], y[i]);
            }
            out.setMotion(i, moved, turned, kind, index);
        }
        for (int i = 0; i < robots; i++) {
            if (in.wantsGrip(i)) {
                out.addGrip(i, grip(i));
            }
        }
        readSonars(in);
        for (int k = 0; k < rangeCount; k++) {
            out.addRange(ranges[k]);
        }
        rayPass.read(in, out);
        for (int o = 0; o < things.count(); o++) {
            out.setObject(o, things.x(o), things.y(o), things.heading(o));
        }
    }

    // ---- sliding --------------------------------------------------------------------------------------------

    /** The last slide worked out ({@link #slide}), world mm. */
    private double slideX;
    private double slideY;
    private final double[] near = new double[2];

    /**
     * Robot i, at its point of contact with what blocked its move along unit u (a {@code kind} thing, {@code index}),
     * slides along it: the rest of its move, {@code left}, projected on the blocker's tangent, as far as that is free
     * ({@link #slideX}, {@link #slideY}). False when it does not slide (it met the blocker head on).
     */
    private boolean slide(int i, double ux, double uy, double left, byte kind, int index) {
        double px = x[i];
        double py = y[i];
        Segment wall = moveVisitor.hit;
        switch (kind) {
            case GeometryStepResponse.CONTACT_ROBOT -> {
                near[0] = x[index];
                near[1] = y[index];
            }
            case GeometryStepResponse.CONTACT_OBJECT -> things.nearest(index, px, py, near);
            default -> {
                double ex = wall.bx - wall.ax;
                double ey = wall.by - wall.ay;
                double len2 = ex * ex + ey * ey;
                double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((px - wall.ax) * ex + (py - wall.ay) * ey) / len2));
                near[0] = wall.ax + t * ex;
                near[1] = wall.ay + t * ey;
            }
        }
        double nx = px - near[0];
        double ny = py - near[1];
        double n = Math.hypot(nx, ny);
        if (n == 0) {
            return false;
        }
        nx /= n;
        ny /= n;
        double into = ux * nx + uy * ny;
        double tx = ux - into * nx;
        double ty = uy - into * ny;
        double along = Math.hypot(tx, ty);
        if (into >= 0 || along < 1e-9) {
            return false;
        }
        tx /= along;
        ty /= along;
        double reach = left * along;
        double free = firstContact(i, tx, ty, reach);
        double s = free > reach ? reach : Math.max(0, free - CONTACT_GAP_MM);
        slideX = tx * s;
        slideY = ty * s;
        return s > 0;
    }

    // ---- turning --------------------------------------------------------------------------------------------

    /**
     * Turns robot i by {@code turn} degrees, as far as the objects in its gripper turn free (found to 1/2^20 of the
     * turn); its heading and its load follow. Returns the angle turned.
     */
    private double turn(int i, double turn) {
        double from = heading[i];
        if (turn == 0 || !carries(i)) {
            heading[i] = Kinematics.turn(from, turn);
            return turn;
        }
        double[] start = loadPoses(i);
        double free = 0;
        if (loadFree(i, start, turn)) {
            free = turn;
        } else {
            double lo = 0;
            double hi = 1;
            for (int k = 0; k < 20; k++) {
                double mid = (lo + hi) / 2;
                if (loadFree(i, start, turn * mid)) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            free = turn * lo;
        }
        placeLoad(i, start, free);
        heading[i] = Kinematics.turn(from, free);
        return free;
    }

    private boolean carries(int i) {
        for (int c : carrier) {
            if (c == i) {
                return true;
            }
        }
        return false;
    }

    /** The poses of robot i's load, x, y, heading an object, in object order. */
    private double[] loadPoses(int i) {
        double[] poses = new double[3 * things.count()];
        for (int o = 0; o < things.count(); o++) {
            poses[3 * o] = things.x(o);
            poses[3 * o + 1] = things.y(o);
            poses[3 * o + 2] = things.heading(o);
        }
        return poses;
    }

    /** Puts robot i's load where turning it by {@code deg} about the robot's centre takes it from {@code start}. */
    private void placeLoad(int i, double[] start, double deg) {
        double a = Math.toRadians(deg);
        double c = Math.cos(a);
        double s = Math.sin(a);
        for (int o = 0; o < things.count(); o++) {
            if (carrier[o] == i) {
                double dx = start[3 * o] - x[i];
                double dy = start[3 * o + 1] - y[i];
                things.place(o, x[i] + dx * c - dy * s, y[i] + dx * s + dy * c,
                        Kinematics.turn(start[3 * o + 2], deg));
            }
        }
    }

    /** True if robot i's load, turned by {@code deg} from {@code start}, overlaps nothing. */
    private boolean loadFree(int i, double[] start, double deg) {
        placeLoad(i, start, deg);
        for (int o = 0; o < things.count(); o++) {
            if (carrier[o] == i && overlaps(o, i)) {
                return false;
            }
        }
        return true;
    }

    /** True if object o, where it stands, overlaps a wall, an obstacle, another object or a robot but {@code own}. */
    private boolean overlaps(int o, int own) {
        things.envelope(o, 0, area);
        OverlapVisitor v = overlapVisitor;
        v.begin(o);
        world.query(area, v);
        if (v.hit) {
            return true;
        }
        for (int p = 0; p < things.count(); p++) {
            if (p != o && carrier[p] != own && !things.outside(p, area) && things.overlapsObject(o, p)) {
                return true;
            }
        }
        cells.select(area);
        for (int c = cells.nextCell(); c >= 0; c = cells.nextCell()) {
            for (int j = grid.first(c); j >= 0; j = grid.next(j)) {
                if (j != own && things.overlapsDisc(o, x[j], y[j], radius[j])) {
                    return true;
                }
            }
        }
        return false;
    }

    private final OverlapVisitor overlapVisitor = new OverlapVisitor();

    /** Whether a wall or obstacle edge overlaps object {@link #object}. */
    private final class OverlapVisitor implements ItemVisitor {
        int object;
        boolean hit;

        void begin(int o) {
            object = o;
            hit = false;
        }

        @Override
        public void visitItem(Object item) {
            Segment s = (Segment) item;
            hit = hit || things.overlapsSegment(object, s.ax, s.ay, s.bx, s.by);
        }
    }

    // ---- moving and pushing ---------------------------------------------------------------------------------

    /**
     * How far robot i travels of {@code dist} along unit (ux, uy), pushing the movable objects it meets (they move
     * with it, at its pace); its contact in {@link #moveVisitor} (with a push, the object it pushes).
     */
    private double push(int i, double ux, double uy, double dist) {
        pushedCount = 0;
        double x0 = x[i];
        double y0 = y[i];
        double travelled = 0;
        double time = 1; // (the share of the step left)
        double factor = 1;
        byte kind = GeometryStepResponse.CONTACT_NONE;
        int index = -1;
        while (true) {
            x[i] = x0 + ux * travelled; // (where it has got to, for the next look ahead; it moves once, at the end)
            y[i] = y0 + uy * travelled;
            double reach = time * dist * factor;
            double t = firstContact(i, ux, uy, reach);
            byte hitKind = moveVisitor.kind;
            int hit = moveVisitor.index;
            for (int k = 0; k < pushedCount; k++) {
                double tk = objectContact(pushed[k], i, ux, uy, reach);
                if (tk < t) {
                    t = tk;
                    hitKind = contactKind;
                    hit = contactIndex;
                }
            }
            if (t > reach) {
                advance(i, ux, uy, reach);
                travelled += reach;
                break;
            }
            double step = Math.max(0, t - CONTACT_GAP_MM);
            advance(i, ux, uy, step);
            travelled += step;
            time -= step / (dist * factor);
            if (pushedCount == 0) {
                kind = hitKind;
                index = hit;
            }
            if (hitKind != GeometryStepResponse.CONTACT_OBJECT || !pushable(hit) || pushedCount == MAX_PUSHED) {
                break;
            }
            pushed[pushedCount++] = hit;
            factor = pushFactor(i);
        }
        x[i] = x0;
        y[i] = y0;
        moveVisitor.kind = kind;
        moveVisitor.index = index;
        return travelled;
    }

    /**
     * The share of its move a robot covers while pushing {@link #pushed}: {@code m / (m + sum of mu_k m_k)}, its mass
     * m against each pushed object's mass m_k times its friction mu_k.
     */
    private double pushFactor(int i) {
        double load = 0;
        for (int k = 0; k < pushedCount; k++) {
            WorldObject o = things.object(pushed[k]);
            load += o.friction() * o.massKg();
        }
        return mass[i] / (mass[i] + load);
    }

    private boolean pushable(int o) {
        if (!things.object(o).movable() || carrier[o] >= 0) {
            return false;
        }
        for (int k = 0; k < pushedCount; k++) {
            if (pushed[k] == o) {
                return false;
            }
        }
        return true;
    }

    /**
     * Moves the objects robot i pushes, and its load, {@code d} along (ux, uy) (the robot itself moves once, at the
     * end).
     */
    private void advance(int i, double ux, double uy, double d) {
        if (d == 0) {
            return;
        }
        for (int o = 0; o < things.count(); o++) {
            if (carrier[o] == i || isPushed(o)) {
                things.place(o, things.x(o) + ux * d, things.y(o) + uy * d, things.heading(o));
            }
        }
    }

    private byte contactKind;
    private int contactIndex;

    /**
     * How far object o, pushed by robot {@code pusher}, may travel along (ux, uy) up to {@code reach} before it touches
     * something (a wall, obstacle, robot or an object not being pushed); what it touches in {@link #contactKind} and
     * {@link #contactIndex}.
     */
    private double objectContact(int o, int pusher, double ux, double uy, double reach) {
        things.envelope(o, 0, area);
        area.expandToInclude(area.getMinX() + ux * reach, area.getMinY() + uy * reach);
        area.expandToInclude(area.getMaxX() + ux * reach, area.getMaxY() + uy * reach);
        ObjectMoveVisitor v = objectMoveVisitor;
        v.begin(o, ux, uy);
        world.query(area, v);
        double best = v.best;
        contactKind = v.kind;
        contactIndex = v.index;
        for (int p = 0; p < things.count(); p++) {
            if (p == o || isPushed(p) || things.outside(p, area)) {
                continue;
            }
            double t = things.toObject(o, p, ux, uy);
            if (t < best) {
                best = t;
                contactKind = GeometryStepResponse.CONTACT_OBJECT;
                contactIndex = p;
            }
        }
        cells.select(area);
        for (int c = cells.nextCell(); c >= 0; c = cells.nextCell()) {
            for (int j = grid.first(c); j >= 0; j = grid.next(j)) {
                if (j == pusher || SonarPass.outside(area, x[j], y[j], radius[j])) {
                    continue;
                }
                double t = things.toDisc(o, ux, uy, x[j], y[j], radius[j]);
                if (t < best) {
                    best = t;
                    contactKind = GeometryStepResponse.CONTACT_ROBOT;
                    contactIndex = j;
                }
            }
        }
        return best;
    }

    private boolean isPushed(int o) {
        for (int k = 0; k < pushedCount; k++) {
            if (pushed[k] == o) {
                return true;
            }
        }
        return false;
    }

    private final ObjectMoveVisitor objectMoveVisitor = new ObjectMoveVisitor();

    /** Finds the first wall a moving object would touch; reused, so it allocates nothing per query. */
    private final class ObjectMoveVisitor implements ItemVisitor {
        int object;
        double ux;
        double uy;
        double best;
        byte kind;
        int index;

        void begin(int o, double dx, double dy) {
            object = o;
            ux = dx;
            uy = dy;
            best = Sweep.NEVER;
            kind = GeometryStepResponse.CONTACT_NONE;
            index = -1;
        }

        @Override
        public void visitItem(Object item) {
            Segment s = (Segment) item;
            double t = things.toSegment(object, ux, uy, s.ax, s.ay, s.bx, s.by);
            if (t < best) {
                best = t;
                kind = s.ownerKind;
                index = s.ownerIndex;
            }
        }
    }

    // ---- gripping -------------------------------------------------------------------------------------------

    /**
     * What robot i's gripper takes: the nearest movable, gripable object no one carries whose nearest point lies within
     * the gripper's reach of the rim and within its half angle of the heading; -1 for none (or no gripper, or a
     * robot that carries already).
     */
    private int grip(int i) {
        RobotProperties.Gripper g = grippers[i];
        if (g == null || carries(i)) {
            return -1;
        }
        int best = -1;
        double bestGap = Double.POSITIVE_INFINITY;
        for (int o = 0; o < things.count(); o++) {
            WorldObject w = things.object(o);
            if (!w.gripable() || carrier[o] >= 0 || things.gone(o)) {
                continue;
            }
            double gap = things.nearest(o, x[i], y[i], scratch) - radius[i];
            double bearing = Math.toDegrees(Math.atan2(scratch[1] - y[i], scratch[0] - x[i])) - heading[i];
            bearing = Math.abs(bearing - 360 * Math.rint(bearing / 360));
            if (gap <= g.reachMm() && bearing <= g.halfAngleDeg() && gap < bestGap) {
                best = o;
                bestGap = gap;
            }
        }
        if (best >= 0) {
            carrier[best] = i;
        }
        return best;
    }

    // ---- sensing --------------------------------------------------------------------------------------------

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

    /**
     * Distance robot i may travel along unit (ux, uy) before first contact, looking no further than {@code dist}; its
     * contact in moveVisitor. Objects carried by robot i move with it: their own sweeps count too; the objects it
     * pushes do not (they move ahead of it).
     */
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
        for (int o = 0; o < things.count(); o++) {
            if (carrier[o] == i || isPushed(o) || things.outside(o, area)) {
                continue;
            }
            double t = things.discTo(o, px, py, ux, uy, r);
            if (t < v.best) {
                v.best = t;
                v.kind = GeometryStepResponse.CONTACT_OBJECT;
                v.index = o;
            }
        }
        for (int o = 0; o < things.count(); o++) {
            if (carrier[o] == i) {
                double best = v.best;
                double t = objectContact(o, i, ux, uy, dist);
                if (t < best && !(contactKind == GeometryStepResponse.CONTACT_OBJECT && carrier[contactIndex] == i)) {
                    v.best = t;
                    v.kind = contactKind;
                    v.index = contactIndex;
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
        /** The wall or arena edge {@link #best} is of (when {@link #kind} is one's). */
        Segment hit;

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
                hit = s;
            }
        }
    }
}

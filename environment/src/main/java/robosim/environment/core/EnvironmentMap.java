package robosim.environment.core;

import java.util.ArrayList;
import java.util.List;
import robosim.protocol.GeometryWorld;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotProperties;
import robosim.protocol.WorldSnapshot;

/**
 * The world as it stands: the static map from the file, every robot's properties (from its
 * handshake) and its current pose (world mm, degrees). Answers snapshots for viewers and the world
 * description for Geometry. Owned by {@link SimulationCore}.
 */
public final class EnvironmentMap {
    private WorldSpec spec;
    private List<RobotProperties> properties;
    private double[] x;
    private double[] y;
    private double[] heading;

    EnvironmentMap(WorldSpec spec, List<RobotProperties> properties) {
        if (properties.size() != spec.robots().size()) {
            throw new IllegalArgumentException("need properties for " + spec.robots().size() + " robots, got "
                    + properties.size());
        }
        this.spec = spec;
        this.properties = List.copyOf(properties);
        int n = properties.size();
        x = new double[n];
        y = new double[n];
        heading = new double[n];
        for (int i = 0; i < n; i++) {
            WorldSpec.RobotSpec r = spec.robots().get(i);
            x[i] = r.xMm();
            y[i] = r.yMm();
            heading[i] = r.headingDeg();
        }
    }

    /** Robot {@code robot} joins the world at its spec's pose; returns its index (the last). */
    int add(WorldSpec.RobotSpec robot, RobotProperties p) {
        int i = x.length;
        spec = spec.withRobot(robot);
        List<RobotProperties> more = new ArrayList<>(properties);
        more.add(p);
        properties = List.copyOf(more);
        x = java.util.Arrays.copyOf(x, i + 1);
        y = java.util.Arrays.copyOf(y, i + 1);
        heading = java.util.Arrays.copyOf(heading, i + 1);
        x[i] = robot.xMm();
        y[i] = robot.yMm();
        heading[i] = robot.headingDeg();
        if (gone != null) {
            gone = java.util.Arrays.copyOf(gone, i + 1);
        }
        return i;
    }

    public WorldSpec spec() {
        return spec;
    }

    public int robotCount() {
        return x.length;
    }

    public String name(int robot) {
        return spec.robots().get(robot).name();
    }

    /** Every robot's properties, world order (an immutable list, replaced when a robot joins). */
    public List<RobotProperties> properties() {
        return properties;
    }

    public RobotProperties properties(int robot) {
        return properties.get(robot);
    }

    public double xMm(int robot) {
        return x[robot];
    }

    public double yMm(int robot) {
        return y[robot];
    }

    public double headingDeg(int robot) {
        return heading[robot];
    }

    /** The live pose arrays, for the sensors' context (read-only use, on the step's thread). */
    double[] xs() {
        return x;
    }

    double[] ys() {
        return y;
    }

    double[] headings() {
        return heading;
    }

    void setPose(int robot, double xMm, double yMm, double headingDeg) {
        x[robot] = xMm;
        y[robot] = yMm;
        heading[robot] = headingDeg;
    }

    /** The robots' poses as a new immutable update, labelled with {@code step}. */
    public PoseUpdate poses(long step) {
        return new PoseUpdate(step, x.clone(), y.clone(), heading.clone(), null, List.of(), departed, held);
    }

    /** As {@link #poses}, with each robot's sonar ranges of that step (taken as they are). */
    PoseUpdate poses(long step, double[][] sonarMm, List<String> tags) {
        return new PoseUpdate(step, x.clone(), y.clone(), heading.clone(), sonarMm, tags, departed, held);
    }

    private List<String> departed = List.of();
    private List<String> held = List.of();
    private boolean[] gone;

    /** Robot {@code robot} has left the simulation. */
    void depart(int robot) {
        if (gone == null) {
            gone = new boolean[x.length];
        }
        hold(robot, false);
        if (!gone[robot]) {
            gone[robot] = true;
            List<String> more = new ArrayList<>(departed);
            more.add(name(robot));
            departed = List.copyOf(more);
        }
    }

    /** Robot {@code robot} is away, held for its return, or back. */
    void hold(int robot, boolean away) {
        List<String> now = new ArrayList<>(held);
        now.remove(name(robot));
        if (away) {
            now.add(name(robot));
        }
        held = List.copyOf(now);
    }

    /** Robots that have left the world. */
    public int departedCount() {
        return departed.size();
    }

    /** True once robot {@code robot} has left. */
    public boolean isGone(int robot) {
        return gone != null && gone[robot];
    }

    /** The robots' radii, mm, in world order. */
    double radiusMm(int robot) {
        return properties.get(robot).radiusMm();
    }

    public GeometryWorld geometryWorld() {
        List<String> names = new ArrayList<>();
        for (WorldSpec.RobotSpec r : spec.robots()) {
            names.add(r.name());
        }
        return new GeometryWorld(spec.arena(), spec.obstacles(), names, properties);
    }

    public WorldSnapshot snapshot(long step) {
        return snapshot(spec, properties, poses(step));
    }

    /** A snapshot of a world whose robots are described by {@code properties}, at the given poses. */
    public static WorldSnapshot snapshot(WorldSpec spec, List<RobotProperties> properties, PoseUpdate poses) {
        List<String> names = new ArrayList<>();
        for (int i = 0; i < properties.size(); i++) {
            names.add(spec.robots().get(i).name());
        }
        return new WorldSnapshot(spec.timeStepMs(), spec.arena(), spec.obstacles(), names, properties, poses);
    }
}

package robosim.environment.core;

import java.util.ArrayList;
import java.util.List;
import robosim.protocol.GeometryWorld;
import robosim.protocol.PoseUpdate;
import robosim.protocol.RobotProperties;
import robosim.protocol.WorldObject;
import robosim.protocol.WorldSnapshot;

/**
 * The world as it stands: the static map from the file, every robot's properties (from its
 * handshake) and its current pose (world mm, degrees), every object's pose and the robot carrying it, if one does.
 * Answers snapshots for viewers and the world description for Geometry. Owned by {@link SimulationCore}.
 */
public final class EnvironmentMap {
    private WorldSpec spec;
    private List<RobotProperties> properties;
    private double[] x;
    private double[] y;
    private double[] heading;
    private final double[] objectX;
    private final double[] objectY;
    private final double[] objectHeading;
    /** Each object out of the world. */
    private final boolean[] objectGone;
    /** The robot carrying each object, or -1. */
    private final int[] carrier;

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
        List<WorldObject> objects = spec.scenery().objects();
        int m = objects.size();
        objectX = new double[m];
        objectY = new double[m];
        objectHeading = new double[m];
        carrier = new int[m];
        objectGone = new boolean[m];
        for (int o = 0; o < m; o++) {
            objectX[o] = objects.get(o).xMm();
            objectY[o] = objects.get(o).yMm();
            objectHeading[o] = objects.get(o).headingDeg();
            carrier[o] = -1;
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

    public int objectCount() {
        return objectX.length;
    }

    public double objectXMm(int object) {
        return objectX[object];
    }

    public double objectYMm(int object) {
        return objectY[object];
    }

    public double objectHeadingDeg(int object) {
        return objectHeading[object];
    }

    /** The robot carrying object {@code object}, or -1. */
    public int carrier(int object) {
        return carrier[object];
    }

    /** True if object {@code object} is out of the world (the world's loop functions removed it). */
    public boolean objectGone(int object) {
        return objectGone[object];
    }

    /** Object {@code object} goes out of the world (let go of by whoever held it), or comes back into it. */
    void objectGone(int object, boolean gone) {
        objectGone[object] = gone;
        if (gone) {
            carrier[object] = -1;
        }
    }

    /** The objects out of the world, in world order (a new array). */
    public int[] objectsGone() {
        int n = 0;
        for (boolean g : objectGone) {
            n += g ? 1 : 0;
        }
        int[] out = new int[n];
        for (int o = 0, k = 0; o < objectGone.length; o++) {
            if (objectGone[o]) {
                out[k++] = o;
            }
        }
        return out;
    }

    /** The object robot {@code robot} carries, or -1. */
    public int carried(int robot) {
        for (int o = 0; o < carrier.length; o++) {
            if (carrier[o] == robot) {
                return o;
            }
        }
        return -1;
    }

    void setObjectPose(int object, double xMm, double yMm, double headingDeg) {
        objectX[object] = xMm;
        objectY[object] = yMm;
        objectHeading[object] = headingDeg;
    }

    /** Object {@code object} is now carried by robot {@code robot} (-1: by none). */
    void carry(int object, int robot) {
        carrier[object] = robot;
    }

    /** The robots' poses (and the objects') as a new immutable update, labelled with {@code step}. */
    public PoseUpdate poses(long step) {
        return scene(new PoseUpdate(step, x.clone(), y.clone(), heading.clone(), null, List.of(), departed, held),
                null);
    }

    /** As {@link #poses}, with each robot's sonar ranges of that step and its LEDs (each taken as it is). */
    PoseUpdate poses(long step, double[][] sonarMm, List<String> tags, int[][] leds) {
        return scene(new PoseUpdate(step, x.clone(), y.clone(), heading.clone(), sonarMm, tags, departed, held), leds);
    }

    private PoseUpdate scene(PoseUpdate robots, int[][] leds) {
        if (objectX.length == 0 && leds == null) {
            return robots;
        }
        return robots.withScene(objectX.clone(), objectY.clone(), objectHeading.clone(), leds);
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
        return new GeometryWorld(spec.arena(), spec.obstacles(), names, properties, spec.scenery().objects());
    }

    /** A snapshot of a world whose robots are described by {@code properties}, at the given poses. */
    public static WorldSnapshot snapshot(WorldSpec spec, List<RobotProperties> properties, PoseUpdate poses) {
        List<String> names = new ArrayList<>();
        for (int i = 0; i < properties.size(); i++) {
            names.add(spec.robots().get(i).name());
        }
        return new WorldSnapshot(spec.timeStepMs(), spec.arena(), spec.obstacles(), names, properties, poses,
                spec.scenery());
    }
}

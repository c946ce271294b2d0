package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.List;

/**
 * Environment -> viewer, after each step: every robot's pose (mm, degrees) at the end of
 * {@code step}, in snapshot order, and the sonar ranges (mm) each robot read in that step (none if it
 * did not ask), and every tag so far as "tagger>target" (cumulative, so a viewer that skips steps
 * misses none), and the names of the robots that have left the simulation (cumulative too; a viewer
 * draws them as gone; their last pose stays in the arrays), and the robots away now, standing where they
 * were until they come back ({@code --on-robot-loss HOLD} or {@code WAIT}). Immutable once built, so one instance is shared by every viewer worker; a live
 * viewer may see only some steps, a recording viewer sees all.
 */
public final class PoseUpdate implements java.io.Externalizable {
    private long step;
    private double[] xMm = new double[0];
    private double[] yMm = new double[0];
    private double[] headingDeg = new double[0];
    private double[][] sonarMm = new double[0][];
    private List<String> tags = List.of();
    private List<String> departed = List.of();
    private List<String> held = List.of();
    /** Each object's pose at the end of the step, in the snapshot's order (none in a world without objects). */
    private double[] objectXMm = NONE;
    private double[] objectYMm = NONE;
    private double[] objectHeadingDeg = NONE;
    /** Each robot's LED colours ({@code 0xRRGGBB}, black is off), its LEDs' order; {@link #NO_LEDS} for none. */
    private int[][] leds;
    /** What the world's loop functions painted over the floor, its lights as they switched them (null: as the
     * file's), and the metrics they reported this step. */
    private List<Floor.Region> paint = List.of();
    private boolean[] lightsOn;
    private List<Report> reports = List.of();
    /** What the loop functions drew over the world this step ({@link Traces}: a piece), and the whole drawing as of it. */
    private Traces traces = Traces.NONE;
    private Traces tracesWhole = Traces.NONE;
    /** The objects the loop functions took out of the world, in world order. */
    private int[] objectsGone = NO_OBJECTS;

    private static final double[] NONE = new double[0];
    private static final int[] NO_OBJECTS = new int[0];
    /** The LEDs of a robot that has none, or whose LEDs are all off and always were. */
    public static final int[] NO_LEDS = new int[0];

    public PoseUpdate() {
    }

    /** Poses without sonar ranges. Takes the arrays as they are: the caller must not change them. */
    public PoseUpdate(long step, double[] xMm, double[] yMm, double[] headingDeg) {
        this(step, xMm, yMm, headingDeg, null);
    }

    /**
     * Takes the arrays as they are: the caller must never change them afterwards.
     *
     * @param sonarMm per robot its ranges this step (an empty array if none); null for none at all
     */
    public PoseUpdate(long step, double[] xMm, double[] yMm, double[] headingDeg, double[][] sonarMm) {
        if (xMm.length != yMm.length || xMm.length != headingDeg.length
                || (sonarMm != null && sonarMm.length != xMm.length)) {
            throw new IllegalArgumentException("pose arrays differ in length");
        }
        this.step = step;
        this.xMm = xMm;
        this.yMm = yMm;
        this.headingDeg = headingDeg;
        if (sonarMm == null) {
            sonarMm = new double[xMm.length][];
            java.util.Arrays.fill(sonarMm, NONE);
        }
        this.sonarMm = sonarMm;
    }

    /** As above, with the tags so far ("tagger>target", oldest first; taken as it is). */
    public PoseUpdate(long step, double[] xMm, double[] yMm, double[] headingDeg, double[][] sonarMm,
            List<String> tags) {
        this(step, xMm, yMm, headingDeg, sonarMm);
        this.tags = tags;
    }

    /** As above, with the robots that have left so far (names, in the order they left; taken as it is). */
    public PoseUpdate(long step, double[] xMm, double[] yMm, double[] headingDeg, double[][] sonarMm,
            List<String> tags, List<String> departed) {
        this(step, xMm, yMm, headingDeg, sonarMm, tags);
        this.departed = departed;
    }

    /** As above, with the robots away now, held for their return (names, in the order they were lost). */
    public PoseUpdate(long step, double[] xMm, double[] yMm, double[] headingDeg, double[][] sonarMm,
            List<String> tags, List<String> departed, List<String> held) {
        this(step, xMm, yMm, headingDeg, sonarMm, tags, departed);
        this.held = held;
    }

    /**
     * This update with the objects' poses and the robots' LED colours of its step (taken as they are: the caller must
     * never change them; {@code leds} null or a robot's {@link #NO_LEDS} for none).
     */
    public PoseUpdate withScene(double[] objectX, double[] objectY, double[] objectHeading, int[][] robotLeds) {
        if (objectX.length != objectY.length || objectX.length != objectHeading.length
                || (robotLeds != null && robotLeds.length != xMm.length)) {
            throw new IllegalArgumentException("object or LED arrays differ in length");
        }
        PoseUpdate u = new PoseUpdate(step, xMm, yMm, headingDeg, sonarMm, tags, departed, held);
        u.objectXMm = objectX;
        u.objectYMm = objectY;
        u.objectHeadingDeg = objectHeading;
        u.leds = robotLeds;
        u.paint = paint;
        u.lightsOn = lightsOn;
        u.reports = reports;
        u.traces = traces;
        u.tracesWhole = tracesWhole;
        u.objectsGone = objectsGone;
        return u;
    }

    /**
     * This update with what the world's loop functions left of its step: {@code painted} over the floor (oldest
     * first), {@code lights} as they stand (switched on or off), the metrics they reported for the step, what they
     * drew over the world ({@code piece}, this step's, and {@code whole}, the drawing as of this step, which a
     * snapshot made of this update carries: {@link #posesOnly}), and the objects they took out of the world
     * ({@code gone}, in world order).
     */
    public PoseUpdate withExperiment(List<Floor.Region> painted, List<Light> lights, List<Report> metrics,
            Traces piece, Traces whole, int[] gone) {
        PoseUpdate u = withScene(objectXMm, objectYMm, objectHeadingDeg, leds);
        u.paint = List.copyOf(painted);
        u.lightsOn = new boolean[lights.size()];
        for (int i = 0; i < lights.size(); i++) {
            u.lightsOn[i] = lights.get(i).on();
        }
        u.reports = List.copyOf(metrics);
        u.traces = piece;
        u.tracesWhole = whole;
        u.objectsGone = gone;
        return u;
    }

    /** The objects the world's loop functions took out of it (in world order; none without them). */
    public int[] objectsGone() {
        return objectsGone.clone();
    }

    /** True if object {@code o} is out of the world (its loop functions removed it): viewers leave it out. */
    public boolean objectGone(int o) {
        return java.util.Arrays.binarySearch(objectsGone, o) >= 0;
    }

    /** What the world's loop functions drew over it this step (a piece of the drawing: {@link Traces.Log#apply}). */
    public Traces traces() {
        return traces;
    }

    /**
     * This update, what it draws preceded by what {@code earlier} drew: the update a viewer is sent instead of both
     * (its queue keeps the newest).
     */
    public PoseUpdate drawnAfter(PoseUpdate earlier) {
        if (earlier.traces.isEmpty()) {
            return this;
        }
        PoseUpdate u = withScene(objectXMm, objectYMm, objectHeadingDeg, leds);
        u.traces = earlier.traces.then(traces);
        return u;
    }

    /** This update drawing {@code piece} instead of what it drew (a replay's: a piece of its own drawing). */
    public PoseUpdate withPiece(Traces piece) {
        PoseUpdate u = withScene(objectXMm, objectYMm, objectHeadingDeg, leds);
        u.traces = piece;
        return u;
    }

    /**
     * This update drawing {@code whole}, the drawing as of its step, entire (a replay's snapshot: the drawing pieced
     * together from the recorded steps).
     */
    public PoseUpdate withWholeDrawing(Traces whole) {
        PoseUpdate u = withScene(objectXMm, objectYMm, objectHeadingDeg, leds);
        u.traces = whole;
        u.tracesWhole = whole;
        return u;
    }

    /** What the world's loop functions have painted over the floor, oldest first (none: the file's floor). */
    public List<Floor.Region> paint() {
        return paint;
    }

    /** Light {@code light} of {@code file} (the world's lights) as it stands in this step: switched as loop functions left it. */
    public Light light(List<Light> file, int light) {
        Light l = file.get(light);
        if (lightsOn == null || light >= lightsOn.length || lightsOn[light] == l.on()) {
            return l;
        }
        return new Light(l.name(), l.xMm(), l.yMm(), l.heightMm(), l.rgb(), l.intensity(), lightsOn[light]);
    }

    /** Whether each light is on, as the world's loop functions left it (a copy); null in a world without them. */
    public boolean[] lightsOn() {
        return lightsOn == null ? null : lightsOn.clone();
    }

    /** The metrics the world's loop functions reported for this step. */
    public List<Report> reports() {
        return reports;
    }

    /**
     * The poses alone: the same step, robots, poses, objects, LEDs and who has left or is away, without sonar ranges
     * or tags (what a {@link WorldSnapshot} carries). Shares this update's arrays.
     */
    public PoseUpdate posesOnly() {
        PoseUpdate u = new PoseUpdate(step, xMm, yMm, headingDeg, null, List.of(), departed, held)
                .withScene(objectXMm, objectYMm, objectHeadingDeg, leds);
        u.paint = paint; // (a viewer joining mid-run sees the loop functions' paint and lights at once)
        u.lightsOn = lightsOn;
        u.reports = reports;
        u.traces = tracesWhole; // (and their whole drawing)
        u.tracesWhole = tracesWhole;
        u.objectsGone = objectsGone;
        return u;
    }

    /** Objects whose poses it holds: all the world's, or none. */
    public int objectCount() {
        return objectXMm.length;
    }

    public double objectXMm(int object) {
        return objectXMm[object];
    }

    public double objectYMm(int object) {
        return objectYMm[object];
    }

    public double objectHeadingDeg(int object) {
        return objectHeadingDeg[object];
    }

    /** Robot {@code robot}'s LED colours, its LEDs' order ({@link #NO_LEDS} for none). Do not change. */
    public int[] leds(int robot) {
        return leds == null ? NO_LEDS : leds[robot];
    }

    /** The robots away now, standing where they were until they come back, in the order they were lost. */
    public List<String> held() {
        return held;
    }

    /** The robots that have left the simulation so far, in the order they left. */
    public List<String> departed() {
        return departed;
    }

    /** Every tag so far, "tagger>target", oldest first. */
    public List<String> tags() {
        return tags;
    }

    public long step() {
        return step;
    }

    public int count() {
        return xMm.length;
    }

    public double xMm(int robot) {
        return xMm[robot];
    }

    public double yMm(int robot) {
        return yMm[robot];
    }

    public double headingDeg(int robot) {
        return headingDeg[robot];
    }

    /** Robot's sonar ranges this step, in its layout order; empty if it did not read them. Do not change. */
    public double[] sonarMm(int robot) {
        return sonarMm[robot];
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeLong(step);
        out.writeInt(xMm.length);
        for (int i = 0; i < xMm.length; i++) {
            out.writeDouble(xMm[i]);
            out.writeDouble(yMm[i]);
            out.writeDouble(headingDeg[i]);
            out.writeByte(sonarMm[i].length);
            Wire.writeDoubles(out, sonarMm[i], sonarMm[i].length);
        }
        Wire.writeStrings(out, tags);
        Wire.writeStrings(out, departed);
        Wire.writeStrings(out, held);
        out.writeInt(objectXMm.length);
        for (int o = 0; o < objectXMm.length; o++) {
            out.writeDouble(objectXMm[o]);
            out.writeDouble(objectYMm[o]);
            out.writeDouble(objectHeadingDeg[o]);
        }
        out.writeBoolean(leds != null);
        if (leds != null) {
            for (int[] robot : leds) {
                out.writeByte(robot.length);
                for (int c : robot) {
                    out.writeInt(c);
                }
            }
        }
        out.writeBoolean(lightsOn != null);
        if (lightsOn != null) {
            Floor.writeRegions(out, paint);
            out.writeShort(lightsOn.length);
            for (boolean on : lightsOn) {
                out.writeBoolean(on);
            }
            Report.write(out, reports);
            traces.write(out);
            out.writeInt(objectsGone.length);
            for (int o : objectsGone) {
                out.writeInt(o);
            }
        }
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        step = in.readLong();
        int n = Limits.checkCount("robot count", in.readInt(), Limits.MAX_ROBOTS);
        xMm = new double[n];
        yMm = new double[n];
        headingDeg = new double[n];
        sonarMm = new double[n][];
        for (int i = 0; i < n; i++) {
            xMm[i] = in.readDouble();
            yMm[i] = in.readDouble();
            headingDeg[i] = in.readDouble();
            int ranges = Limits.checkCount("sonar range count", in.readUnsignedByte(), Limits.MAX_SONARS);
            sonarMm[i] = ranges == 0 ? NONE : Wire.readDoubles(in, ranges);
        }
        tags = Wire.readStrings(in, "tag count", Limits.MAX_TAGS);
        departed = Wire.readStrings(in, "departed robot count", Limits.MAX_ROBOTS);
        held = Wire.readStrings(in, "held robot count", Limits.MAX_ROBOTS);
        if (!RecordingVersion.withScene(in)) {
            return; // (a recording made before objects and LEDs)
        }
        int objects = Limits.checkCount("object count", in.readInt(), Limits.MAX_OBJECTS);
        objectXMm = objects == 0 ? NONE : new double[objects];
        objectYMm = objects == 0 ? NONE : new double[objects];
        objectHeadingDeg = objects == 0 ? NONE : new double[objects];
        for (int o = 0; o < objects; o++) {
            objectXMm[o] = in.readDouble();
            objectYMm[o] = in.readDouble();
            objectHeadingDeg[o] = in.readDouble();
        }
        if (in.readBoolean()) {
            leds = new int[n][];
            for (int i = 0; i < n; i++) {
                int count = Limits.checkCount("LED count", in.readUnsignedByte(), Limits.MAX_LEDS);
                leds[i] = count == 0 ? NO_LEDS : new int[count];
                for (int k = 0; k < count; k++) {
                    leds[i][k] = in.readInt() & 0xFFFFFF;
                }
            }
        }
        if (!RecordingVersion.withExperiment(in) || !in.readBoolean()) {
            return; // (no loop functions, or a recording made before them)
        }
        paint = List.copyOf(Floor.readRegions(in));
        lightsOn = new boolean[Limits.checkCount("light count", in.readUnsignedShort(), Limits.MAX_LIGHTS)];
        for (int i = 0; i < lightsOn.length; i++) {
            lightsOn[i] = in.readBoolean();
        }
        reports = Report.read(in, Report.MAX_PER_STEP);
        if (RecordingVersion.withTraces(in)) {
            traces = Traces.read(in);
            tracesWhole = traces.fresh() ? traces : Traces.NONE; // (a piece alone: the drawing before it is not here)
            objectsGone = new int[Limits.checkCount("gone object count", in.readInt(), objectXMm.length)];
            for (int k = 0; k < objectsGone.length; k++) {
                objectsGone[k] = in.readInt();
                if (objectsGone[k] < 0 || objectsGone[k] >= objectXMm.length
                        || (k > 0 && objectsGone[k] <= objectsGone[k - 1])) {
                    throw new ProtocolException("gone object " + objectsGone[k] + " (of " + objectXMm.length
                            + ", in world order, once each)");
                }
            }
        }
    }
}

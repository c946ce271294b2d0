package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * Geometry -> Environment, once per step, in answer to {@link GeometryStepRequest}: for every robot
 * in world order the distance it actually moved (mm, signed like the request) and turned (deg),
 * what it touched (a kind and an index into the world's robots, obstacles or objects), and - for the robots
 * that asked - its sonar ranges (mm), concatenated in robot order and sonar-layout order, and its proximity rays'
 * ranges (mm), likewise; then every object's pose at the end of the step, and each gripping robot's catch (the object
 * its gripper took, or -1).
 */
public final class GeometryStepResponse implements java.io.Externalizable {
    public static final byte CONTACT_NONE = 0;
    public static final byte CONTACT_ROBOT = 1;
    public static final byte CONTACT_OBSTACLE = 2;
    public static final byte CONTACT_ARENA = 3;
    public static final byte CONTACT_OBJECT = 4;

    private long step;
    private int count;
    private double[] movedMm = new double[0];
    private double[] turnedDeg = new double[0];
    private byte[] contactKind = new byte[0];
    private int[] contactIndex = new int[0];
    private int rangeCount;
    private double[] rangesMm = new double[0];
    private int rayCount;
    private double[] rayRangesMm = new double[0];
    private int objects;
    private double[] objectXMm = new double[0];
    private double[] objectYMm = new double[0];
    private double[] objectHeadingDeg = new double[0];
    /** Robots that asked to grip this step, and what each took (-1: nothing), in robot order. */
    private int grips;
    private int[] gripRobot = new int[0];
    private int[] gripObject = new int[0];
    /** Robots that slid along what blocked them, and how far, world mm (beyond their move along their heading). */
    private int slides;
    private int[] slideRobot = new int[0];
    private double[] slideXMm = new double[0];
    private double[] slideYMm = new double[0];

    public GeometryStepResponse() {
    }

    public GeometryStepResponse(int robots, int maxRanges) {
        this(robots, maxRanges, 0, 0);
    }

    /** An answer for {@code robots} robots and {@code objects} objects, with room for the ranges and rays given. */
    public GeometryStepResponse(int robots, int maxRanges, int maxRays, int objects) {
        resize(robots, maxRanges, maxRays, objects);
    }

    private void resize(int robots, int ranges, int rays, int objectCount) {
        count = robots;
        movedMm = new double[robots];
        turnedDeg = new double[robots];
        contactKind = new byte[robots];
        contactIndex = new int[robots];
        rangesMm = new double[ranges];
        rayRangesMm = new double[rays];
        objects = objectCount;
        objectXMm = new double[objectCount];
        objectYMm = new double[objectCount];
        objectHeadingDeg = new double[objectCount];
        gripRobot = new int[robots];
        gripObject = new int[robots];
        slideRobot = new int[robots];
        slideXMm = new double[robots];
        slideYMm = new double[robots];
    }

    /**
     * Starts filling in the answer to one step; ranges, rays and grips are appended ({@link #addRange},
     * {@link #addRay}, {@link #addGrip}), objects set ({@link #setObject}).
     */
    public void begin(long step) {
        this.step = step;
        this.rangeCount = 0;
        this.rayCount = 0;
        this.grips = 0;
        this.slides = 0;
    }

    public void setMotion(int robot, double moved, double turned, byte kind, int index) {
        movedMm[robot] = moved;
        turnedDeg[robot] = turned;
        contactKind[robot] = kind;
        contactIndex[robot] = index;
    }

    public void addRange(double mm) {
        rangesMm[rangeCount++] = mm;
    }

    public void addRay(double mm) {
        rayRangesMm[rayCount++] = mm;
    }

    /** Object {@code o}'s pose at the end of the step. */
    public void setObject(int o, double x, double y, double heading) {
        objectXMm[o] = x;
        objectYMm[o] = y;
        objectHeadingDeg[o] = heading;
    }

    /** Robot {@code robot}, which asked to grip, took object {@code object} (-1: nothing); robots in order. */
    public void addGrip(int robot, int object) {
        gripRobot[grips] = robot;
        gripObject[grips++] = object;
    }

    /**
     * Robot {@code robot} slid ({@code dx}, {@code dy}) world mm along what blocked it, after its move along its
     * heading; robots in order.
     */
    public void addSlide(int robot, double dx, double dy) {
        slideRobot[slides] = robot;
        slideXMm[slides] = dx;
        slideYMm[slides++] = dy;
    }

    public int slideCount() {
        return slides;
    }

    public int slideRobot(int k) {
        return slideRobot[k];
    }

    public double slideXMm(int k) {
        return slideXMm[k];
    }

    public double slideYMm(int k) {
        return slideYMm[k];
    }

    public int rayCount() {
        return rayCount;
    }

    public double rayMm(int i) {
        return rayRangesMm[i];
    }

    public int objectCount() {
        return objects;
    }

    public double objectXMm(int o) {
        return objectXMm[o];
    }

    public double objectYMm(int o) {
        return objectYMm[o];
    }

    public double objectHeadingDeg(int o) {
        return objectHeadingDeg[o];
    }

    public int gripCount() {
        return grips;
    }

    /** The k-th gripping robot's index. */
    public int gripRobot(int k) {
        return gripRobot[k];
    }

    /** What the k-th gripping robot took: an object's index, or -1. */
    public int gripObject(int k) {
        return gripObject[k];
    }

    public long step() {
        return step;
    }

    public int count() {
        return count;
    }

    public double movedMm(int i) {
        return movedMm[i];
    }

    public double turnedDeg(int i) {
        return turnedDeg[i];
    }

    public byte contactKind(int i) {
        return contactKind[i];
    }

    public int contactIndex(int i) {
        return contactIndex[i];
    }

    public int rangeCount() {
        return rangeCount;
    }

    public double rangeMm(int i) {
        return rangesMm[i];
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeLong(step);
        out.writeInt(count);
        for (int i = 0; i < count; i++) {
            out.writeDouble(movedMm[i]);
            out.writeDouble(turnedDeg[i]);
            out.writeByte(contactKind[i]);
            out.writeInt(contactIndex[i]);
        }
        out.writeInt(rangeCount);
        Wire.writeDoubles(out, rangesMm, rangeCount);
        out.writeInt(rayCount);
        Wire.writeDoubles(out, rayRangesMm, rayCount);
        out.writeInt(objects);
        for (int o = 0; o < objects; o++) {
            out.writeDouble(objectXMm[o]);
            out.writeDouble(objectYMm[o]);
            out.writeDouble(objectHeadingDeg[o]);
        }
        out.writeInt(grips);
        for (int k = 0; k < grips; k++) {
            out.writeInt(gripRobot[k]);
            out.writeInt(gripObject[k]);
        }
        out.writeInt(slides);
        for (int k = 0; k < slides; k++) {
            out.writeInt(slideRobot[k]);
            out.writeDouble(slideXMm[k]);
            out.writeDouble(slideYMm[k]);
        }
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        step = in.readLong();
        int robots = Limits.checkCount("robot count", in.readInt(), Limits.MAX_ROBOTS);
        movedMm = new double[robots];
        turnedDeg = new double[robots];
        contactKind = new byte[robots];
        contactIndex = new int[robots];
        count = robots;
        for (int i = 0; i < robots; i++) {
            movedMm[i] = in.readDouble();
            turnedDeg[i] = in.readDouble();
            contactKind[i] = in.readByte();
            contactIndex[i] = in.readInt();
        }
        rangeCount = Limits.checkCount("range count", in.readInt(), Limits.MAX_RANGES);
        rangesMm = Wire.readDoubles(in, rangeCount);
        rayCount = Limits.checkCount("ray count", in.readInt(), Limits.MAX_RANGES);
        rayRangesMm = Wire.readDoubles(in, rayCount);
        objects = Limits.checkCount("object count", in.readInt(), Limits.MAX_OBJECTS);
        objectXMm = new double[objects];
        objectYMm = new double[objects];
        objectHeadingDeg = new double[objects];
        for (int o = 0; o < objects; o++) {
            objectXMm[o] = in.readDouble();
            objectYMm[o] = in.readDouble();
            objectHeadingDeg[o] = in.readDouble();
        }
        grips = Limits.checkCount("grip count", in.readInt(), robots);
        gripRobot = new int[grips];
        gripObject = new int[grips];
        for (int k = 0; k < grips; k++) {
            gripRobot[k] = in.readInt();
            gripObject[k] = in.readInt();
        }
        slides = Limits.checkCount("slide count", in.readInt(), robots);
        slideRobot = new int[slides];
        slideXMm = new double[slides];
        slideYMm = new double[slides];
        for (int k = 0; k < slides; k++) {
            slideRobot[k] = in.readInt();
            slideXMm[k] = in.readDouble();
            slideYMm[k] = in.readDouble();
        }
    }
}

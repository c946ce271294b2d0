package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * Environment -> Geometry, once per step: for every robot in world order its pose at the start of
 * the step (mm, degrees), the requested turn (deg) and move (mm, along the heading after the turn),
 * and a flags byte: {@link #SONAR} (its sonar ranges are wanted), {@link #RAYS} (its proximity rays' ranges are
 * wanted), {@link #GRIP} (its gripper takes what is in reach after the step's moves) and {@link #ABSENT} (the robot
 * has left the simulation: it neither moves, blocks nor echoes, and gets no ranges); then for every object in world
 * order its pose at the start of the step and the robot carrying it (-1 for none; {@link #GONE}, -2, for an object out of
 * the world, which loop functions removed). Geometry is stateless between
 * steps.
 *
 * <p>The sender may reuse one instance and its arrays from step to step (the connection writes
 * messages unshared); a received instance owns fresh arrays.
 */
public final class GeometryStepRequest implements java.io.Externalizable {
    private long step;
    private int count;
    private double[] xMm = new double[0];
    private double[] yMm = new double[0];
    private double[] headingDeg = new double[0];
    private double[] turnDeg = new double[0];
    private double[] moveMm = new double[0];
    private byte[] flags = new byte[0];
    private int objects;
    private double[] objectXMm = new double[0];
    private double[] objectYMm = new double[0];
    private double[] objectHeadingDeg = new double[0];
    private int[] carrier = new int[0];

    /** Flag: this robot's sonar ranges are wanted. */
    public static final byte SONAR = 1;
    /** Flag: this robot has left; the world goes on without it. */
    public static final byte ABSENT = 2;
    /** Flag: this robot's gripper takes the object in reach, if any, after the step's moves. */
    public static final byte GRIP = 4;
    /** Flag: this robot's proximity rays' ranges are wanted. */
    public static final byte RAYS = 8;
    /**
     * Flag: this robot slides along what blocks it (a wheeled swarm robot's contact, as ARGoS's dynamics2d has it), where
     * a robot without it stops where it touches.
     */
    public static final byte SLIDE = 16;
    /** An object's carrier that says it is out of the world: nothing meets, sees or holds it this step. */
    public static final int GONE = -2;

    public GeometryStepRequest() {
    }

    public GeometryStepRequest(int robots) {
        this(robots, 0);
    }

    /** A request for {@code robots} robots and {@code objects} objects, each object carried by none. */
    public GeometryStepRequest(int robots, int objects) {
        resize(robots);
        resizeObjects(objects);
    }

    private void resizeObjects(int n) {
        objects = n;
        objectXMm = new double[n];
        objectYMm = new double[n];
        objectHeadingDeg = new double[n];
        carrier = new int[n];
        java.util.Arrays.fill(carrier, -1);
    }

    private void resize(int n) {
        count = n;
        xMm = new double[n];
        yMm = new double[n];
        headingDeg = new double[n];
        turnDeg = new double[n];
        moveMm = new double[n];
        flags = new byte[n];
    }

    public void setStep(long step) {
        this.step = step;
    }

    public void set(int robot, double x, double y, double heading, double turn, double move, boolean wantsSonar) {
        set(robot, x, y, heading, turn, move, wantsSonar ? SONAR : 0);
    }

    /** Robot {@code robot}'s pose, turn, move and flags ({@link #SONAR}, {@link #RAYS}, {@link #GRIP}, {@link #SLIDE}). */
    public void set(int robot, double x, double y, double heading, double turn, double move, byte robotFlags) {
        xMm[robot] = x;
        yMm[robot] = y;
        headingDeg[robot] = heading;
        turnDeg[robot] = turn;
        moveMm[robot] = move;
        flags[robot] = (byte) (robotFlags & (SONAR | RAYS | GRIP | SLIDE));
    }

    /** Object {@code object}'s pose at the start of the step, and the robot carrying it (-1 for none, {@link #GONE}). */
    public void setObject(int object, double x, double y, double heading, int carriedBy) {
        objectXMm[object] = x;
        objectYMm[object] = y;
        objectHeadingDeg[object] = heading;
        carrier[object] = carriedBy;
    }

    /** Marks a robot as gone for this step: no motion, no contact, no echo, no ranges. */
    public void setAbsent(int robot) {
        moveMm[robot] = 0;
        turnDeg[robot] = 0;
        flags[robot] = ABSENT;
    }

    public boolean isAbsent(int i) {
        return (flags[i] & ABSENT) != 0;
    }

    public long step() {
        return step;
    }

    public int count() {
        return count;
    }

    public double xMm(int i) {
        return xMm[i];
    }

    public double yMm(int i) {
        return yMm[i];
    }

    public double headingDeg(int i) {
        return headingDeg[i];
    }

    public double turnDeg(int i) {
        return turnDeg[i];
    }

    public double moveMm(int i) {
        return moveMm[i];
    }

    public boolean wantsSonar(int i) {
        return (flags[i] & SONAR) != 0 && (flags[i] & ABSENT) == 0;
    }

    public boolean wantsRays(int i) {
        return (flags[i] & RAYS) != 0 && (flags[i] & ABSENT) == 0;
    }

    /** True when robot i slides along what blocks it ({@link #SLIDE}). */
    public boolean slides(int i) {
        return (flags[i] & SLIDE) != 0 && (flags[i] & ABSENT) == 0;
    }

    public boolean wantsGrip(int i) {
        return (flags[i] & GRIP) != 0 && (flags[i] & ABSENT) == 0;
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

    /** The robot carrying object {@code o}, or -1. */
    public int carrier(int o) {
        return carrier[o];
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeLong(step);
        out.writeInt(count);
        for (int i = 0; i < count; i++) {
            out.writeDouble(xMm[i]);
            out.writeDouble(yMm[i]);
            out.writeDouble(headingDeg[i]);
            out.writeDouble(turnDeg[i]);
            out.writeDouble(moveMm[i]);
            out.writeByte(flags[i]);
        }
        out.writeInt(objects);
        for (int o = 0; o < objects; o++) {
            out.writeDouble(objectXMm[o]);
            out.writeDouble(objectYMm[o]);
            out.writeDouble(objectHeadingDeg[o]);
            out.writeInt(carrier[o]);
        }
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        step = in.readLong();
        resize(Limits.checkCount("robot count", in.readInt(), Limits.MAX_ROBOTS));
        for (int i = 0; i < count; i++) {
            xMm[i] = in.readDouble();
            yMm[i] = in.readDouble();
            headingDeg[i] = in.readDouble();
            turnDeg[i] = in.readDouble();
            moveMm[i] = in.readDouble();
            flags[i] = in.readByte();
        }
        resizeObjects(Limits.checkCount("object count", in.readInt(), Limits.MAX_OBJECTS));
        for (int o = 0; o < objects; o++) {
            objectXMm[o] = in.readDouble();
            objectYMm[o] = in.readDouble();
            objectHeadingDeg[o] = in.readDouble();
            carrier[o] = in.readInt();
            if (carrier[o] < GONE || carrier[o] >= count) {
                throw new ProtocolException("object " + o + " carried by robot " + carrier[o] + " of " + count);
            }
        }
    }
}

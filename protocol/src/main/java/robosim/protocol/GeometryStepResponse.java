package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * Geometry -> Environment, once per step, in answer to {@link GeometryStepRequest}: for every robot
 * in world order the distance it actually moved (mm, signed like the request) and turned (deg),
 * what it touched (a kind and an index into the world's robots or obstacles), and - for the robots
 * that asked - its sonar ranges (mm), concatenated in robot order and sonar-layout order.
 */
public final class GeometryStepResponse implements java.io.Externalizable {
    public static final byte CONTACT_NONE = 0;
    public static final byte CONTACT_ROBOT = 1;
    public static final byte CONTACT_OBSTACLE = 2;
    public static final byte CONTACT_ARENA = 3;

    private long step;
    private int count;
    private double[] movedMm = new double[0];
    private double[] turnedDeg = new double[0];
    private byte[] contactKind = new byte[0];
    private int[] contactIndex = new int[0];
    private int rangeCount;
    private double[] rangesMm = new double[0];

    public GeometryStepResponse() {
    }

    public GeometryStepResponse(int robots, int maxRanges) {
        resize(robots, maxRanges);
    }

    private void resize(int robots, int ranges) {
        count = robots;
        movedMm = new double[robots];
        turnedDeg = new double[robots];
        contactKind = new byte[robots];
        contactIndex = new int[robots];
        rangesMm = new double[ranges];
    }

    /** Starts filling in the answer to one step; ranges are appended with {@link #addRange}. */
    public void begin(long step) {
        this.step = step;
        this.rangeCount = 0;
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
    }
}

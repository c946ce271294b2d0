package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * Environment -> Geometry, once per step: for every robot in world order its pose at the start of
 * the step (mm, degrees), the requested turn (deg) and move (mm, along the heading after the turn),
 * and a flags byte: {@link #SONAR} (its sonar ranges are wanted) and {@link #ABSENT} (the robot has
 * left the simulation: it neither moves, blocks nor echoes, and gets no ranges). Geometry is
 * stateless between steps.
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

    /** Flag: this robot's sonar ranges are wanted. */
    public static final byte SONAR = 1;
    /** Flag: this robot has left; the world goes on without it. */
    public static final byte ABSENT = 2;

    public GeometryStepRequest() {
    }

    public GeometryStepRequest(int robots) {
        resize(robots);
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
        xMm[robot] = x;
        yMm[robot] = y;
        headingDeg[robot] = heading;
        turnDeg[robot] = turn;
        moveMm[robot] = move;
        flags[robot] = wantsSonar ? SONAR : 0;
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
    }
}

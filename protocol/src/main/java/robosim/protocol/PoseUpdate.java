package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * Environment -> viewer, after each step: every robot's pose (mm, degrees) at the end of
 * {@code step}, in snapshot order. Immutable once built, so one instance is shared by every
 * viewer worker; a live viewer may see only some steps, a recording viewer sees all.
 */
public final class PoseUpdate implements java.io.Externalizable {
    private long step;
    private double[] xMm = new double[0];
    private double[] yMm = new double[0];
    private double[] headingDeg = new double[0];

    public PoseUpdate() {
    }

    /** Takes the arrays as they are: the caller must never change them afterwards. */
    public PoseUpdate(long step, double[] xMm, double[] yMm, double[] headingDeg) {
        if (xMm.length != yMm.length || xMm.length != headingDeg.length) {
            throw new IllegalArgumentException("pose arrays differ in length");
        }
        this.step = step;
        this.xMm = xMm;
        this.yMm = yMm;
        this.headingDeg = headingDeg;
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

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeLong(step);
        out.writeInt(xMm.length);
        for (int i = 0; i < xMm.length; i++) {
            out.writeDouble(xMm[i]);
            out.writeDouble(yMm[i]);
            out.writeDouble(headingDeg[i]);
        }
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        step = in.readLong();
        int n = Limits.checkCount("robot count", in.readInt(), Limits.MAX_ROBOTS);
        xMm = new double[n];
        yMm = new double[n];
        headingDeg = new double[n];
        for (int i = 0; i < n; i++) {
            xMm[i] = in.readDouble();
            yMm[i] = in.readDouble();
            headingDeg[i] = in.readDouble();
        }
    }
}

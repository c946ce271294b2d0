package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * A static obstacle: a simple polygon given by its vertices in world millimetres, as
 * {@code x0, y0, x1, y1, ...} (the ring is closed implicitly). Written inline.
 */
public record ObstacleShape(String name, double[] xyMm) {
    public ObstacleShape {
        if (name == null) {
            throw new IllegalArgumentException("obstacle name must not be null");
        }
        if (xyMm.length < 6 || xyMm.length % 2 != 0) {
            throw new IllegalArgumentException("obstacle " + name + " needs at least 3 vertices (x,y pairs), got "
                    + xyMm.length + " numbers");
        }
        for (double v : xyMm) {
            if (!Double.isFinite(v)) {
                throw new IllegalArgumentException("obstacle " + name + " has a non-finite coordinate");
            }
        }
        xyMm = xyMm.clone();
    }

    /** The vertex coordinates; a copy, so the shape stays immutable. */
    @Override
    public double[] xyMm() {
        return xyMm.clone();
    }

    public int vertexCount() {
        return xyMm.length / 2;
    }

    public double x(int vertex) {
        return xyMm[2 * vertex];
    }

    public double y(int vertex) {
        return xyMm[2 * vertex + 1];
    }

    /** An axis-aligned rectangle with its lower-left corner at (x, y). */
    public static ObstacleShape rectangle(String name, double xMm, double yMm, double widthMm, double heightMm) {
        return new ObstacleShape(name, new double[] {xMm, yMm, xMm + widthMm, yMm, xMm + widthMm, yMm + heightMm,
            xMm, yMm + heightMm});
    }

    void write(ObjectOutput out) throws IOException {
        out.writeUTF(name);
        out.writeInt(xyMm.length / 2);
        Wire.writeDoubles(out, xyMm, xyMm.length);
    }

    static ObstacleShape read(ObjectInput in) throws IOException {
        String name = in.readUTF();
        int vertices = Limits.checkCount("vertex count", in.readInt(), Limits.MAX_VERTICES);
        double[] xy = Wire.readDoubles(in, 2 * vertices);
        try {
            return new ObstacleShape(name, xy);
        } catch (IllegalArgumentException e) {
            throw new ProtocolException(e.getMessage());
        }
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof ObstacleShape other && name.equals(other.name)
                && java.util.Arrays.equals(xyMm, other.xyMm);
    }

    @Override
    public int hashCode() {
        return name.hashCode() * 31 + java.util.Arrays.hashCode(xyMm);
    }

    @Override
    public String toString() {
        return "ObstacleShape[" + name + ", " + vertexCount() + " vertices]";
    }
}

package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * An object of the world, a box or a cylinder, as its file places it: its shape ({@code widthMm} along its own x axis,
 * {@code depthMm} along its y axis; a cylinder's both its diameter), height, mass, friction coefficient, colour
 * ({@code 0xRRGGBB}), whether robots push it ({@code movable}) and grip it ({@code gripable}), and its start pose
 * (centre, heading). Where it stands later is the world's (the Geometry process moves it). Written inline.
 */
public record WorldObject(String name, Shape shape, double widthMm, double depthMm, double heightMm, double massKg,
        double friction, boolean movable, boolean gripable, int rgb, double xMm, double yMm, double headingDeg) {
    /** What an object is. */
    public enum Shape {
        BOX, CYLINDER
    }

    public WorldObject {
        if (name == null || name.isEmpty()) {
            throw new IllegalArgumentException("an object needs a name");
        }
        java.util.Objects.requireNonNull(shape, "shape");
        if (!(widthMm > 0) || !(depthMm > 0) || !(heightMm > 0) || Double.isInfinite(widthMm)
                || Double.isInfinite(depthMm) || Double.isInfinite(heightMm)) {
            throw new IllegalArgumentException("object " + name + "'s size must be > 0, got " + widthMm + " x "
                    + depthMm + " x " + heightMm);
        }
        if (shape == Shape.CYLINDER && widthMm != depthMm) {
            throw new IllegalArgumentException("cylinder " + name + " is as wide as deep (its diameter), got "
                    + widthMm + " x " + depthMm);
        }
        if (!(massKg > 0) || Double.isInfinite(massKg) || !(friction >= 0) || Double.isInfinite(friction)) {
            throw new IllegalArgumentException("object " + name + " needs a mass > 0 and a friction >= 0, got "
                    + massKg + " kg, " + friction);
        }
        if (gripable && !movable) {
            throw new IllegalArgumentException("object " + name + " is gripable, so it must be movable");
        }
        if (rgb < 0 || rgb > 0xFFFFFF) {
            throw new IllegalArgumentException("object " + name + "'s colour is 0 to 0xFFFFFF, got " + rgb);
        }
        if (!Double.isFinite(xMm) || !Double.isFinite(yMm) || !Double.isFinite(headingDeg)) {
            throw new IllegalArgumentException("object " + name + "'s pose must be finite numbers");
        }
    }

    /** A cylinder's radius; a box's half width. */
    public double radiusMm() {
        return widthMm / 2;
    }

    /** The radius of the smallest disc around its centre that holds it. */
    public double reachMm() {
        return shape == Shape.CYLINDER ? widthMm / 2 : Math.hypot(widthMm, depthMm) / 2;
    }

    /**
     * A box's corners at centre (x, y), heading {@code headingDeg}, into {@code out} from {@code at} as x0, y0, ...
     * x3, y3: counter-clockwise from the corner behind and right of its centre (its own frame: x along its width, y
     * along its depth). The one formula every part that draws or moves a box uses.
     */
    public void corners(double x, double y, double headingDeg, double[] out, int at) {
        double h = Math.toRadians(headingDeg);
        double c = Math.cos(h);
        double s = Math.sin(h);
        double hw = widthMm / 2;
        double hd = depthMm / 2;
        for (int k = 0; k < 4; k++) {
            double u = k == 0 || k == 3 ? -hw : hw;
            double v = k < 2 ? -hd : hd;
            out[at + 2 * k] = x + u * c - v * s;
            out[at + 2 * k + 1] = y + u * s + v * c;
        }
    }

    /** Its corners at its start pose, as {@link #corners(double, double, double, double[], int)} gives them. */
    public double[] corners() {
        double[] out = new double[8];
        corners(xMm, yMm, headingDeg, out, 0);
        return out;
    }

    /** This object at another pose (mm, degrees). */
    public WorldObject at(double x, double y, double heading) {
        return new WorldObject(name, shape, widthMm, depthMm, heightMm, massKg, friction, movable, gripable, rgb, x, y,
                heading);
    }

    void write(ObjectOutput out) throws IOException {
        out.writeUTF(name);
        out.writeByte(shape.ordinal());
        out.writeDouble(widthMm);
        out.writeDouble(depthMm);
        out.writeDouble(heightMm);
        out.writeDouble(massKg);
        out.writeDouble(friction);
        out.writeByte((movable ? 1 : 0) | (gripable ? 2 : 0));
        out.writeInt(rgb);
        out.writeDouble(xMm);
        out.writeDouble(yMm);
        out.writeDouble(headingDeg);
    }

    static WorldObject read(ObjectInput in) throws IOException {
        String name = in.readUTF();
        int kind = in.readByte();
        if (kind < 0 || kind >= Shape.values().length) {
            throw new ProtocolException("object " + Printable.of(name, 64) + " of unknown shape " + kind);
        }
        double w = in.readDouble();
        double d = in.readDouble();
        double h = in.readDouble();
        double mass = in.readDouble();
        double friction = in.readDouble();
        int flags = in.readByte();
        try {
            return new WorldObject(name, Shape.values()[kind], w, d, h, mass, friction, (flags & 1) != 0,
                    (flags & 2) != 0, in.readInt(), in.readDouble(), in.readDouble(), in.readDouble());
        } catch (IllegalArgumentException e) {
            throw new ProtocolException(e.getMessage());
        }
    }
}

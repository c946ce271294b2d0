package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * A light of the world: where it stands, how high over the floor, its colour ({@code 0xRRGGBB}), its intensity (what
 * light sensors scale distances by: a robot's type says its law) and whether it is on. Light sensors and cameras see it
 * when nothing stands in the way; an intensity of 0 is never seen. Written inline.
 */
public record Light(String name, double xMm, double yMm, double heightMm, int rgb, double intensity, boolean on) {
    public Light {
        if (name == null || name.isEmpty()) {
            throw new IllegalArgumentException("a light needs a name");
        }
        if (!Double.isFinite(xMm) || !Double.isFinite(yMm) || !(heightMm >= 0) || Double.isInfinite(heightMm)) {
            throw new IllegalArgumentException("light " + name + " needs a finite place and a height >= 0, got ("
                    + xMm + ", " + yMm + ", " + heightMm + ")");
        }
        if (rgb < 0 || rgb > 0xFFFFFF) {
            throw new IllegalArgumentException("light " + name + "'s colour is 0 to 0xFFFFFF, got " + rgb);
        }
        if (!(intensity >= 0) || Double.isInfinite(intensity)) {
            throw new IllegalArgumentException("light " + name + "'s intensity must be >= 0, got " + intensity);
        }
    }

    /** True if sensors see it: on, and of an intensity above 0. */
    public boolean shines() {
        return on && intensity > 0;
    }

    void write(ObjectOutput out) throws IOException {
        out.writeUTF(name);
        out.writeDouble(xMm);
        out.writeDouble(yMm);
        out.writeDouble(heightMm);
        out.writeInt(rgb);
        out.writeDouble(intensity);
        out.writeBoolean(on);
    }

    static Light read(ObjectInput in) throws IOException {
        try {
            return new Light(in.readUTF(), in.readDouble(), in.readDouble(), in.readDouble(), in.readInt(),
                    in.readDouble(), in.readBoolean());
        } catch (IllegalArgumentException e) {
            throw new ProtocolException(e.getMessage());
        }
    }
}

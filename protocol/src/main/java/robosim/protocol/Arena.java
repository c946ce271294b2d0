package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/** The rectangular arena, world millimetres; robots must stay inside it. Written inline. */
public record Arena(double minXMm, double minYMm, double maxXMm, double maxYMm) {
    public Arena {
        if (!(maxXMm > minXMm) || !(maxYMm > minYMm) || Double.isInfinite(maxXMm - minXMm)
                || Double.isInfinite(maxYMm - minYMm)) {
            throw new IllegalArgumentException("arena must have positive finite width and height, got x "
                    + minXMm + ".." + maxXMm + ", y " + minYMm + ".." + maxYMm);
        }
    }

    void write(ObjectOutput out) throws IOException {
        out.writeDouble(minXMm);
        out.writeDouble(minYMm);
        out.writeDouble(maxXMm);
        out.writeDouble(maxYMm);
    }

    static Arena read(ObjectInput in) throws IOException {
        double x0 = in.readDouble();
        double y0 = in.readDouble();
        double x1 = in.readDouble();
        double y1 = in.readDouble();
        try {
            return new Arena(x0, y0, x1, y1);
        } catch (IllegalArgumentException e) {
            throw new ProtocolException(e.getMessage());
        }
    }
}

package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.ArrayList;
import java.util.List;

/**
 * A robot sets one of its actuators (its LEDs' colours, the bytes its range-and-bearing device sends): the actuator's
 * name and its new values, held from this step on until set again. Written inline inside {@link StepRequest}.
 */
public record Actuation(String device, double[] values) {
    /** Actuations one request may carry. */
    public static final int MAX_PER_STEP = 16;

    public Actuation {
        if (device == null || device.isEmpty()) {
            throw new IllegalArgumentException("an actuation names its device");
        }
        if (values.length > Limits.MAX_SENSOR_VALUES) {
            throw new IllegalArgumentException("an actuation of " + values.length + " values, at most "
                    + Limits.MAX_SENSOR_VALUES);
        }
        values = values.clone();
    }

    @Override
    public double[] values() {
        return values.clone();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Actuation a && device.equals(a.device) && java.util.Arrays.equals(values, a.values);
    }

    @Override
    public int hashCode() {
        return device.hashCode() * 31 + java.util.Arrays.hashCode(values);
    }

    @Override
    public String toString() {
        return device + java.util.Arrays.toString(values);
    }

    static void write(ObjectOutput out, List<Actuation> actuations) throws IOException {
        out.writeByte(actuations.size());
        for (Actuation a : actuations) {
            out.writeUTF(a.device);
            out.writeInt(a.values.length);
            Wire.writeDoubles(out, a.values, a.values.length);
        }
    }

    static List<Actuation> read(ObjectInput in) throws IOException {
        int n = Limits.checkCount("actuation count", in.readUnsignedByte(), MAX_PER_STEP);
        List<Actuation> out = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            String device = in.readUTF();
            double[] values = Wire.readDoubles(in, Limits.checkCount("actuation value count", in.readInt(),
                    Limits.MAX_SENSOR_VALUES));
            try {
                out.add(new Actuation(device, values));
            } catch (IllegalArgumentException e) {
                throw new ProtocolException(e.getMessage());
            }
        }
        return List.copyOf(out);
    }
}

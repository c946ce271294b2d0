package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;

/**
 * One plug-in sensor's reading for one step (SENSOR requests other than sonar: laser, heat, bump,
 * and any sensor added later): its name as configured in the environment file and its values,
 * whose meaning and units the sensor defines. Written inline.
 */
public record SensorReading(String name, double[] values) {
    public SensorReading {
        if (name == null || values == null) {
            throw new IllegalArgumentException("sensor reading needs a name and values");
        }
    }

    /** The values; the array itself, which nobody may change. */
    @Override
    public double[] values() {
        return values;
    }

    void write(ObjectOutput out) throws IOException {
        out.writeUTF(name);
        out.writeInt(values.length);
        Wire.writeDoubles(out, values, values.length);
    }

    static SensorReading read(ObjectInput in) throws IOException {
        String name = in.readUTF();
        int n = Limits.checkCount("sensor value count", in.readInt(), Limits.MAX_SENSOR_VALUES);
        return new SensorReading(name, Wire.readDoubles(in, n));
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof SensorReading r && name.equals(r.name) && java.util.Arrays.equals(values, r.values);
    }

    @Override
    public int hashCode() {
        return name.hashCode() * 31 + java.util.Arrays.hashCode(values);
    }

    @Override
    public String toString() {
        return name + java.util.Arrays.toString(values);
    }
}

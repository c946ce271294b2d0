package robosim.devices;

/**
 * The values one configured actuator is set to: how many, the range each must lie in, and whether each is a whole
 * number (a colour, a byte). A value out of its range is refused with the value, as {@code move(NaN)} is. A learner's
 * action space for it is a box of this shape.
 */
public record ActuatorValues(int count, double low, double high, boolean whole) {
    public ActuatorValues {
        if (count < 0 || !(low <= high)) {
            throw new IllegalArgumentException("an actuator's values need a count >= 0 and low <= high");
        }
    }

    /**
     * Why {@code values} cannot be set, naming the value and what it must be ({@code device} names the actuator in the
     * line), or null when they can.
     */
    public String problem(String device, double[] values) {
        if (values.length != count) {
            return device + " takes " + count + " values, got " + values.length;
        }
        for (int k = 0; k < count; k++) {
            double v = values[k];
            if (!(v >= low && v <= high) || (whole && v != Math.rint(v))) {
                return device + " value " + k + " must be " + (whole ? "a whole number " : "") + "from "
                        + Attribute.plain(low) + " to " + Attribute.plain(high) + ", got " + Attribute.plain(v);
            }
        }
        return null;
    }
}

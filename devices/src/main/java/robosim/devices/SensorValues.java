package robosim.devices;

/**
 * The values one configured sensor gives each step: how many at most, the range each lies in (noise included) and
 * their unit. A sensor that reads a list of things (a camera's blobs, the messages heard) gives its values in groups,
 * one a thing, each field of a group in a range of its own ({@link #fieldLow}, {@link #fieldHigh}), and fewer than
 * {@link #count} when it sees fewer things. A learner's observation space is a box of this shape
 * ({@code gymnasium.spaces.Box(low, high, (count,))}, each group's bounds repeated).
 *
 * @param low the least any value is
 * @param high the most any value is
 * @param fieldLow each field's least, in a group's order; empty when the values are not in groups
 * @param fieldHigh each field's most
 */
public record SensorValues(int count, double low, double high, String unit, double[] fieldLow, double[] fieldHigh) {
    public SensorValues {
        if (count < 0 || !(low <= high)) {
            throw new IllegalArgumentException("a sensor's values need a count >= 0 and low <= high, got " + count
                    + " in [" + low + ", " + high + "]");
        }
        if (fieldLow.length != fieldHigh.length || (fieldLow.length > 0 && count % fieldLow.length != 0)) {
            throw new IllegalArgumentException("a sensor's groups need a bound a field and a count of whole groups");
        }
        fieldLow = fieldLow.clone();
        fieldHigh = fieldHigh.clone();
    }

    /** {@code count} values, each in [low, high]. */
    public SensorValues(int count, double low, double high, String unit) {
        this(count, low, high, unit, new double[0], new double[0]);
    }

    /** Up to {@code items} groups of values, field k of each in [{@code low[k]}, {@code high[k]}]. */
    public static SensorValues groups(int items, double[] low, double[] high, String unit) {
        double least = Double.POSITIVE_INFINITY;
        double most = Double.NEGATIVE_INFINITY;
        for (int k = 0; k < low.length; k++) {
            least = Math.min(least, low[k]);
            most = Math.max(most, high[k]);
        }
        return new SensorValues(items * low.length, least, most, unit, low, high);
    }

    @Override
    public double[] fieldLow() {
        return fieldLow.clone();
    }

    @Override
    public double[] fieldHigh() {
        return fieldHigh.clone();
    }

    /** Fields in a group: 1 when the values are not in groups. */
    public int group() {
        return Math.max(1, fieldLow.length);
    }

    /** The least value {@code k} may be. */
    public double low(int k) {
        return fieldLow.length == 0 ? low : fieldLow[k % fieldLow.length];
    }

    /** The most value {@code k} may be. */
    public double high(int k) {
        return fieldHigh.length == 0 ? high : fieldHigh[k % fieldHigh.length];
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof SensorValues v && count == v.count && low == v.low && high == v.high
                && unit.equals(v.unit) && java.util.Arrays.equals(fieldLow, v.fieldLow)
                && java.util.Arrays.equals(fieldHigh, v.fieldHigh);
    }

    @Override
    public int hashCode() {
        return java.util.Objects.hash(count, low, high, unit, java.util.Arrays.hashCode(fieldLow));
    }
}

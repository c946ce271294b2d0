package robosim.devices;

/**
 * The values one configured sensor gives each step: how many, the range each lies in (noise included) and their
 * unit. A learner's observation space is a box of this shape ({@code gymnasium.spaces.Box(low, high, (count,))}).
 */
public record SensorValues(int count, double low, double high, String unit) {
    public SensorValues {
        if (count < 0 || !(low <= high)) {
            throw new IllegalArgumentException("a sensor's values need a count >= 0 and low <= high, got " + count
                    + " in [" + low + ", " + high + "]");
        }
    }
}

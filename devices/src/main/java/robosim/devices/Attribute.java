package robosim.devices;

/**
 * One number a device takes from the environment file ({@code <sensor type="laser" fovDeg="90"/>}): its name, the
 * value when the file gives none, the range it must be in (each end open or closed, infinite for none), its unit and
 * what it is. A device declares its attributes once, in its {@link SensorInfo}, and reads them with {@link #read};
 * the file reader refuses an attribute no declaration names, and {@code describe.sh} lists them.
 */
public record Attribute(String name, double otherwise, double low, boolean lowOpen, double high, boolean highOpen,
        String unit, String description) {
    /** A number of any value. */
    public static Attribute number(String name, double otherwise, String unit, String description) {
        return new Attribute(name, otherwise, Double.NEGATIVE_INFINITY, false, Double.POSITIVE_INFINITY, false, unit,
                description);
    }

    /**
     * The standard deviation of Gaussian noise on every value, in the device's unit, drawn from the world's seeded
     * generator (0: none).
     */
    public static Attribute noise(String unit) {
        return number("noise", 0, unit, "standard deviation of Gaussian noise on every value, from the world's seed")
                .atLeast(0);
    }

    /** This attribute, at least {@code min}. */
    public Attribute atLeast(double min) {
        return new Attribute(name, otherwise, min, false, high, highOpen, unit, description);
    }

    /** This attribute, more than {@code min}. */
    public Attribute above(double min) {
        return new Attribute(name, otherwise, min, true, high, highOpen, unit, description);
    }

    /** This attribute, at most {@code max}. */
    public Attribute atMost(double max) {
        return new Attribute(name, otherwise, low, lowOpen, max, false, unit, description);
    }

    /**
     * Its value in {@code given}, or {@link #otherwise} when the file gives none.
     *
     * @throws IllegalArgumentException naming it and the value: not a number, or out of its range
     */
    public double read(Attributes given) {
        double v = given.number(name, otherwise);
        if (!(inLow(v) && inHigh(v))) {
            throw new IllegalArgumentException(name + " must be " + range() + ", got " + v);
        }
        return v;
    }

    private boolean inLow(double v) {
        return lowOpen ? v > low : v >= low;
    }

    private boolean inHigh(double v) {
        return highOpen ? v < high : v <= high;
    }

    /** Its range as a line says it: {@code in (0, 360]}, {@code > 0}, {@code >= 0}, {@code any number}. */
    public String range() {
        boolean bottom = low != Double.NEGATIVE_INFINITY;
        boolean top = high != Double.POSITIVE_INFINITY;
        if (bottom && top) {
            return "in " + (lowOpen ? "(" : "[") + plain(low) + ", " + plain(high) + (highOpen ? ")" : "]");
        }
        if (bottom) {
            return (lowOpen ? "> " : ">= ") + plain(low);
        }
        if (top) {
            return (highOpen ? "< " : "<= ") + plain(high);
        }
        return "any number";
    }

    /** A number as a person writes it: 360, not 360.0. */
    public static String plain(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}

package robosim.devices;

import java.util.List;

/**
 * One value a device takes from the environment file ({@code <sensor type="laser" fovDeg="90"/>}), a number or one
 * of some words: its name, the value when the file gives none, the range a number must be in (each end open or
 * closed, infinite for none) or the words it may be, its unit and what it is. A device declares its attributes once,
 * in its {@link SensorInfo} or {@link ActuatorInfo}, and reads them with {@link #read} or {@link #choose}; the file
 * reader refuses an attribute no declaration names, and {@code describe.sh} lists them.
 *
 * @param choices the words a choice may be (its default {@code choices.get((int) otherwise)}); empty for a number
 */
public record Attribute(String name, double otherwise, double low, boolean lowOpen, double high, boolean highOpen,
        String unit, String description, List<String> choices) {
    public Attribute {
        choices = List.copyOf(choices);
    }

    /** A number of any value. */
    public static Attribute number(String name, double otherwise, String unit, String description) {
        return new Attribute(name, otherwise, Double.NEGATIVE_INFINITY, false, Double.POSITIVE_INFINITY, false, unit,
                description, List.of());
    }

    /** One of {@code choices}, the first by default. */
    public static Attribute choice(String name, String description, String... choices) {
        return new Attribute(name, 0, 0, false, 0, false, "", description, List.of(choices));
    }

    /** True for an attribute that is one of some words. */
    public boolean isChoice() {
        return !choices.isEmpty();
    }

    /** Its value in {@code given}, one of its words, or its first when the file gives none. */
    public String choose(Attributes given) {
        String v = given.text(name, choices.get((int) otherwise));
        if (!choices.contains(v)) {
            throw new IllegalArgumentException(name + " must be " + range() + ", got '" + v + "'");
        }
        return v;
    }

    /** Its default as a line shows it: {@code 7.5 mm}, {@code foot-bot}. */
    public String shownDefault() {
        return isChoice() ? choices.get((int) otherwise) : plain(otherwise) + (unit.isEmpty() ? "" : " " + unit);
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
        return new Attribute(name, otherwise, min, false, high, highOpen, unit, description, choices);
    }

    /** This attribute, more than {@code min}. */
    public Attribute above(double min) {
        return new Attribute(name, otherwise, min, true, high, highOpen, unit, description, choices);
    }

    /** This attribute, at most {@code max}. */
    public Attribute atMost(double max) {
        return new Attribute(name, otherwise, low, lowOpen, max, false, unit, description, choices);
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

    /** Its range as a line says it: {@code in (0, 360]}, {@code > 0}, {@code >= 0}, {@code any number}, {@code one of a, b}. */
    public String range() {
        if (isChoice()) {
            return "one of " + String.join(", ", choices);
        }
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

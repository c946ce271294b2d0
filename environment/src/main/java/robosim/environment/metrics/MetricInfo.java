package robosim.environment.metrics;

/**
 * What a metric is, for everyone who shows it: its name (a column of a sweep's tables, a key of the learning link's
 * metrics), its unit (a plot's axis), the confidence interval its mean gets in a sweep's {@code summary.csv}, where its
 * column stands among the built-in metrics' (lower first), and a sentence on how it is counted.
 */
public record MetricInfo(String name, String unit, Interval interval, int column, String description) {
    /** The 95% confidence interval of a metric's mean over a combination's runs. */
    public enum Interval {
        /** Student's t with n - 1 degrees of freedom: for a quantity that may take any value. */
        STUDENT_T,
        /** A bootstrap percentile interval, which stays within the values' range: for counts and shares. */
        BOOTSTRAP
    }

    public MetricInfo {
        if (name == null || !name.matches("[a-z][a-z0-9_]{0,63}")) {
            throw new IllegalArgumentException("a metric's name is 1 to 64 lower-case letters, digits and _, got "
                    + name);
        }
        if (unit == null || unit.isBlank() || interval == null || description == null || description.isBlank()) {
            throw new IllegalArgumentException("metric " + name + " needs a unit, an interval and a description");
        }
    }
}

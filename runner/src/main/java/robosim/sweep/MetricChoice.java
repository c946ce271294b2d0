package robosim.sweep;

import robosim.protocol.Report;

/**
 * A metric a sweep file asks for: a built-in one ({@link RunMetrics#BUILT_IN}), a value the control code reports
 * ({@code Robot.report}, summed over the robots) or a {@link Metric} class of one's own.
 *
 * @param kind which of the three
 * @param name the built-in's or the report's name, or the class's
 */
public record MetricChoice(Kind kind, String name) {
    /** Where the value comes from. */
    public enum Kind { BUILT_IN, REPORT, CLASS }

    static MetricChoice of(String builtIn, String report, String className) {
        return builtIn != null ? new MetricChoice(Kind.BUILT_IN, builtIn)
                : report != null ? new MetricChoice(Kind.REPORT, report) : new MetricChoice(Kind.CLASS, className);
    }

    /** A choice as a command line writes it: a built-in's name, {@code report:NAME}, or a class name (with a dot). */
    public static MetricChoice parse(String written) {
        if (written.startsWith("report:")) {
            return new MetricChoice(Kind.REPORT, written.substring("report:".length()));
        }
        return written.contains(".") ? new MetricChoice(Kind.CLASS, written) : new MetricChoice(Kind.BUILT_IN, written);
    }

    /** What is wrong with this choice (an unknown built-in, a bad report name, a class that is not a Metric), or null. */
    public String problem() {
        return switch (kind) {
            case BUILT_IN -> RunMetrics.BUILT_IN.contains(name) ? null
                    : "'" + name + "' is not a built-in metric (they are: " + String.join(", ", RunMetrics.BUILT_IN) + ")";
            case REPORT -> Report.problem(name, 0);
            case CLASS -> {
                try {
                    String column = instance().name();
                    yield Report.problem(column, 0) != null ? "class " + name + " names its metric badly: "
                            + Report.problem(column, 0) : RunMetrics.reserved(column) ? "class " + name + " names its "
                            + "metric '" + column + "', a built-in's or a row's own column" : null;
                } catch (ReflectiveOperationException | LinkageError | ClassCastException e) {
                    yield "class " + name + " is not a robosim.sweep.Metric with a public no-argument constructor on "
                            + "the class path (ROBOSIM_CLASSPATH): " + e;
                }
            }
        };
    }

    /** A new instance of the class of a {@link Kind#CLASS} choice. */
    Metric instance() throws ReflectiveOperationException {
        Class<?> c = Class.forName(name, true, MetricChoice.class.getClassLoader());
        return (Metric) c.asSubclass(Metric.class).getConstructor().newInstance();
    }
}

package robosim.sweep;

import java.util.Arrays;
import java.util.Locale;
import robosim.environment.metrics.Metrics;
import robosim.protocol.Report;

/**
 * A metric a sweep file asks for: a built-in one ({@link Metrics}), a value the control code reports
 * ({@code Robot.report}), taken over the robots as {@link Over} says, or a {@link Metric} class of one's own.
 *
 * @param kind which of the three
 * @param name the built-in's or the report's name, or the class's
 * @param over how a report's values (each robot's newest) make the run's: null for the default, their sum in a column
 *     named as the report; otherwise in a column named by it ({@link #column})
 * @param count whether a report is a count (sweep file: {@code count="true"}): never below zero, its 95% interval a
 *     bootstrap one, as the built-in counts' ({@code MetricInfo.Interval.BOOTSTRAP}), not Student's t
 */
public record MetricChoice(Kind kind, String name, Over over, boolean count) {
    /** Where the value comes from. */
    public enum Kind { BUILT_IN, REPORT, CLASS }

    /** How a report's values, one per robot that reported it, make the run's (sweep file: {@code over="..."}). */
    public enum Over {
        SUM, MEAN, MIN, MAX,
        /** A column per robot: {@code NAME.ROBOT}. */
        EACH;

        /** As a sweep file writes it. */
        String written() {
            return name().toLowerCase(Locale.ROOT);
        }

        static Over of(String written) {
            for (Over o : values()) {
                if (o.written().equals(written)) {
                    return o;
                }
            }
            return null;
        }

        static String names() {
            return String.join(", ", Arrays.stream(values()).map(Over::written).toList());
        }
    }

    /** A built-in metric, a report summed over the robots, or a class. */
    public MetricChoice(Kind kind, String name) {
        this(kind, name, null, false);
    }

    /** A report taken over the robots as {@code over} says (a measure, not a count), or as the two-argument one. */
    public MetricChoice(Kind kind, String name, Over over) {
        this(kind, name, over, false);
    }

    static MetricChoice of(String builtIn, String report, String className, Over over, boolean count) {
        return builtIn != null ? new MetricChoice(Kind.BUILT_IN, builtIn)
                : report != null ? new MetricChoice(Kind.REPORT, report, over, count)
                : new MetricChoice(Kind.CLASS, className);
    }

    /** Whether {@code column} of a row is this choice's, a report declared a count. */
    boolean countsIn(String column) {
        return count && kind == Kind.REPORT && (over == Over.EACH ? column.startsWith(name + ".")
                : column.equals(column(null)));
    }

    /**
     * A choice as a command line writes it: a built-in's name, {@code report:NAME} or {@code report:NAME:OVER}, or a
     * class name (with a dot).
     */
    public static MetricChoice parse(String written) {
        if (written.startsWith("report:")) {
            String rest = written.substring("report:".length());
            int colon = rest.lastIndexOf(':');
            Over over = colon < 0 ? null : Over.of(rest.substring(colon + 1));
            return over == null ? new MetricChoice(Kind.REPORT, rest)
                    : new MetricChoice(Kind.REPORT, rest.substring(0, colon), over);
        }
        return written.contains(".") ? new MetricChoice(Kind.CLASS, written) : new MetricChoice(Kind.BUILT_IN, written);
    }

    /**
     * The column of a report's value over the robots: the name (the default sum; {@code report.NAME} where a built-in
     * or a row's own column has it), else {@code NAME.robot_OVER} ({@code nearest_m.robot_mean}); for {@link Over#EACH}
     * robot {@code robot}'s column, {@code NAME.ROBOT}.
     */
    String column(String robot) {
        if (over == null) {
            return RunMetrics.reportColumn(name);
        }
        return name + "." + (over == Over.EACH ? robot : "robot_" + over.written());
    }

    /** What is wrong with this choice (an unknown built-in, a bad report name, a class that is not a Metric), or null. */
    public String problem() {
        return switch (kind) {
            case BUILT_IN -> Metrics.info(name) != null ? null
                    : "'" + name + "' is not a built-in metric (they are: " + String.join(", ", Metrics.names()) + ")";
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

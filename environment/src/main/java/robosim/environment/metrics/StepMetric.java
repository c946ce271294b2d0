package robosim.environment.metrics;

/**
 * A metric of a run, counted step by step, by one implementation wherever the steps come from: a world stepped
 * live (the learning host's, a run's) or a recording read back (a sweep's row, {@code record-tool.sh metrics}), so
 * the two give the same number, bit for bit. One instance counts one run: {@link #begin}, then {@link #step} after
 * each step, {@link #value} at any time.
 *
 * <p>A built-in metric is a subclass with a public no-argument constructor, registered for
 * {@link java.util.ServiceLoader} ({@code @AutoService(StepMetric.class)}): {@link Metrics} finds it, and so every
 * sweep, table, plot, {@code record-tool.sh}, the testkit, the learning link and {@code describe.sh metrics}. No
 * other file changes. Not thread-safe: the thread that steps the run.
 */
public abstract class StepMetric {
    private final MetricInfo info;

    protected StepMetric(MetricInfo info) {
        this.info = info;
    }

    /** What it is: its name, unit, interval and place. */
    public final MetricInfo info() {
        return info;
    }

    /** The run starts; the world before its first step. */
    public abstract void begin(RunStart run);

    /** The world after a step. */
    public abstract void step(StepView step);

    /** The run's value so far. */
    public abstract double value();
}

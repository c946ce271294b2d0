package robosim.environment.metrics;

import java.util.List;

/**
 * A run's built-in metrics counted as it goes: a fresh instance of each ({@link Metrics#fresh}), begun on the
 * world before the first step, told each step after it. Its values are in the built-ins' column order. Not
 * thread-safe: the thread that steps the run.
 */
public final class MetricTally {
    private final StepMetric[] metrics;

    /** A tally of a run in {@code start}'s arena, cells of {@code start}'s side, from its robots' start poses. */
    public MetricTally(RunStart start) {
        List<StepMetric> fresh = Metrics.fresh();
        this.metrics = fresh.toArray(new StepMetric[0]);
        for (StepMetric m : metrics) {
            m.begin(start);
        }
    }

    /** The world after a step. */
    public void step(StepView step) {
        for (StepMetric m : metrics) {
            m.step(step);
        }
    }

    /** How many metrics it counts. */
    public int size() {
        return metrics.length;
    }

    /** Metric {@code i}'s value so far (column order). */
    public double value(int i) {
        return metrics[i].value();
    }

    /** Metric {@code i}'s description. */
    public MetricInfo info(int i) {
        return metrics[i].info();
    }
}

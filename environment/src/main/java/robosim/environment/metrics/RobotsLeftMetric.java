package robosim.environment.metrics;

import com.google.auto.service.AutoService;

/** {@code robots_left}: robots still in the world (those that joined included, those that departed not). */
@AutoService(StepMetric.class)
public final class RobotsLeftMetric extends StepMetric {
    private int left;

    public RobotsLeftMetric() {
        super(new MetricInfo("robots_left", "robots", MetricInfo.Interval.BOOTSTRAP, 60,
                "robots still in the world at the end (those that joined included, those that departed not)"));
    }

    @Override
    public void begin(RunStart run) {
        step(run.start());
    }

    @Override
    public void step(StepView step) {
        left = Math.max(0, step.robots() - step.departed());
    }

    @Override
    public double value() {
        return left;
    }
}

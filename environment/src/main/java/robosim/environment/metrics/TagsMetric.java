package robosim.environment.metrics;

import com.google.auto.service.AutoService;

/** {@code tags}: tags made: a robot's tag that hit a robot or a taggable obstacle, each pair once. */
@AutoService(StepMetric.class)
public final class TagsMetric extends StepMetric {
    private int tags;

    public TagsMetric() {
        super(new MetricInfo("tags", "count", MetricInfo.Interval.BOOTSTRAP, 40,
                "tags made (a robot's tag that hit a robot or a taggable obstacle; each tagger and target once)"));
    }

    @Override
    public void begin(RunStart run) {
        tags = run.start().tags();
    }

    @Override
    public void step(StepView step) {
        tags = step.tags();
    }

    @Override
    public double value() {
        return tags;
    }
}

package robosim.environment.metrics;

import com.google.auto.service.AutoService;

/** {@code messages_delivered}: messages delivered to robots. */
@AutoService(StepMetric.class)
public final class MessagesDeliveredMetric extends StepMetric {
    private long delivered;

    public MessagesDeliveredMetric() {
        super(new MetricInfo("messages_delivered", "count", MetricInfo.Interval.BOOTSTRAP, 30,
                "messages delivered to robots"));
    }

    @Override
    public void begin(RunStart run) {
        delivered = 0;
    }

    @Override
    public void step(StepView step) {
        for (int r = 0; r < step.robots(); r++) {
            if (step.tookPart(r)) {
                delivered += step.delivered(r);
            }
        }
    }

    @Override
    public double value() {
        return delivered;
    }
}

package robosim.environment.metrics;

import com.google.auto.service.AutoService;
import java.util.Arrays;

/** {@code contacts}: times a robot touched something: a step it ends touching after one it did not. */
@AutoService(StepMetric.class)
public final class ContactsMetric extends StepMetric {
    private boolean[] touching = new boolean[0];
    private long contacts;

    public ContactsMetric() {
        super(new MetricInfo("contacts", "count", MetricInfo.Interval.BOOTSTRAP, 20,
                "times a robot touched something (a step it ends touching a wall, an obstacle or a robot, after one "
                        + "it did not)"));
    }

    @Override
    public void begin(RunStart run) {
        touching = new boolean[run.start().robots()];
    }

    @Override
    public void step(StepView step) {
        int n = step.robots();
        if (n > touching.length) {
            touching = Arrays.copyOf(touching, n);
        }
        for (int r = 0; r < n; r++) {
            if (step.tookPart(r)) {
                boolean now = step.touching(r);
                if (now && !touching[r]) {
                    contacts++;
                }
                touching[r] = now;
            }
        }
    }

    @Override
    public double value() {
        return contacts;
    }
}

package robosim.environment.metrics;

import com.google.auto.service.AutoService;
import java.util.Arrays;

/** {@code distance_m}: the robots' paths, summed: each robot's straight move from step to step, from its start pose. */
@AutoService(StepMetric.class)
public final class DistanceMetric extends StepMetric {
    private double[] lastX = new double[0];
    private double[] lastY = new double[0];
    private double distanceMm;

    public DistanceMetric() {
        super(new MetricInfo("distance_m", "m, all robots' paths", MetricInfo.Interval.STUDENT_T, 10,
                "the robots' paths, summed: each robot's straight move from step to step (a robot that joined from "
                        + "where it is first seen)"));
    }

    @Override
    public void begin(RunStart run) {
        StepView start = run.start();
        lastX = new double[start.robots()];
        lastY = new double[start.robots()];
        for (int r = 0; r < start.robots(); r++) {
            lastX[r] = start.xMm(r);
            lastY[r] = start.yMm(r);
        }
    }

    @Override
    public void step(StepView step) {
        int n = step.robots();
        if (n > lastX.length) {
            int had = lastX.length;
            lastX = Arrays.copyOf(lastX, n);
            lastY = Arrays.copyOf(lastY, n);
            Arrays.fill(lastX, had, n, Double.NaN);
        }
        for (int r = 0; r < n; r++) {
            double x = step.xMm(r);
            double y = step.yMm(r);
            if (!Double.isNaN(lastX[r])) {
                distanceMm += Math.hypot(x - lastX[r], y - lastY[r]);
            }
            lastX[r] = x;
            lastY[r] = y;
        }
    }

    @Override
    public double value() {
        return distanceMm / 1000;
    }
}

package robosim.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import robosim.geometry.GeometryEngine;
import robosim.geometry.StaticWorld;
import robosim.protocol.Arena;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.RobotProperties;

/**
 * The Geometry engine alone on the speed workload's world (test-envs/bench-N.xml: N Scouts of 16 sonars,
 * one per 2 m cell, every sonar read every step, each robot driving 20 mm and now and then turning):
 * microseconds per step, with the sonar pass on one core or split over two from SPLIT robots asking.
 * Three rounds of STEPS steps; the last is the warm figure.
 *
 * <p>usage: {@code java -cp "bench-jmh/target/lib/*:bench-jmh/target/bench-jmh-*.jar" robosim.bench.GeometrySteps
 * N STEPS SPLIT} (SPLIT 0: never split)
 */
public final class GeometrySteps {
    private GeometrySteps() {
    }

    public static void main(String[] args) {
        if (args.length != 3) {
            System.err.println("usage: GeometrySteps N STEPS SPLIT (SPLIT 0: the sonar pass on one core)");
            System.exit(2);
        }
        int n = Integer.parseInt(args[0]);
        int steps = Integer.parseInt(args[1]);
        int split = Integer.parseInt(args[2]);
        int side = 2 * (int) Math.ceil(Math.sqrt(n));
        List<RobotProperties> props = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            props.add(robosim.devices.RobotTypes.properties("Scout"));
        }
        GeometryEngine engine = new GeometryEngine(new StaticWorld(new Arena(0, 0, side * 1000.0, side * 1000.0),
                List.of()), props, split);
        double[][] pose = new double[n][];
        int perRow = side / 2;
        for (int i = 0; i < n; i++) {
            pose[i] = new double[] {1000 + (i % perRow) * 2000, 1000 + (i / perRow) * 2000, i * 37 % 360};
        }
        Random random = new Random(1);
        GeometryStepResponse out = engine.newResponse();
        for (int round = 1; round <= 3; round++) {
            long t0 = System.nanoTime();
            for (int k = 0; k < steps; k++) {
                GeometryStepRequest q = new GeometryStepRequest(n);
                for (int i = 0; i < n; i++) {
                    q.set(i, pose[i][0], pose[i][1], pose[i][2], random.nextInt(10) == 0 ? 30 : 0, 20, true);
                }
                engine.step(q, out);
                for (int i = 0; i < n; i++) {
                    double h = pose[i][2] + out.turnedDeg(i);
                    pose[i][0] += Math.cos(Math.toRadians(h)) * out.movedMm(i);
                    pose[i][1] += Math.sin(Math.toRadians(h)) * out.movedMm(i);
                    pose[i][2] = h;
                }
            }
            double us = (System.nanoTime() - t0) / 1e3 / steps;
            System.out.printf(Locale.ROOT, "round=%d robots=%d split_from=%d us_per_step=%.1f us_per_sonar=%.3f%n",
                    round, n, split, us, us / (n * 16));
        }
    }
}

import java.nio.file.Path;
import java.util.Locale;
import robosim.testkit.Simulation;

/**
 * What a test of control code costs with the testkit: K simulations one after another in one JVM, as the tests of a
 * test class run, each built from an environment file, started, run STEPS steps and closed; prints each one's
 * milliseconds (the first pays the JVM's class loading and JIT warm-up; the others are warm runs).
 * usage: java -cp 'runner/target/lib/*:testkit/target/testkit-0.1.0-SNAPSHOT.jar' bench/TestkitCost.java FILE.xml K STEPS
 * Prints one line per simulation: sim=k ms=M, then first_ms=... warm_median_ms=....
 */
public class TestkitCost {
    public static void main(String[] args) throws Exception {
        if (args.length != 3) {
            System.err.println("usage: java -cp 'runner/target/lib/*:testkit/target/testkit-0.1.0-SNAPSHOT.jar' "
                    + "bench/TestkitCost.java FILE.xml K STEPS");
            System.exit(2);
        }
        Path file = Path.of(args[0]);
        int k = Integer.parseInt(args[1]);
        long steps = Long.parseLong(args[2]);
        double[] ms = new double[k];
        for (int i = 0; i < k; i++) {
            long t0 = System.nanoTime();
            try (Simulation sim = Simulation.of(file).start()) {
                sim.run(steps);
            }
            ms[i] = (System.nanoTime() - t0) / 1e6;
            System.out.println(String.format(Locale.ROOT, "sim=%d ms=%.1f", i + 1, ms[i]));
        }
        double[] warm = java.util.Arrays.copyOfRange(ms, 1, k);
        java.util.Arrays.sort(warm);
        System.out.println(String.format(Locale.ROOT, "first_ms=%.1f warm_median_ms=%.1f", ms[0],
                warm.length == 0 ? Double.NaN : warm[warm.length / 2]));
    }
}

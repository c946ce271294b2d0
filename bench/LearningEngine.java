import java.nio.file.Path;
import java.util.Locale;
import java.util.SplittableRandom;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.core.WorldSpec;
import robosim.rl.BatchWorlds;

/**
 * The limit of learning over the link: the same K worlds a learner steps (robosim.rl.BatchWorlds, the same threads),
 * with each step's actions made inline, in this JVM, by the thread that steps them: uniformly random velocities
 * within each robot's limits, as bench/learning_bench.py's learner sends. No link, no Python, no copies out. The
 * clock starts after WARM steps (the JIT) and runs STEPS steps.
 * usage: java -cp 'runner/target/lib/*:runner/target/runner-*.jar' bench/LearningEngine.java FILE.xml WORLDS STEPS [WARM]
 *     [THREADS]   (THREADS: the batch's, default the cores, as the learning host's)
 * Prints one line: worlds=K robots=N threads=T steps=S wall=Ws steps/s=R robot-steps/s=R.
 */
public class LearningEngine {
    public static void main(String[] args) throws Exception {
        WorldSpec spec = new EnvironmentLoader().load(Path.of(args[0]));
        int worlds = Integer.parseInt(args[1]);
        long steps = Long.parseLong(args[2]);
        long warm = args.length > 3 ? Long.parseLong(args[3]) : 500;
        int threads = args.length > 4 ? Integer.parseInt(args[4]) : Runtime.getRuntime().availableProcessors();
        try (BatchWorlds batch = new BatchWorlds(spec, worlds, new BatchWorlds.Settings(1, 0, false, 0.5, threads))) {
            int n = batch.robots();
            double[][] limits = batch.limits();
            float[] actions = new float[worlds * n * 2];
            boolean[] reset = new boolean[worlds];
            long[] seeds = new long[worlds];
            SplittableRandom random = new SplittableRandom(1);
            long start = 0;
            for (long k = -warm; k < steps; k++) {
                if (k == 0) {
                    start = System.nanoTime();
                }
                for (int i = 0; i < actions.length; i++) {
                    double max = limits[(i / 2) % n][i % 2];
                    actions[i] = (float) random.nextDouble(-max, max);
                }
                batch.step(actions, reset, seeds);
            }
            double wall = (System.nanoTime() - start) / 1e9;
            System.out.printf(Locale.ROOT, "worlds=%d robots=%d threads=%d steps=%d wall=%.3fs steps/s=%.1f "
                    + "robot-steps/s=%.1f%n", worlds, n, threads, steps, wall, steps / wall, steps * worlds * n / wall);
        }
    }
}

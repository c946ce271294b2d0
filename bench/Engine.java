import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import robosim.devices.Drive;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.core.InProcessGeometry;
import robosim.environment.core.SimulationCore;
import robosim.environment.core.WorldSpec;
import robosim.protocol.RobotProperties;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * The engine alone: the limit of the one-JVM layout. The Environment's core and the Geometry engine step the
 * world of an environment file on one thread, with each robot's decisions made inline, on that thread, from
 * its last response: no control threads, no Hardware Simulators, no loop, no hand-offs. The decisions are
 * robosim.examples.Wander's, with a Scout's default speeds (legs of 250 mm at 500 mm/s; when a sonar within 60
 * degrees of ahead reads under 600 mm, a turn of 30 to 90 degrees at 90 deg/s towards the more open side), so
 * the world does the work a one-JVM run of test-envs/bench-N.xml does. The clock runs from step 0 to the
 * last, as the Environment's own clock does (JIT warm-up included, start-up left out).
 * usage: java -cp 'runner/target/lib/*' bench/Engine.java FILE.xml|N STEPS
 * N stands for test-envs/bench-N.xml; a third argument (the floors' mode, which the peers' side-by-side script
 * passes) is ignored, so this runs in a floor's place there, with CLASSPATH='runner/target/lib/*'.
 * Prints one line: robots=N steps=S wall=Ws steps/s=R robot-steps/s=R.
 */
public class Engine {
    public static void main(String[] args) throws Exception {
        Path file = args[0].matches("\\d+") ? Path.of("test-envs", "bench-" + args[0] + ".xml") : Path.of(args[0]);
        WorldSpec spec = new EnvironmentLoader().load(file);
        long steps = Long.parseLong(args[1]);
        int n = spec.robots().size();
        List<RobotProperties> properties = new ArrayList<>();
        for (WorldSpec.RobotSpec r : spec.robots()) {
            properties.add(robosim.devices.RobotTypes.properties(r.type()));
        }
        SimulationCore core = new SimulationCore(spec, properties); // (no metrics: as a run without liveMetrics)
        InProcessGeometry geometry = new InProcessGeometry(core.map().geometryWorld());
        Wanderer[] robots = new Wanderer[n];
        for (int i = 0; i < n; i++) {
            robots[i] = new Wanderer(spec.robots().get(i).name(), properties.get(i), spec.timeStepMs());
        }
        StepRequest[] requests = new StepRequest[n];
        long start = System.nanoTime();
        for (long k = 0; k < steps; k++) {
            for (int i = 0; i < n; i++) {
                requests[i] = robots[i].request(k);
            }
            core.step(k, requests, geometry);
            for (int i = 0; i < n; i++) {
                robots[i].respond(core.response(i));
            }
        }
        double wall = (System.nanoTime() - start) / 1e9;
        System.out.printf(Locale.ROOT, "robots=%d steps=%d wall=%.3fs steps/s=%.1f robot-steps/s=%.1f%n", n, steps, wall,
                steps / wall, steps * n / wall);
    }

    /** Wander's decisions, inline: a leg ahead or a turn, cut into one step's worth at a time. */
    static final class Wanderer {
        static final double CLEARANCE_MM = 600;
        static final double LEG_MM = 250;
        final Random random;
        final double[] angles;
        /** Wander's velocities: a Scout's defaults. */
        static final double VELOCITY_MM_S = 500;
        static final double ROT_VELOCITY_DEG_S = 90;
        final double stepSeconds;
        double moveLeft;
        double turnLeft;
        double[] sonar = new double[0];
        boolean slept;

        Wanderer(String name, RobotProperties p, long stepMs) {
            random = new Random(name.hashCode());
            angles = new double[p.sonars().size()];
            for (int s = 0; s < angles.length; s++) {
                angles[s] = normalise(p.sonars().get(s).angleDeg());
            }
            stepSeconds = Drive.seconds(stepMs);
        }

        StepRequest request(long k) {
            if (slept && moveLeft == 0 && turnLeft == 0) {
                decide();
            }
            slept = true;
            double move = Drive.piece(moveLeft, VELOCITY_MM_S, stepSeconds);
            double turn = Drive.piece(turnLeft, ROT_VELOCITY_DEG_S, stepSeconds);
            moveLeft -= move;
            turnLeft -= turn;
            return new StepRequest(k, move, turn, true, List.of());
        }

        void respond(StepResponse r) {
            sonar = r.sonarMm();
        }

        private void decide() {
            double ahead = Double.POSITIVE_INFINITY;
            double left = 0;
            double right = 0;
            for (int s = 0; s < sonar.length; s++) {
                if (Math.abs(angles[s]) <= 60) {
                    ahead = Math.min(ahead, sonar[s]);
                }
                if (angles[s] > 0 && angles[s] < 180) {
                    left += sonar[s];
                } else if (angles[s] < 0) {
                    right += sonar[s];
                }
            }
            if (ahead < CLEARANCE_MM) {
                double by = 30 + random.nextInt(61);
                turnLeft = left >= right ? by : -by;
            } else {
                moveLeft = LEG_MM;
            }
        }

        static double normalise(double deg) {
            double a = deg % 360;
            return a > 180 ? a - 360 : a <= -180 ? a + 360 : a;
        }
    }
}

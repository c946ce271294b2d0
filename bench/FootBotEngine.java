import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import robosim.devices.Drive;
import robosim.devices.RobotTypes;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.core.InProcessGeometry;
import robosim.environment.core.SimulationCore;
import robosim.environment.core.WorldSpec;
import robosim.protocol.Actuation;
import robosim.protocol.RobotProperties;
import robosim.protocol.SensorReading;
import robosim.protocol.StepRequest;

/**
 * The foot-bot engine alone: the limit of a one-JVM run of bench/footbots-100.xml (or -1000). The Environment's core
 * and the Geometry engine step the world on one thread, each robot's decisions made inline from its last response:
 * robosim.examples.Diffusion's (ARGoS's footbot_diffusion: the proximity ring's mean vector, straight on or a turn on
 * one wheel at 50 mm/s), every sensor of the robot asked every step and every range-and-bearing device sending, as a
 * Hardware Simulator asks and sends. No control threads, no loop, no hand-offs. The clock runs from step 0 to the last.
 * usage: java -cp 'runner/target/lib/*' bench/FootBotEngine.java FILE.xml STEPS
 * Prints one line: robots=N steps=S wall=Ws steps/s=R robot-steps/s=R.
 */
public class FootBotEngine {
    static final double V = 50;
    static final double ALPHA = Math.toRadians(7.5);
    static final double DELTA = 0.1;

    public static void main(String[] args) throws Exception {
        WorldSpec spec = new EnvironmentLoader().load(Path.of(args[0]));
        long steps = Long.parseLong(args[1]);
        int n = spec.robots().size();
        List<RobotProperties> properties = new ArrayList<>();
        List<List<String>> sensors = new ArrayList<>();
        double[] wheelBase = new double[n];
        for (WorldSpec.RobotSpec r : spec.robots()) {
            properties.add(RobotTypes.properties(r.type()));
            sensors.add(r.sensorNames());
            wheelBase[sensors.size() - 1] = RobotTypes.known(r.type()).body().wheelBaseMm();
        }
        SimulationCore core = new SimulationCore(spec, properties);
        InProcessGeometry geometry = new InProcessGeometry(core.map().geometryWorld());
        double seconds = Drive.seconds(spec.timeStepMs());
        StepRequest[] requests = new StepRequest[n];
        double[][] wheels = new double[n][2];
        List<Actuation> rab = List.of(new Actuation("rab", new double[10]));
        long start = System.nanoTime();
        for (long k = 0; k < steps; k++) {
            for (int i = 0; i < n; i++) {
                double[] drive = Drive.wheels(wheels[i][0], wheels[i][1], wheelBase[i], seconds);
                requests[i] = new StepRequest(k, drive[1], drive[0], false, List.of(), sensors.get(i))
                        .with(k == 0 && spec.robots().get(i).actuators().stream().anyMatch(a -> a.name().equals("rab"))
                                ? rab : List.of(), StepRequest.Gripper.STAY);
            }
            core.step(k, requests, geometry);
            for (int i = 0; i < n; i++) {
                decide(core.response(i).readings(), wheels[i]);
            }
        }
        double wall = (System.nanoTime() - start) / 1e9;
        System.out.printf(Locale.ROOT, "robots=%d steps=%d wall=%.3fs steps/s=%.1f robot-steps/s=%.1f%n", n, steps, wall,
                steps / wall, steps * n / wall);
    }

    /** Diffusion's decision from the proximity ring's readings, into the wheels' speeds. */
    static void decide(List<SensorReading> readings, double[] wheels) {
        for (SensorReading r : readings) {
            if (r.name().equals("proximity")) {
                double[] near = r.values();
                double x = 0;
                double y = 0;
                for (int k = 0; k < near.length; k++) {
                    double a = Math.toRadians(7.5 + k * 360.0 / near.length);
                    x += near[k] * Math.cos(a);
                    y += near[k] * Math.sin(a);
                }
                double angle = Math.atan2(y / near.length, x / near.length);
                boolean straight = Math.abs(angle) <= ALPHA && Math.hypot(x, y) / near.length < DELTA;
                wheels[0] = straight || angle > 0 ? V : 0;
                wheels[1] = straight || angle <= 0 ? V : 0;
            }
        }
    }
}

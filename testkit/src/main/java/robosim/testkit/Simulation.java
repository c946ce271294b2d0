package robosim.testkit;

import java.io.IOException;
import java.net.InetAddress;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import robosim.api.RobotControl;
import robosim.environment.config.EnvironmentFileException;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.core.Parameters;
import robosim.environment.core.WorldSpec;
import robosim.environment.metrics.Metrics;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.RunStatus;
import robosim.environment.run.Settings;
import robosim.hardware.ControlFailure;
import robosim.hardware.InMemoryRobots;
import robosim.protocol.InMemoryLink;

/**
 * A whole simulation in the caller's JVM, for testing control code: the Environment's loop, collision and
 * sonar, and each robot's Hardware Simulator running its control code, linked in memory as in
 * {@code headless.sh --one-jvm} (the same steps as a run of separate processes). Build it from an environment
 * file or a {@link World} built in code, give robots control objects of your own (or let them run the file's
 * control classes), then run it a number of steps or until a condition holds, and ask where each robot is,
 * what it sensed, which messages it received, what it touched and what it reported, and the run's built-in
 * metrics ({@link #metric}).
 *
 * <p>A robot whose control code throws out of {@code run} fails the test: the next {@link #run}, {@link #runUntil}
 * or {@link #close} throws an {@link AssertionError} naming the robot and the step, with what it threw as its
 * cause, unless the builder was told to expect it ({@link Builder#expectFailure}); {@link #failure} asks.
 *
 * <pre>{@code
 * try (Simulation sim = Simulation.of(World.arena(4, 4).robot("r1", "Scout", 1, 2, 0))
 *         .control("r1", new MyControl()).start()) {
 *     sim.run(50);
 *     assertTrue(sim.pose("r1").xMm() > 1500);
 * }
 * }</pre>
 *
 * Not thread-safe: one test thread drives it. Its viewer port (loopback) lets a viewer watch while it runs.
 */
public final class Simulation implements AutoCloseable {
    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(Simulation.class);
    private final ClientWorkerCoordinator coordinator;
    /** The world as read (its parameters for the warnings at the end of what control code asked for). */
    private final WorldSpec world;
    private final Map<String, WatchedRobot> robots;
    private final InMemoryRobots hardware;
    private final long waitMs;
    /** The robots whose control code may fail without failing the test. */
    private final Set<String> expected;
    /** The robots whose control code's failure has failed the test already (it is said once). */
    private final Set<String> said = new HashSet<>();

    private Simulation(ClientWorkerCoordinator coordinator, WorldSpec world, Map<String, WatchedRobot> robots,
            InMemoryRobots hardware, long waitMs, Set<String> expected) {
        this.coordinator = coordinator;
        this.world = world;
        this.robots = robots;
        this.hardware = hardware;
        this.waitMs = waitMs;
        this.expected = expected;
    }

    /**
     * A simulation of the environment file {@code file}, read at {@link Builder#start} (with the builder's
     * parameters); its robots run the file's control classes (found on this JVM's class path) unless
     * {@link Builder#control} gives one an object.
     *
     * @throws IllegalArgumentException naming a file that is not there
     */
    public static Builder of(Path file) {
        if (!java.nio.file.Files.isRegularFile(file)) {
            throw new IllegalArgumentException(file + ": file not found");
        }
        return new Builder(null, file);
    }

    /** A simulation of a world built in code; every robot needs a control object ({@link Builder#control}). */
    public static Builder of(World world) {
        return new Builder(world.spec(), null);
    }

    private static WorldSpec load(Path file, Map<String, String> params) {
        try {
            return new EnvironmentLoader().load(file, params);
        } catch (EnvironmentFileException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
    }

    /** How a {@link Simulation} starts. */
    public static final class Builder {
        /** The world built in code, or null for a file (read at the start). */
        private final WorldSpec spec;
        /** The environment file, or null for a world built in code. */
        private final Path file;
        private final Map<String, RobotControl> controls = new HashMap<>();
        /** Control objects chosen by each robot's description, for the robots {@link #control} gives none, or null. */
        private java.util.function.Function<WorldSpec.RobotSpec, RobotControl> chooser;
        private final Map<String, String> params = new LinkedHashMap<>();
        private final Set<String> expected = new HashSet<>();
        private Long seed;
        private robosim.loop.LoopFunctions loopFunctions;
        private Duration stepTimeout = Duration.ofSeconds(10);
        private Duration wait = Duration.ofMinutes(10);
        private boolean history = true;

        private Builder(WorldSpec spec, Path file) {
            this.spec = spec;
            this.file = file;
        }

        /** Robot {@code robot} runs {@code control} (this object, not a new instance of the file's class). */
        public Builder control(String robot, RobotControl control) {
            known(spec, robot);
            controls.put(robot, control);
            return this;
        }

        /**
         * Each robot that {@link #control} gives no object runs the one {@code chooser} gives for its description
         * (its type, control and sensors, as the file says), or, where it gives null, the file's control class.
         */
        public Builder controls(java.util.function.Function<WorldSpec.RobotSpec, RobotControl> chooser) {
            this.chooser = chooser;
            return this;
        }

        /** Refuses a robot {@code spec} does not have (a file's, once read). */
        private static void known(WorldSpec spec, String robot) {
            if (spec != null && spec.indexOf(robot) < 0) {
                throw new IllegalArgumentException("no robot named \"" + robot + "\" in " + spec.source());
            }
        }

        /**
         * The control code's parameter {@code name} is {@code value} ({@code Robot.parameter}), as {@code --param}
         * gives it: for a file, a {@code ${NAME:default}} placeholder or a {@code <param>} of its world (an
         * unknown name is an IllegalArgumentException at {@link #start}, naming the file's parameters); for a world
         * built in code, a parameter of every robot.
         */
        public Builder param(String name, String value) {
            params.put(name, value);
            return this;
        }

        /** As {@link #param(String, String)}, a whole number. */
        public Builder param(String name, long value) {
            return param(name, Long.toString(value));
        }

        /** As {@link #param(String, String)}, a number. */
        public Builder param(String name, double value) {
            return param(name, Double.toString(value));
        }

        /**
         * The world's loop functions are {@code code} (this object, not a new instance of the file's class; with the
         * file's {@code <loopFunctions>} parameters, if it names any), so the test can ask it what it saw. A loop
         * function that throws ends the run: the next {@link Simulation#run} throws, naming it and the step.
         */
        public Builder loopFunctions(robosim.loop.LoopFunctions code) {
            this.loopFunctions = java.util.Objects.requireNonNull(code, "code");
            return this;
        }

        /** The run's seed (over the file's or the world's), as a sweep's or {@code --seed} gives it. */
        public Builder seed(long seed) {
            this.seed = seed;
            return this;
        }

        /**
         * Robot {@code robot}'s control code may throw out of {@code run} without failing the test (the robot then
         * stands still); {@link Simulation#failure} says whether it did.
         */
        public Builder expectFailure(String robot) {
            known(spec, robot);
            expected.add(robot);
            return this;
        }

        /**
         * A robot whose control code does not yield (make a call) this long after its step went out is dropped,
         * and the simulation goes on without it (default 10 s).
         */
        public Builder stepTimeout(Duration timeout) {
            stepTimeout = timeout;
            return this;
        }

        /**
         * Whether the simulation keeps every message and contact of its robots for {@link Simulation#received} and
         * {@link Simulation#contacts} (default: it does). A long run whose robots are driven from outside, the
         * ROS 2 bridge's, keeps none: its memory does not grow with them, and those two then refuse.
         */
        public Builder history(boolean keep) {
            history = keep;
            return this;
        }

        /** The longest {@link Simulation#run} waits for its steps before it gives up (default 10 min). */
        public Builder waitAtMost(Duration timeout) {
            wait = timeout;
            return this;
        }

        /**
         * Starts the simulation: every robot is placed and welcomed, its control code starts with step 0, which
         * nothing has computed yet.
         *
         * @throws IllegalArgumentException naming the file, the line and what is wrong with it, a robot the world does
         *     not have, a robot without control code, or one that cannot start
         */
        public Simulation start() {
            WorldSpec spec = file != null ? load(file, params) : params.isEmpty() ? this.spec
                    : this.spec.withParameters(new Parameters(join(this.spec.parameters().world(), params),
                            this.spec.parameters().robots()));
            for (String robot : controls.keySet()) {
                known(spec, robot);
            }
            for (String robot : expected) {
                known(spec, robot);
            }
            if (seed != null) {
                spec = spec.withSeed(seed);
            }
            if (loopFunctions != null) {
                spec = spec.withLoopFunctions(new robosim.environment.core.LoopSpec(loopFunctions.getClass().getName(),
                        spec.loopFunctions() == null ? Map.of() : spec.loopFunctions().parameters(), loopFunctions));
            }
            Map<String, RobotControl> controls = new HashMap<>(this.controls);
            for (WorldSpec.RobotSpec r : spec.robots()) {
                RobotControl chosen = chooser == null || controls.containsKey(r.name()) ? null : chooser.apply(r);
                if (chosen != null) {
                    controls.put(r.name(), chosen);
                }
                if (!controls.containsKey(r.name()) && r.control().isBlank()) {
                    throw new IllegalArgumentException("robot " + r.name() + " of " + spec.source()
                            + " has no control code: give it one with control(\"" + r.name() + "\", ...)");
                }
            }
            Map<String, WatchedRobot> watched = new LinkedHashMap<>();
            InMemoryRobots robots = new InMemoryRobots();
            InMemoryLink.Starter starter = new InMemoryLink.Starter() {
                @Override
                public InMemoryLink.Robot start(String name, String type, String controlClass,
                        InMemoryLink.Environment environment) {
                    RobotControl given = controls.get(name);
                    WatchedRobot w = new WatchedRobot(name, history);
                    InMemoryLink.Environment seen = w.environment(environment);
                    w.attach(given != null ? robots.start(name, type, given, seen)
                            : robots.start(name, type, controlClass, seen));
                    watched.put(name, w);
                    return w;
                }

                @Override
                public InMemoryLink.ControlEnd awaitControlCode(long ms) throws InterruptedException {
                    return robots.awaitControlCode(ms);
                }
            };
            Settings settings;
            try {
                settings = Settings.builder().ports(InetAddress.getLoopbackAddress(), 0, 0, 0).inProcessGeometry(true)
                        .stepTimeoutMs(stepTimeout.toMillis()).speed(0).robotsInThisJvm(starter).liveMetrics(true)
                        .build();
            } catch (RuntimeException e) {
                throw new IllegalArgumentException(e.getMessage(), e);
            }
            ClientWorkerCoordinator c = new ClientWorkerCoordinator(spec, settings);
            c.startPaused();
            Simulation sim = new Simulation(c, spec, watched, robots, Math.max(1, wait.toMillis()),
                    Set.copyOf(expected));
            try {
                c.start();
                c.startRobotsInThisJvm();
                if (!c.awaitStart(sim.waitMs, TimeUnit.MILLISECONDS)) {
                    String why = c.status().reason();
                    c.close();
                    throw new IllegalArgumentException("the simulation of " + spec.source() + " did not start"
                            + (why == null || why.isEmpty() ? "" : ": " + why));
                }
            } catch (IOException e) {
                c.close();
                throw new IllegalStateException("could not open the simulation's ports: " + e.getMessage(), e);
            } catch (InterruptedException e) {
                c.close();
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while the simulation started", e);
            }
            return sim;
        }

        private static Map<String, String> join(Map<String, String> world, Map<String, String> given) {
            Map<String, String> all = new LinkedHashMap<>(world);
            all.putAll(given);
            return all;
        }
    }

    /** The world it simulates, as read from its file or built (with the builder's parameters and seed). */
    public WorldSpec world() {
        return world;
    }

    /** Steps completed so far (0 before {@link #run}). */
    public long steps() {
        return coordinator.status().step();
    }

    /**
     * Runs {@code n} more steps and holds; returns this.
     *
     * @throws IllegalStateException if the simulation ended first (every robot gone), naming why
     */
    public Simulation run(long n) {
        if (n < 1) {
            throw new IllegalArgumentException("run(n) needs n >= 1, got " + n);
        }
        long wanted = steps() + n;
        long at;
        try {
            at = coordinator.step(n, waitMs, TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted after step " + steps(), e);
        }
        failIfControlFailed();
        if (at < wanted) {
            RunStatus s = coordinator.status();
            throw new IllegalStateException(s.state() == RunStatus.State.ENDED
                    ? "the simulation ended after " + s.step() + " steps: " + s.reason()
                    : "step " + wanted + " was not out after " + waitMs + " ms (step " + s.step() + " is)");
        }
        return this;
    }

    /**
     * Runs one step at a time until {@code done} holds (looked at after each step) or {@code maxSteps} steps have
     * run; true if it holds.
     */
    public boolean runUntil(Predicate<Simulation> done, long maxSteps) {
        for (long i = 0; i < maxSteps; i++) {
            if (done.test(this)) {
                return true;
            }
            run(1);
        }
        return done.test(this);
    }

    /** The robots, in the world's order. */
    public List<String> robots() {
        return new ArrayList<>(robots.keySet());
    }

    /** Where {@code robot} stands after the last step (where it was placed, before the first). */
    public Pose pose(String robot) {
        return watched(robot).pose();
    }

    /** {@code robot}'s sonar ranges in the last step, mm, in its sonars' order (empty before the first step). */
    public double[] sonar(String robot) {
        return watched(robot).sonar();
    }

    /** {@code robot}'s sensor {@code sensor} in the last step (as {@code Robot.sensor}), or null if it gave none. */
    public double[] reading(String robot, String sensor) {
        return watched(robot).reading(sensor);
    }

    /**
     * Every message {@code robot} has received so far, in order.
     *
     * @throws IllegalStateException if the simulation keeps no history ({@link Builder#history})
     */
    public List<Received> received(String robot) {
        return watched(robot).received();
    }

    /**
     * Every step in which {@code robot} touched something so far, in order.
     *
     * @throws IllegalStateException if the simulation keeps no history ({@link Builder#history})
     */
    public List<Contact> contacts(String robot) {
        return watched(robot).contacts();
    }

    /**
     * What {@code robot}'s control code threw out of {@code run} so far, and at which step (steps completed, as
     * {@link #steps}), or null if it did not.
     */
    public ControlFailure failure(String robot) {
        watched(robot);
        for (ControlFailure f : hardware.failures()) {
            if (f.robot().equals(robot)) {
                return f;
            }
        }
        return null;
    }

    /** Whether {@code robot}'s control code threw out of {@code run} so far. */
    public boolean failed(String robot) {
        return failure(robot) != null;
    }

    /**
     * The newest value {@code robot} reported under {@code name} ({@code Robot.report}) with its requests for the
     * steps run so far, or null if it reported none.
     */
    public Double reported(String robot, String name) {
        return watched(robot).reports().get(name);
    }

    /** Everything {@code robot} reported so far: the newest value of each name, in the order first reported. */
    public Map<String, Double> reports(String robot) {
        return watched(robot).reports();
    }

    /**
     * The built-in metric {@code name} of the run so far ({@code distance_m}, {@code contacts}, ...: the same numbers a
     * sweep's row gives for a run of these steps, its area counted in cells of 0.5 m, a sweep's default;
     * {@code describe.sh metrics} lists them).
     *
     * @throws IllegalArgumentException naming the built-in metrics, for a name that is none of them
     */
    public double metric(String name) {
        if (Metrics.info(name) == null) {
            throw new IllegalArgumentException("no built-in metric named \"" + name + "\" (they are: "
                    + String.join(", ", Metrics.names()) + ")");
        }
        return coordinator.metrics().getOrDefault(name, Double.NaN);
    }

    /** Every built-in metric of the run so far, by name in column order (none before the first step). */
    public Map<String, Double> metrics() {
        return coordinator.metrics();
    }

    /** Why the simulation is over for {@code robot} (dropped, the end), or null while it takes part. */
    public String ended(String robot) {
        return watched(robot).end();
    }

    /** The loopback port a viewer connects to ({@code scripts/viewer2d.sh localhost PORT}) to watch the run. */
    public int viewerPort() {
        return coordinator.ports()[1];
    }

    private WatchedRobot watched(String robot) {
        WatchedRobot w = robots.get(robot);
        if (w == null) {
            throw new IllegalArgumentException("no robot named \"" + robot + "\" (robots: " + robots.keySet() + ")");
        }
        return w;
    }

    /**
     * Ends the simulation: every control code is told (its blocked call throws) and gets up to 2 s to end (its
     * {@code finally} blocks), the ports close.
     *
     * @throws AssertionError if a robot's control code threw out of {@code run} (not expected, not said yet)
     */
    @Override
    public void close() {
        coordinator.close();
        try {
            for (String w : world.parameters().warnings(coordinator.awaitControlCode(2000).asked())) {
                LOG.warn(w);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        failIfControlFailed();
    }

    /** Fails the test with the first failure of control code not expected and not said yet. */
    private void failIfControlFailed() {
        for (ControlFailure f : hardware.failures()) {
            if (!expected.contains(f.robot()) && said.add(f.robot())) {
                throw new AssertionError("robot " + f.robot() + ": its control code failed at step " + f.step() + ": "
                        + f.summary() + " (expectFailure(\"" + f.robot() + "\") if the test expects it)", f.thrown());
            }
        }
    }
}

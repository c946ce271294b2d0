package robosim.testkit;

import java.io.IOException;
import java.net.InetAddress;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import robosim.api.RobotControl;
import robosim.environment.config.EnvironmentFileException;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.core.WorldSpec;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.net.RunStatus;
import robosim.environment.net.Settings;
import robosim.hardware.InMemoryRobots;
import robosim.protocol.InMemoryLink;

/**
 * A whole simulation in the caller's JVM, for testing control code: the Environment's loop, collision and
 * sonar, and each robot's Hardware Simulator running its control code, linked in memory as in
 * {@code headless.sh --one-jvm} (the same steps as a run of separate processes). Build it from an environment
 * file or a {@link World} built in code, give robots control objects of your own (or let them run the file's
 * control classes), then run it a number of steps or until a condition holds, and ask where each robot is,
 * what it sensed, which messages it received and what it touched.
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
    private final ClientWorkerCoordinator coordinator;
    private final Map<String, WatchedRobot> robots;
    private final long waitMs;

    private Simulation(ClientWorkerCoordinator coordinator, Map<String, WatchedRobot> robots, long waitMs) {
        this.coordinator = coordinator;
        this.robots = robots;
        this.waitMs = waitMs;
    }

    /**
     * A simulation of the environment file {@code file}; its robots run the file's control classes (found on this
     * JVM's class path) unless {@link Builder#control} gives one an object.
     *
     * @throws IllegalArgumentException naming the file, the line and what is wrong with it
     */
    public static Builder of(Path file) {
        try {
            return new Builder(new EnvironmentLoader().load(file));
        } catch (EnvironmentFileException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
    }

    /** A simulation of a world built in code; every robot needs a control object ({@link Builder#control}). */
    public static Builder of(World world) {
        return new Builder(world.spec());
    }

    /** How a {@link Simulation} starts. */
    public static final class Builder {
        private final WorldSpec spec;
        private final Map<String, RobotControl> controls = new HashMap<>();
        private Duration stepTimeout = Duration.ofSeconds(10);
        private Duration wait = Duration.ofMinutes(10);

        private Builder(WorldSpec spec) {
            this.spec = spec;
        }

        /** Robot {@code robot} runs {@code control} (this object, not a new instance of the file's class). */
        public Builder control(String robot, RobotControl control) {
            if (spec.indexOf(robot) < 0) {
                throw new IllegalArgumentException("no robot named \"" + robot + "\" in " + spec.source());
            }
            controls.put(robot, control);
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

        /** The longest {@link Simulation#run} waits for its steps before it gives up (default 10 min). */
        public Builder waitAtMost(Duration timeout) {
            wait = timeout;
            return this;
        }

        /**
         * Starts the simulation: every robot is placed and welcomed, its control code starts with step 0, which
         * nothing has computed yet.
         *
         * @throws IllegalArgumentException naming a robot without control code, or one that cannot start
         */
        public Simulation start() {
            for (WorldSpec.RobotSpec r : spec.robots()) {
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
                    WatchedRobot w = new WatchedRobot(given != null ? robots.start(name, type, given, environment)
                            : robots.start(name, type, controlClass, environment), name);
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
                        .stepTimeoutMs(stepTimeout.toMillis()).speed(0).robotsInThisJvm(starter).build();
            } catch (RuntimeException e) {
                throw new IllegalArgumentException(e.getMessage(), e);
            }
            ClientWorkerCoordinator c = new ClientWorkerCoordinator(spec, settings);
            c.startPaused();
            Simulation sim = new Simulation(c, watched, Math.max(1, wait.toMillis()));
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

    /** Every message {@code robot} has received so far, in order. */
    public List<Received> received(String robot) {
        return watched(robot).received();
    }

    /** Every step in which {@code robot} touched something so far, in order. */
    public List<Contact> contacts(String robot) {
        return watched(robot).contacts();
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
     */
    @Override
    public void close() {
        coordinator.close();
        try {
            coordinator.awaitControlCode(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}

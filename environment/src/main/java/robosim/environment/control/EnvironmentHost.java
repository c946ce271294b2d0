package robosim.environment.control;

import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.config.EnvironmentFileException;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.core.WorldSpec;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.RunStatus;
import robosim.environment.run.RunSummary;
import robosim.environment.run.Settings;

/**
 * Runs simulations one after another on the same ports: the first from the file given at start-up,
 * later ones when the control port says {@code start} (the same file again) or {@code load FILE} (a
 * new file: the current simulation ends, its robots are told, and the Environment waits for the new
 * file's robots). Each simulation is one {@link ClientWorkerCoordinator}.
 */
public final class EnvironmentHost {
    private static final Logger LOG = LoggerFactory.getLogger(EnvironmentHost.class);

    private final Settings base;
    private final boolean keepRunning;
    private Path file;
    private WorldSpec spec;
    private ClientWorkerCoordinator current;
    private Settings settings;
    private boolean shutdown;
    private boolean startPaused;
    private volatile RobotLaunches launches;
    /** True while {@code load} replaces the simulation: {@link #run} must not take its end for the last. */
    private boolean replacing;

    /**
     * @param keepRunning after a simulation ends, wait for {@code start}, {@code load} or
     *     {@code shutdown} instead of returning from {@link #run}
     * @param startPaused the first simulation waits for {@code start} once every client is there
     */
    public EnvironmentHost(Path file, WorldSpec spec, Settings settings, boolean keepRunning,
            boolean startPaused) {
        this.file = file;
        this.spec = spec;
        this.base = settings;
        this.settings = settings;
        this.keepRunning = keepRunning;
        this.startPaused = startPaused;
    }

    /** The control port's {@code add ... CONTROL} starts robot processes with this ({@code --launch-robots}). */
    public void launchRobots(RobotLaunches with) {
        launches = with;
    }

    /** The robot launcher, or null: {@code add} then waits for a robot process started elsewhere. */
    public RobotLaunches launches() {
        return launches;
    }

    /** Where a robot process on this machine connects: the address the robot port listens on, or loopback. */
    public String robotHost() {
        java.net.InetAddress bind = base.bind();
        return bind.isAnyLocalAddress() ? "127.0.0.1" : bind.getHostAddress();
    }

    /** Stops every robot process {@code add} started that is still running (the Environment is closing). */
    public void stopLaunched() {
        RobotLaunches l = launches;
        if (l != null) {
            l.close();
        }
    }

    /** Binds the ports and opens the first simulation; a port in use is a BindException naming it. */
    public void open() throws IOException {
        ClientWorkerCoordinator c;
        synchronized (this) {
            current = newSession(spec, startPaused);
            c = current;
        }
        c.startRobotsInThisJvm(); // (without the lock: control classes' constructors run)
    }


    /**
     * Under this host's lock: opens the next simulation on the same ports. The previous one's ports
     * must be free already ({@link #release}, called without the lock).
     */
    private ClientWorkerCoordinator newSession(WorldSpec s, boolean paused) throws IOException {
        sessions++;
        if (base.record() != null && sessions > 1) { // each simulation its own recording: FILE, FILE-2, ...
            settings = settings.toBuilder().record(numbered(base.record(), sessions)).build();
        }
        ClientWorkerCoordinator c = new ClientWorkerCoordinator(s, settings);
        if (paused) {
            c.startPaused();
        }
        c.start();
        int[] p = c.ports();
        // later simulations listen on the same ports, even when the first ones were picked by the system
        settings = base.toBuilder().ports(base.bind(), p[0], p[1], Math.max(p[2], base.geometryPort())).build();
        return c;
    }

    /** Simulations opened so far (this host's lock). */
    private int sessions;

    /** {@code run.rec} as the n-th simulation's recording: {@code run-n.rec}. */
    static Path numbered(Path file, int n) {
        String name = file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String numbered = dot > 0 ? name.substring(0, dot) + "-" + n + name.substring(dot) : name + "-" + n;
        return file.resolveSibling(numbered);
    }

    /**
     * The JVM's {@code shutdown} hook (Ctrl-C, SIGTERM): stops the current simulation and waits (up to 5 s)
     * for its recording's end and its viewers' last updates.
     */
    public void stopOnSignal() {
        ClientWorkerCoordinator c = current();
        c.stop("the Environment was stopped");
        try {
            c.awaitOutputDone(5000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** The ports of the current simulation: robot, viewer, geometry (-1 when in-process). */
    public synchronized int[] ports() {
        return current.ports();
    }

    public synchronized ClientWorkerCoordinator current() {
        return current;
    }

    public synchronized Path file() {
        return file;
    }

    /**
     * Waits for each simulation to end and reports it; returns the exit code when the host is done:
     * at the first end unless it keeps running, else at {@code shutdown}.
     */
    public int run(Consumer<RunSummary> ended) throws InterruptedException {
        while (true) {
            ClientWorkerCoordinator c;
            synchronized (this) {
                c = current;
            }
            c.awaitEnd();
            c.awaitOutputDone(5000);
            RunSummary summary = c.summary();
            ended.accept(summary);
            synchronized (this) {
                while (replacing) {
                    wait();
                }
                if (current != c) {
                    continue; // a new file was loaded: its simulation is already waiting for clients
                }
                if (shutdown || !keepRunning) {
                    return shutdown ? 0 : exitCode(summary);
                }
                LOG.info("simulation over; waiting for start, load or shutdown on the control port");
                while (current == c && !shutdown) {
                    wait();
                }
                if (shutdown) {
                    return 0;
                }
            }
        }
    }

    /**
     * The exit code of a run that ends the Environment: 0 when it completed with every robot, 1 when it
     * did not complete, {@link #EXIT_ROBOTS_REMOVED} when it completed without one robot or more,
     * {@link #EXIT_CONTROL_FAILED} when the world's loop functions threw.
     */
    static int exitCode(RunSummary summary) {
        if (summary.experimentFailed()) {
            return EXIT_CONTROL_FAILED;
        }
        if (!summary.completed()) {
            return 1;
        }
        return summary.departures().isEmpty() ? 0 : EXIT_ROBOTS_REMOVED;
    }

    /** The exit code of a completed run that lost a robot (it left, or was removed). */
    public static final int EXIT_ROBOTS_REMOVED = 3;

    /**
     * The exit code of a run (in this JVM, {@code --one-jvm}) that went on while a robot's control code threw out
     * of {@code run}: the robot process's own code for it ({@code HardwareSimulator.EXIT_CONTROL_FAILED}); and of a
     * run whose loop functions threw.
     */
    public static final int EXIT_CONTROL_FAILED = 4;

    /** {@code start}: resumes a paused simulation, or runs the current file again once it has ended. */
    public String start() throws IOException, InterruptedException {
        ClientWorkerCoordinator c = current();
        if (c.status().state() != RunStatus.State.ENDED) {
            c.resume();
            return "running";
        }
        release(c);
        synchronized (this) {
            if (shutdown) {
                return "the Environment is shutting down";
            }
            if (current != c) {
                return "a new simulation is already waiting for its robots";
            }
            current = newSession(spec, false);
            notifyAll();
            c = current;
        }
        c.startRobotsInThisJvm(); // (without the lock: control classes' constructors run)
        return "started a new simulation of " + file;
    }

    /**
     * Without the lock: lets an ended simulation's viewers take its end (so a viewer sees why, not a
     * broken connection), then closes it and waits until its ports are free for the next one.
     */
    private static void release(ClientWorkerCoordinator ended) throws IOException {
        try {
            ended.awaitOutputDone(5000);
            ended.close();
            ended.awaitServersClosed(5000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while the previous simulation closed its ports");
        }
    }

    /** {@code load FILE}: checks the file first; a bad one changes nothing. */
    public String load(Path newFile) throws IOException, EnvironmentFileException {
        WorldSpec loaded = new EnvironmentLoader().load(newFile);
        ClientWorkerCoordinator old;
        ClientWorkerCoordinator next;
        synchronized (this) {
            if (shutdown) {
                return "the Environment is shutting down";
            }
            old = current;
            replacing = true;
        }
        try {
            old.stop("a new environment file was loaded: " + newFile);
            release(old);
            synchronized (this) {
                file = newFile;
                spec = loaded;
                current = newSession(loaded, false);
                next = current;
            }
        } finally {
            synchronized (this) {
                replacing = false;
                notifyAll();
            }
        }
        next.startRobotsInThisJvm();
        LOG.info("loaded {}: waiting for its {} robot(s)", newFile, loaded.robots().size());
        return "loaded " + newFile + "; waiting for " + loaded.robots().size() + " robot(s)";
    }

    /** {@code stop}: ends the current simulation (robots, viewers and Geometry are told). */
    public String stop() throws InterruptedException {
        ClientWorkerCoordinator c = current();
        c.stop("stopped from the control port");
        c.awaitEnd(10, TimeUnit.SECONDS);
        return "stopped at step " + c.status().step();
    }

    /** {@code shutdown}: ends the current simulation and lets {@link #run} return. */
    public String shutdown() {
        ClientWorkerCoordinator c;
        synchronized (this) {
            shutdown = true;
            c = current;
            notifyAll();
        }
        c.stop("the Environment was shut down from the control port");
        return "shutting down";
    }
}

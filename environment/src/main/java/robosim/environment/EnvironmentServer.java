package robosim.environment;

import java.io.IOException;
import java.net.BindException;
import java.nio.file.Path;
import java.util.List;
import java.util.ServiceLoader;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import robosim.environment.control.ControlServer;
import robosim.environment.control.EnvironmentCommands;
import robosim.environment.control.EnvironmentDirectories;
import robosim.environment.control.EnvironmentHost;
import robosim.environment.control.RobotLaunches;
import robosim.environment.control.WebViewers;
import robosim.environment.core.WorldSpec;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.run.Departure;
import robosim.environment.run.Settings;
import robosim.protocol.InMemoryLink;
import robosim.protocol.StepNumbers;
import robosim.protocol.VirtualThreads;
import robosim.web.WebViewerServer;

/**
 * An Environment server, in a JVM of its own ({@link EnvironmentMain}) or in a runner's ({@code headless.sh
 * --one-jvm}), built from one {@link Plan}: it opens its ports (and the control port and the browser viewer when the
 * plan has them), runs its host's simulations one after another, and hands on its lines: {@code listening
 * robots=P viewers=P geometry=P control=P [web=P] tls=on|off} once its ports are bound, {@code running robots=N}
 * once every client of the first simulation is there (thread {@code start-announcer}), {@code left robot=NAME
 * step=S reason=WHY} for each robot that left, {@code experiment-failed WHY} when the world's loop functions threw,
 * and the summary {@code steps=... robots=... wall_s=...}; with robots
 * in its JVM, a {@code control-failed NAME: ...} line for each robot whose control code threw and a
 * {@code control-running NAME} line for each whose control code was still running 2 s after the end.
 */
public final class EnvironmentServer {
    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(EnvironmentServer.class);
    /** How long the control code of robots in this JVM gets to end after the run, ms (a robot process's grace). */
    private static final long CONTROL_GRACE_MS = 2000;

    private EnvironmentServer() {
    }

    /**
     * What an Environment runs: the world of {@code file} ({@code world}, parameters and seed applied) as
     * {@code settings} say; the control port ({@code controlPort}: 0 a free one, -1 none) and the browser viewer's
     * ({@code webPort}, likewise); the directories the control port's {@code load} may read; whether it waits for
     * more simulations after one ends ({@code keepRunning}), holds before step 1 until told ({@code startPaused}), and
     * starts a robot process for the control port's {@code add} ({@code launchRobots}).
     */
    public record Plan(Path file, WorldSpec world, Settings settings, int controlPort, int webPort,
            EnvironmentDirectories directories, boolean keepRunning, boolean startPaused, boolean launchRobots) {
    }

    /**
     * What starts the robots of {@code world} (of {@code file}) in this JVM: the Hardware Simulator's starter, with
     * this JVM's virtual threads set for it (every robot's control code and the loop on one carrier, unless set
     * already).
     *
     * @throws IllegalArgumentException one line: the Hardware Simulator is not on the class path, or a robot has no
     *     control class this JVM finds
     */
    public static InMemoryLink.Starter robotsInThisJvm(Path file, WorldSpec world) {
        if (System.getProperty(VirtualThreads.PARALLELISM) == null) {
            // every robot's control code and the loop on one carrier: a step passes between them without a wake of
            // the operating system's (the loop's thread: run.LoopThread); read once, as the first virtual thread
            // starts, so a JVM that has run virtual threads already keeps what it has
            System.setProperty(VirtualThreads.PARALLELISM, "1");
        }
        InMemoryLink.Starter starter = ServiceLoader.load(InMemoryLink.Starter.class).findFirst().orElse(null);
        if (starter == null) {
            throw new IllegalArgumentException("--one-jvm needs the Hardware Simulator (robosim hardware-sim) on the "
                    + "class path");
        }
        for (WorldSpec.RobotSpec r : world.robots()) {
            String problem = r.control().isBlank()
                    ? "it has no control class (control=\"...\") to run in this JVM (--one-jvm)"
                    : RobotLaunches.controlClassProblem(r.control(), "this Environment runs with");
            if (problem != null) {
                throw new IllegalArgumentException(file + ": robot " + r.name() + ": " + problem);
            }
        }
        return starter;
    }

    /** Runs the Environment of {@code plan}, its lines to {@code lines} (any thread); returns its exit code. */
    public static int run(Plan plan, Consumer<String> lines) throws InterruptedException {
        Settings settings = plan.settings();
        EnvironmentHost host = new EnvironmentHost(plan.file(), plan.world(), settings, plan.keepRunning(),
                plan.startPaused());
        host.launchRobots(plan.launchRobots() ? new RobotLaunches() : null);
        ControlServer control = null;
        WebViewerServer web = null;
        try {
            host.open();
            if (plan.controlPort() >= 0) {
                control = new ControlServer(new EnvironmentCommands(host, plan.directories()), settings.keys(),
                        settings.handshakeTimeoutMs());
                control.start(settings.bind(), plan.controlPort());
            }
            if (plan.webPort() >= 0) {
                web = WebViewers.start(plan.webPort(), settings.bind(), host.ports()[1], settings.keys(),
                        new EnvironmentCommands(host, plan.directories()));
            }
        } catch (BindException e) {
            closeQuietly(host, control);
            System.err.println("environment: " + e.getMessage() + " (choose another with the --*-port options)");
            return 2;
        } catch (IOException e) {
            closeQuietly(host, control);
            System.err.println("environment: cannot listen on " + settings.bind().getHostAddress() + ": "
                    + e.getMessage());
            return 2;
        }
        Thread shutdown = new Thread(host::stopOnSignal, "shutdown");
        Runtime.getRuntime().addShutdownHook(shutdown);
        int[] ports = host.ports();
        lines.accept("listening robots=" + ports[0] + " viewers=" + ports[1] + " geometry=" + ports[2]
                + " control=" + (control == null ? -1 : control.port()) + (web == null ? "" : " web=" + web.port())
                + " tls=" + (settings.keys() != null && settings.keys().tls() != null ? "on" : "off"));
        announceStart(host.current(), lines);
        int code;
        try {
            code = host.run(s -> {
                for (Departure d : s.departures()) {
                    lines.accept("left robot=" + d.robot() + " step=" + StepNumbers.shown(d.step()) + " reason="
                            + d.why());
                }
                if (s.experimentFailed()) {
                    lines.accept("experiment-failed " + s.reason());
                }
                lines.accept(s.line());
            });
            InMemoryLink.Starter inMemory = settings.robotsInThisJvm();
            if (inMemory != null) { // (their finally blocks, as a robot process's; then what failed)
                InMemoryLink.ControlEnd end = inMemory.awaitControlCode(CONTROL_GRACE_MS);
                List<String> failed = end.failed();
                for (String f : failed) {
                    lines.accept("control-failed " + f);
                }
                for (String r : end.running()) {
                    lines.accept("control-running " + r);
                }
                for (String w : plan.world().parameters().warnings(end.asked())) {
                    LOG.warn(w);
                }
                if (!failed.isEmpty() && (code == 0 || code == EnvironmentHost.EXIT_ROBOTS_REMOVED)) {
                    code = EnvironmentHost.EXIT_CONTROL_FAILED; // (as headless.sh: a failed control code says more)
                }
            }
        } finally {
            if (control != null) {
                control.close();
            }
            if (web != null) {
                web.close();
            }
            host.stopLaunched();
            try {
                Runtime.getRuntime().removeShutdownHook(shutdown); // (run in a runner's JVM: one hook per run)
            } catch (IllegalStateException e) {
                // the JVM is shutting down (the hook is what ended the run)
            }
        }
        return code;
    }

    /**
     * Hands on {@code running robots=N} when every client of the first simulation is there, so a runner knows that a
     * client process which exits from then on has taken part (thread "start-announcer").
     */
    private static void announceStart(ClientWorkerCoordinator first, Consumer<String> lines) {
        Thread t = new Thread(() -> {
            try {
                if (first.awaitStart(Long.MAX_VALUE, TimeUnit.DAYS)) {
                    lines.accept("running robots=" + first.summary().robots());
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "start-announcer");
        t.setDaemon(true);
        t.start();
    }

    private static void closeQuietly(EnvironmentHost host, ControlServer control) {
        if (control != null) {
            control.close();
        }
        ClientWorkerCoordinator c = host.current();
        if (c != null) {
            c.close();
        }
    }
}

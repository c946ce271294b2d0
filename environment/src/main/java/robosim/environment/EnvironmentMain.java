package robosim.environment;

import java.io.IOException;
import java.net.BindException;
import java.net.InetAddress;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.ServiceLoader;
import java.util.function.Consumer;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import robosim.environment.config.EnvironmentFileException;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.control.ControlServer;
import robosim.environment.control.EnvironmentCommands;
import robosim.environment.control.WebViewers;
import robosim.environment.control.EnvironmentDirectories;
import robosim.environment.control.EnvironmentHost;
import robosim.environment.control.RobotLaunches;
import robosim.environment.core.WorldSpec;
import robosim.environment.net.ClientWorkerCoordinator;
import robosim.environment.net.CoordinatorDesign;
import robosim.environment.net.Departure;
import robosim.environment.net.Settings;
import robosim.protocol.InMemoryLink;
import robosim.protocol.ObjectConnection;
import robosim.protocol.Protocol;
import robosim.protocol.SimulationKeys;
import robosim.protocol.VirtualThreads;
import robosim.web.WebViewerServer;

/**
 * {@code scripts/environment.sh FILE.xml}: the Environment server. Prints one line
 * {@code listening robots=P viewers=P geometry=P control=P tls=on|off} when its ports are bound and, when the run ends,
 * {@code summary steps=... robots=... wall_s=... steps_per_s=... robot_steps_per_s=...} (with --one-jvm
 * followed by a {@code control-failed NAME: ...} line for each robot whose control code threw, and a
 * {@code control-running NAME} line for each whose control code was still running 2 s after the end). Exit codes: 0 done, 1 the run failed, 2 bad input (file, option, port), 3 it lost a robot, 4 (--one-jvm) a robot's control code threw out of run.
 */
@Command(name = "environment.sh", mixinStandardHelpOptions = true,
        description = "Loads an environment file, waits for every robot it names (and a Geometry process), "
                + "then runs the simulation in lock-step.")
public final class EnvironmentMain implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "FILE.xml", description = "The environment file.")
    Path file;

    @Option(names = "--robot-port", defaultValue = "" + Protocol.DEFAULT_ROBOT_PORT,
            description = "Port for Hardware Simulators (default: ${DEFAULT-VALUE}; 0 picks a free one).")
    int robotPort;

    @Option(names = "--viewer-port", defaultValue = "" + Protocol.DEFAULT_VIEWER_PORT,
            description = "Port for viewers (default: ${DEFAULT-VALUE}; 0 picks a free one).")
    int viewerPort;

    @Option(names = "--geometry-port", defaultValue = "" + Protocol.DEFAULT_GEOMETRY_PORT,
            description = "Port for the Geometry process (default: ${DEFAULT-VALUE}; 0 picks a free one).")
    int geometryPort;

    @Option(names = "--bind", defaultValue = "127.0.0.1",
            description = "Address to listen on (default: ${DEFAULT-VALUE}, loopback only).")
    String bind;

    @Option(names = "--no-geometry",
            description = "Do collision and sonar in-process instead of in a Geometry process.")
    boolean noGeometry;

    @Option(names = "--one-jvm", description = "Run every robot of the file (its control class) and collision and "
            + "sonar in this JVM, through in-memory links: no robot or Geometry process, no socket, the same results "
            + "(robots that join later still connect; see environment/README.md for when to pick it).")
    boolean oneJvm;

    @Option(names = "--steps", defaultValue = "0",
            description = "End after this many steps (default: ${DEFAULT-VALUE} = run until stopped).")
    long steps;

    @Option(names = "--param", paramLabel = "NAME=VALUE", description = "Give the file's parameter NAME (a "
            + "placeholder ${NAME:default} in it, or a <param name=\"NAME\"> of the world) this value; repeat for more. "
            + "A name the file does not have is refused (test-envs/README.md).")
    java.util.Map<String, String> params = new java.util.LinkedHashMap<>();

    @Option(names = "--seed", description = "The run's seed, in place of the file's seed attribute: sensor noise and "
            + "each robot's Robot.seed() come from it.")
    Long seed;

    @Option(names = "--speed",
            description = "Run at most this many times real time, so a person can watch; 0 = as fast as possible "
                    + "(default: 1, real time, without --steps, a session driven by hand; 0 with --steps).")
    Double speed;

    @Option(names = "--coordinator", defaultValue = "THREADS",
            description = "The coordinator design: THREADS (the report's design and the default: a reading thread "
                    + "per robot, the simulation loop writes every response), SEQUENTIAL (the original's loop: one "
                    + "thread reads every robot in turn) or TWO_THREADS (a reading and a writing thread per robot). "
                    + "Measured against each other in docs/PERFORMANCE.md.")
    CoordinatorDesign design;

    @Option(names = "--step-timeout-ms", defaultValue = ""
            + Settings.DEFAULT_STEP_TIMEOUT_MS,
            description = "Drop a robot that sends no request this long after its step was released "
                    + "(default: ${DEFAULT-VALUE}; 0 = wait for ever).")
    long stepTimeoutMs;

    @Option(names = "--geometry-timeout-ms", defaultValue = ""
            + Settings.DEFAULT_GEOMETRY_TIMEOUT_MS,
            description = "Count the Geometry process as lost if one step's round trip takes longer "
                    + "(default: ${DEFAULT-VALUE}; 0 = wait for ever).")
    long geometryTimeoutMs;

    @Option(names = "--write-timeout-ms", defaultValue = "" + Settings.DEFAULT_WRITE_TIMEOUT_MS,
            description = "Drop a robot or viewer that does not take one write within this time, so no client "
                    + "that stops reading holds the run (default: ${DEFAULT-VALUE}; 0 = never).")
    long writeTimeoutMs;

    @CommandLine.Mixin
    ClientOptions clients;

    @Option(names = "--control-port", defaultValue = "" + Protocol.DEFAULT_CONTROL_PORT,
            description = "The control port for the Control Panel (default: ${DEFAULT-VALUE}; 0 = any free port; "
                    + "-1 = none).")
    int controlPort;

    @Option(names = "--start-paused", description = "Once every client is there, wait for start (or step N) "
            + "from the control port.")
    boolean startPaused;

    @Option(names = "--keep-running", negatable = true, description = "After a simulation ends, wait on the "
            + "control port for start, load or shutdown (default: on without --steps, off with --steps).")
    Boolean keepRunning;

    @Option(names = "--no-step-messages",
            description = "Send robots the step number only before step 0; they count on (the report's untested "
                    + "idea; default: a step number after every response).")
    boolean noStepMessages;

    @Option(names = "--record", paramLabel = "FILE", description = "Record the run into FILE (a new file; a later "
            + "simulation of this Environment into FILE-2, FILE-3...): see scripts/record-tool.sh.")
    Path record;

    @Option(names = "--reset-every", defaultValue = "" + ObjectConnection.DEFAULT_RESET_EVERY,
            description = "Messages between object-stream resets (default: ${DEFAULT-VALUE}).")
    int resetEvery;

    @Option(names = "--handshake-timeout-ms", defaultValue = "10000",
            description = "Drop a client whose hello is not accepted within this time from its connection, "
                    + "however slowly it sends (default: ${DEFAULT-VALUE}).")
    int handshakeTimeoutMs;

    @Option(names = "--env-dir", paramLabel = "DIR",
            description = "A directory whose environment files the control port's load may read; repeat for "
                    + "more (default: the directory of FILE.xml). Nothing outside them is read.")
    java.util.List<Path> envDirs;

    @Option(names = "--web-port", defaultValue = "-1", description = "Serve the browser viewer on this port, on "
            + "--bind; with ROBOSIM_KEYS over TLS to browsers holding the key pair (default: none; 0: a free one).")
    int webPort;

    @Option(names = "--max-connections", defaultValue = "" + Settings.DEFAULT_MAX_CONNECTIONS,
            description = "Connections each port holds at once beyond the robots the file names or lets join "
                    + "(<join max>); one more is closed at once (default: ${DEFAULT-VALUE}).")
    int maxConnections;

    @Override
    public Integer call() throws Exception {
        WorldSpec spec;
        try {
            spec = new EnvironmentLoader().load(file, params);
            spec = seed == null ? spec : spec.withSeed(seed);
        } catch (EnvironmentFileException e) {
            System.err.println(e.getMessage());
            return 2;
        }
        double pace = effectiveSpeed(speed, steps);
        if (steps < 0 || resetEvery < 0 || handshakeTimeoutMs < 0 || !(pace >= 0) || Double.isInfinite(pace)
                || stepTimeoutMs < 0 || geometryTimeoutMs < 0 || writeTimeoutMs < 0) {
            System.err.println("environment: --steps, --speed, --reset-every and the --*-timeout-ms options must be >= 0");
            return 2;
        }
        if (maxConnections < 1) {
            System.err.println("environment: --max-connections must be >= 1, got " + maxConnections);
            return 2;
        }
        InMemoryLink.Starter inMemory = null;
        if (oneJvm && System.getProperty(VirtualThreads.PARALLELISM) == null) {
            // every robot's control code and the loop on one carrier: a step passes between them without a wake of
            // the operating system's (the loop's thread: net.LoopThread); read once, as the first virtual thread
            // starts, so a JVM that has run virtual threads already keeps what it has
            System.setProperty(VirtualThreads.PARALLELISM, "1");
        }
        if (oneJvm) {
            inMemory = ServiceLoader.load(InMemoryLink.Starter.class).findFirst().orElse(null);
            String problem = inMemory == null
                    ? "environment: --one-jvm needs the Hardware Simulator (robosim hardware-sim) on the class path"
                    : oneJvmProblem(spec);
            if (problem != null) {
                System.err.println(problem);
                return 2;
            }
        }
        InetAddress bindAddress = InetAddress.getByName(bind);
        SimulationKeys keys;
        try {
            keys = SimulationKeys.fromEnvironment();
            WebViewers.check(webPort, keys);
        } catch (IOException e) {
            System.err.println("environment: " + e.getMessage());
            return 2;
        }
        if (handshakeTimeoutMs == 0 && !bindAddress.isLoopbackAddress()) {
            System.err.println("environment: --bind " + bind + " needs a handshake deadline: --handshake-timeout-ms 0 "
                    + "would let a stranger hold a connection for ever");
            return 2;
        }
        if ((keys == null || keys.tls() == null) && !bindAddress.isLoopbackAddress()) {
            System.err.println("environment: --bind " + bind + " opens every port beyond this machine: set ROBOSIM_KEYS "
                    + "to a directory made by scripts/make-keys.sh (TLS and the shared secret) for every process");
            return 2;
        }
        if (record != null && (Files.exists(record) || record.toAbsolutePath().getParent() == null
                || !Files.isDirectory(record.toAbsolutePath().getParent()))) {
            System.err.println("environment: --record " + record + ": " + (Files.exists(record)
                    ? "already exists (not overwritten)" : "its directory does not exist"));
            return 2;
        }
        Settings settings;
        try {
            settings = Settings.builder().record(record).ports(bindAddress, robotPort, viewerPort, geometryPort)
                    .keys(keys).maxConnections(maxConnections).handshakeTimeoutMs(handshakeTimeoutMs)
                    .stepTimeoutMs(stepTimeoutMs).geometryTimeoutMs(geometryTimeoutMs).writeTimeoutMs(writeTimeoutMs)
                    .design(design).inProcessGeometry(noGeometry || oneJvm).onGeometryLoss(clients.onGeometryLoss)
                    .onRobotLoss(clients.onRobotLoss).maxSteps(steps).speed(pace).stepMessages(!noStepMessages)
                    .resetEvery(resetEvery).robotsInThisJvm(inMemory).build();
        } catch (IllegalArgumentException e) { // (what the coordinator design does not allow)
            System.err.println("environment: " + e.getMessage());
            return 2;
        }
        EnvironmentDirectories directories;
        try {
            directories = envDirs == null ? EnvironmentDirectories.of(file) : new EnvironmentDirectories(envDirs);
        } catch (IOException e) {
            System.err.println("environment: " + e.getMessage());
            return 2;
        }
        boolean stay = keepRunning != null ? keepRunning : steps == 0;
        EnvironmentHost host = new EnvironmentHost(file, spec, settings, stay, startPaused);
        host.launchRobots(clients.launchRobots ? new robosim.environment.control.RobotLaunches() : null);
        ControlServer control = null;
        WebViewerServer web = null;
        try {
            host.open();
            if (controlPort >= 0) {
                control = new ControlServer(new EnvironmentCommands(host, directories), keys, handshakeTimeoutMs);
                control.start(bindAddress, controlPort);
            }
            if (webPort >= 0) {
                web = WebViewers.start(webPort, bindAddress, host.ports()[1], keys, new EnvironmentCommands(host, directories));
            }
        } catch (BindException e) {
            closeQuietly(host, control);
            System.err.println("environment: " + e.getMessage() + " (choose another with the --*-port options)");
            return 2;
        } catch (IOException e) {
            closeQuietly(host, control);
            System.err.println("environment: cannot listen on " + bind + ": " + e.getMessage());
            return 2;
        }
        Thread shutdown = new Thread(host::stopOnSignal, "shutdown");
        Runtime.getRuntime().addShutdownHook(shutdown);
        int[] ports = host.ports();
        lines.accept("listening robots=" + ports[0] + " viewers=" + ports[1] + " geometry=" + ports[2]
                + " control=" + (control == null ? -1 : control.port()) + (web == null ? "" : " web=" + web.port())
                + " tls=" + (keys != null && keys.tls() != null ? "on" : "off"));
        announceStart(host.current(), lines);
        int code;
        try {
            code = host.run(s -> {
                for (Departure d : s.departures()) {
                    lines.accept("left robot=" + d.robot() + " step=" + robosim.protocol.StepNumbers.shown(d.step())
                            + " reason=" + d.why());
                }
                lines.accept(s.line());
            });
            if (inMemory != null) { // (their finally blocks, as a robot process's; then what failed)
                InMemoryLink.ControlEnd end = inMemory.awaitControlCode(CONTROL_GRACE_MS);
                List<String> failed = end.failed();
                for (String f : failed) {
                    lines.accept("control-failed " + f);
                }
                for (String r : end.running()) {
                    lines.accept("control-running " + r);
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

    /** How long the control code of robots in this JVM gets to end after the run, ms (a robot process's grace). */
    private static final long CONTROL_GRACE_MS = 2000;

    /** Why a robot of the file cannot run in this JVM (it has no control class this JVM finds), or null. */
    private String oneJvmProblem(WorldSpec spec) {
        for (WorldSpec.RobotSpec r : spec.robots()) {
            String problem = r.control().isBlank()
                    ? "it has no control class (control=\"...\") to run in this JVM (--one-jvm)"
                    : RobotLaunches.controlClassProblem(r.control(), "this Environment runs with");
            if (problem != null) {
                return file + ": robot " + r.name() + ": " + problem;
            }
        }
        return null;
    }

    /**
     * Prints {@code running robots=N} when every client of the first simulation is there, so a runner
     * knows that a client process which exits from then on has taken part (thread "start-announcer").
     */
    private static void announceStart(ClientWorkerCoordinator first, Consumer<String> lines) {
        Thread t = new Thread(() -> {
            try {
                if (first.awaitStart(Long.MAX_VALUE, java.util.concurrent.TimeUnit.DAYS)) {
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

    /**
     * The pace of the run: {@code --speed} when given; otherwise real time (1) for a session without
     * {@code --steps} (robots driven by hand wait for people, so running flat out would only burn the
     * CPU), and as fast as possible (0) for a run of a set number of steps.
     */
    static double effectiveSpeed(Double speed, long steps) {
        if (speed != null) {
            return speed;
        }
        return steps == 0 ? 1 : 0;
    }

    /** Where its lines go (listening, running, left, summary): stdout, or a runner in the same JVM. */
    private Consumer<String> lines = line -> {
        System.out.println(line);
        System.out.flush();
    };

    /**
     * Runs the Environment in this JVM with {@code args} as {@code environment.sh} takes them, handing each line
     * it prints ({@code listening ...}, {@code running ...}, {@code left ...}, {@code summary ...}) to
     * {@code lines} instead (any thread); errors still go to stderr. Returns its exit code.
     */
    public static int run(String[] args, Consumer<String> lines) {
        EnvironmentMain m = new EnvironmentMain();
        m.lines = lines;
        return commandLine(m).execute(args);
    }

    private static CommandLine commandLine(EnvironmentMain m) {
        CommandLine cl = new CommandLine(m);
        cl.setParameterExceptionHandler((ex, a) -> {
            System.err.println("environment: " + ex.getMessage() + " (see --help)");
            return 2;
        });
        return cl;
    }

    public static void main(String[] args) {
        System.exit(commandLine(new EnvironmentMain()).execute(args));
    }
}

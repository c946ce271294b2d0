package robosim.runner;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeoutException;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import robosim.api.RobotControl;
import robosim.control.ControlClient;
import robosim.environment.EnvironmentServer;
import robosim.environment.RunOptions;
import robosim.environment.config.EnvironmentFileException;
import robosim.environment.control.EnvironmentDirectories;
import robosim.environment.core.WorldSpec;
import robosim.environment.run.Settings;
import robosim.environment.run.Transport;
import robosim.environment.server.WebPortOption;
import robosim.hardware.ConnectionOption;
import robosim.hardware.ExchangeOption;
import robosim.protocol.CommandLines;
import robosim.protocol.ResetOption;
import robosim.protocol.SimulationKeys;

/**
 * {@code scripts/headless.sh --env FILE --steps N}: runs a whole simulation with every part as its
 * own OS process and prints, as its last line,
 * {@code steps=N robots=R wall_s=... steps_per_s=... robot_steps_per_s=...}.
 */
@Command(name = "headless.sh", mixinStandardHelpOptions = true,
        description = "Starts the Environment, the Geometry process and every robot named in the environment file "
                + "as separate processes, runs the given number of steps, stops them all and prints a summary.")
public final class HeadlessRunner implements Callable<Integer> {
    /** The exit code of a run that completed without some of its robots (each is named before the summary). */
    static final int EXIT_ROBOTS_REMOVED = robosim.environment.control.EnvironmentHost.EXIT_ROBOTS_REMOVED;
    /** The exit code of a run in which a robot's control code threw out of {@code run} (each is named before the summary). */
    static final int EXIT_CONTROL_FAILED = robosim.environment.control.EnvironmentHost.EXIT_CONTROL_FAILED;

    @Mixin
    EnvOption env;

    @Option(names = "--steps", defaultValue = "1000", description = "Steps to run (default: ${DEFAULT-VALUE}).")
    long steps;

    @Mixin
    RunOptions run;

    @Option(names = "--ports", paramLabel = "ROBOT,VIEWER,GEOMETRY", split = ",",
            description = "Environment ports (default: free ports picked by the system).")
    List<Integer> ports;

    @Mixin
    WebPortOption web;

    @Option(names = "--robots-in-one-process",
            description = "Run every robot in one JVM, over one shared connection (see --connection).")
    boolean robotsInOneProcess;

    @Mixin
    ConnectionOption connection;

    @Mixin
    ExchangeOption exchange;

    @Mixin
    ResetOption reset;

    @Option(names = "--pose-log", paramLabel = "FILE.csv",
            description = "Write every robot's pose after every step: step,robot,x_m,y_m,heading_deg,state (running, held or gone).")
    Path poseLog;

    @Mixin
    WatchOptions watching;

    @Option(names = "--viewer", description = "Open a Viewer2D window (needs a display); it stays open after the run.")
    boolean viewer;

    @Mixin
    ExtraViewerOptions extraViewers;

    @Mixin
    ChildJvmOptions jvm;

    /** One JVM: the robots whose control code was still running after the end (a warm JVM must not go on). */
    private final List<String> controlStillRunning = new CopyOnWriteArrayList<>();

    @Override
    public Integer call() throws Exception {
        WorldSpec spec;
        try {
            spec = run.world(env.file());
        } catch (EnvironmentFileException e) {
            System.err.println(e.getMessage());
            return 2;
        }
        String bad = badOptions();
        if (bad == null) {
            bad = missingControl(env.file(), spec);
        }
        if (bad != null) {
            System.err.println(bad);
            return 2;
        }
        try (ChildProcesses children = new ChildProcesses(jvm.all)) {
            return run(spec, children);
        }
    }

    private String badOptions() {
        if (steps <= 0) {
            return "headless: --steps must be > 0, got " + steps;
        }
        if (run.oneJvm() && !jvm.all.isEmpty()) {
            return "headless: --one-jvm runs the Environment in this JVM: give its JVM options in ROBOSIM_JAVA_OPTS, "
                    + "not --jvm-opt";
        }
        if (run.oneJvm() && (robotsInOneProcess || connection.given() != null || exchange.given() != null)) {
            return "headless: --one-jvm starts no robot process: --robots-in-one-process, --connection and --exchange "
                    + "do not apply";
        }
        if (extraViewers.negative()) {
            return "headless: --live-viewers and --frozen-viewers must be >= 0";
        }
        if (ports != null && ports.size() != 3) {
            return "headless: --ports needs three ports ROBOT,VIEWER,GEOMETRY, got " + ports;
        }
        String bad = run.problem(steps);
        if (bad == null) {
            bad = web.problem(null);
        }
        return bad == null ? null : "headless: " + bad;
    }

    /**
     * Every robot of {@code spec} (of environment file {@code env}) needs a control class on the class path the robot
     * processes get (ours), or a script there that compiles and an interpreter that can run it, and the world's loop
     * functions their class or script: what is wrong, or null.
     */
    public static String missingControl(java.nio.file.Path env, WorldSpec spec) throws InterruptedException {
        java.util.Set<java.nio.file.Path> scripts = new java.util.LinkedHashSet<>();
        if (spec.loopFunctions() != null && spec.loopFunctions().given() == null) {
            String problem = robosim.environment.core.LoopSpec.problem(spec.loopFunctions().className());
            if (problem != null) {
                return env + ": <loopFunctions>: " + problem;
            }
            if (robosim.protocol.ControlScripts.isScript(spec.loopFunctions().className())) {
                scripts.add(robosim.protocol.ControlScripts.script(spec.loopFunctions().className()));
            }
        }
        for (WorldSpec.RobotSpec r : spec.robots()) {
            String where = env + ": <robot name=\"" + r.name() + "\">";
            if (r.control().isBlank()) {
                return where + " needs a control class (control=\"...\") for the headless runner";
            }
            if (robosim.protocol.ControlScripts.isRos2(r.control())) {
                return where + ": " + robosim.protocol.ControlScripts.ros2Elsewhere();
            }
            if (robosim.protocol.ControlScripts.isScript(r.control())) {
                String problem = robosim.protocol.ControlScripts.problem(r.control());
                if (problem != null) {
                    return where + ": " + problem;
                }
                scripts.add(robosim.protocol.ControlScripts.script(r.control()));
                continue;
            }
            try {
                Class<?> c = Class.forName(r.control(), false, robosim.protocol.ControlClasses.loader());
                if (!RobotControl.class.isAssignableFrom(c)) {
                    return where + ": " + r.control() + " does not implement " + RobotControl.class.getName();
                }
            } catch (ClassNotFoundException | LinkageError e) {
                return where + ": control class " + r.control() + " is not on the class path (add its classes "
                        + "with --classpath or ROBOSIM_CLASSPATH)";
            }
        }
        return scripts.isEmpty() ? null : robosim.protocol.ControlScripts.scriptsProblem(scripts);
    }

    private int run(WorldSpec spec, ChildProcesses children) throws Exception {
        CompletableFuture<Map<String, String>> listening = new CompletableFuture<>();
        CompletableFuture<Map<String, String>> summary = new CompletableFuture<>();
        CompletableFuture<Void> started = new CompletableFuture<>();
        List<String> removed = new CopyOnWriteArrayList<>();
        List<String> controlFailed = new CopyOnWriteArrayList<>(); // (one JVM: the Environment's lines)
        // one JVM: its robots are there at once, so when the watch must see step 0 (the pose log's, the progress's
        // viewer) it holds before step 0 until the watch has its snapshot; otherwise (a sweep's runs) it starts at once
        boolean holdForViewers = poseLog != null || watching.progress();
        EnvironmentServer.Plan plan = null;
        if (run.oneJvm()) {
            try {
                plan = planInThisJvm(spec, holdForViewers);
            } catch (IllegalArgumentException | IOException e) {
                System.err.println("environment: " + e.getMessage());
                return 2;
            }
        }
        java.util.function.Consumer<String> lines = line -> {
            if (line.startsWith("listening ")) {
                listening.complete(fields(line));
            } else if (line.startsWith("running ")) {
                started.complete(null);
            } else if (line.startsWith("left ")) {
                removed.add(line.substring("left ".length()));
            } else if (line.startsWith("control-failed ")) { // (NAME: what it threw)
                String f = line.substring("control-failed ".length());
                int colon = Math.max(0, f.indexOf(": "));
                controlFailed.add("robot " + f.substring(0, colon) + ": its control code failed"
                        + f.substring(colon));
            } else if (line.startsWith("control-running ")) {
                String name = line.substring("control-running ".length());
                controlStillRunning.add(name);
                System.out.println("robot " + name + ": its control code was still running after the run's end");
            } else if (line.startsWith("experiment-failed ")) { // (the loop functions' line)
                System.err.println(line.substring("experiment-failed ".length()));
            } else if (line.startsWith("summary ")) {
                summary.complete(fields(line));
            } else {
                System.out.println(line);
            }
        };
        // one JVM: the Environment (and with it every robot) runs in this one, so a run starts one JVM
        Process environment = plan != null ? InJvmEnvironment.start(plan, lines, jvm.profile)
                : children.start("environment", jvm.environment(), "robosim.environment.EnvironmentMain",
                        environmentArgs(), lines);
        environment.onExit().thenRun(() -> listening.complete(Map.of()));
        Map<String, String> bound = listening.get(60, TimeUnit.SECONDS);
        if (bound.isEmpty()) {
            System.err.println("headless: the Environment exited with code " + environment.waitFor()
                    + " before listening");
            return environment.exitValue() == 2 ? 2 : 1;
        }
        System.out.println("listening robots=" + bound.get("robots") + " viewers=" + bound.get("viewers")
                + " geometry=" + bound.get("geometry") + " control=" + bound.get("control")
                + (bound.containsKey("web") ? " web=" + bound.get("web") : "") + " tls=" + bound.get("tls"));
        int viewerPort = Integer.parseInt(bound.get("viewers"));
        RunWatch watch = RunWatch.connect("127.0.0.1", viewerPort, poseLog, watching.progress(), steps, 10_000);
        ExtraViewers extras = extraViewers.connect(viewerPort);
        if (this.viewer) {
            // this Environment exits after its one run: the window keeps the last picture and stops
            // waiting for a next run on the same port soon after
            children.startDetached("viewer2d", "robosim.viewer.Viewer2DMain",
                    List.of("127.0.0.1", Integer.toString(viewerPort), "--next-run-wait-s", "5"));
        }
        List<ChildProcesses.Child> clients = new ArrayList<>();
        if (!run.inProcessGeometry()) {
            List<String> geometryArgs = new ArrayList<>(List.of("127.0.0.1", bound.get("geometry")));
            geometryArgs.addAll(resetArgs());
            clients.add(children.startChild("geometry", jvm.geometry(),
                    "robosim.geometry.GeometryMain", geometryArgs, null));
        }
        if (run.oneJvm() && holdForViewers) {
            // the robots are here already: the run starts once the watch is one of its viewers (its snapshot came)
            if (watch != null && !watch.awaitSnapshot(60)) {
                System.err.println("headless: the Environment sent the pose log's viewer no snapshot within 60 s");
                return 1;
            }
            try (ControlClient control = new ControlClient("127.0.0.1", Integer.parseInt(bound.get("control")),
                    SimulationKeys.fromEnvironment(), 60_000)) {
                com.fasterxml.jackson.databind.JsonNode answer = control.request("resume");
                if (!answer.path("ok").asBoolean()) {
                    System.err.println("headless: the Environment did not start: " + answer.path("error").asText());
                    return 1;
                }
            }
        } else if (!run.oneJvm()) {
            clients.addAll(startRobots(spec, children, bound.get("robots")));
        }
        String early = EarlyExit.await(started, environment, clients);
        if (early != null) {
            System.err.println("headless: " + early + "; stopping everything");
            return 2;
        }
        if (started.isDone()) {
            String choice = System.getenv("ROBOSIM_JAVA_CHOICE");
            System.out.println("running " + spec.robots().size() + " robots for " + steps + " steps on Java "
                    + Runtime.version().feature() + (choice == null ? "" : " from " + choice));
        }
        long limit = watching.timeoutS() > 0 ? watching.timeoutS() : Long.MAX_VALUE / 2;
        if (!environment.waitFor(limit, TimeUnit.SECONDS)) {
            System.err.println("headless: no end after " + watching.timeoutS() + " s; stopping everything");
            return 1;
        }
        int code = environment.exitValue();
        Map<String, String> s;
        try {
            s = summary.get(10, TimeUnit.SECONDS);
        } catch (TimeoutException e) {
            System.err.println("headless: the Environment exited with code " + code + " without a summary");
            return 1;
        }
        if (watch != null) {
            watch.awaitEnd(60);
            watch.close();
        }
        extras.close();
        List<String> failed = new ArrayList<>(children.awaitAll(30));
        failed.removeIf(f -> f.endsWith("(exit " + ChildProcesses.EXIT_CONTROL_FAILED + ")"));
        controlFailed.addAll(children.controlFailures());
        if (children.stoppedBySignal()) { // (asked to stop: the processes' exits are the stop's, no failure)
            System.err.println("headless: stopped (a signal: SIGTERM, SIGINT or SIGHUP); every process it started was "
                    + "stopped");
        } else if (!failed.isEmpty()) {
            System.err.println("headless: processes that did not end cleanly: " + failed);
            code = code == 0 ? 1 : code;
        }
        for (String r : removed) {
            System.out.println("removed " + r);
        }
        for (String f : controlFailed) {
            System.out.println(f);
        }
        if (!removed.isEmpty() && code == 0) {
            code = EXIT_ROBOTS_REMOVED;
        }
        if (!controlFailed.isEmpty() && (code == 0 || code == EXIT_ROBOTS_REMOVED)) {
            code = EXIT_CONTROL_FAILED;
        }
        System.out.println(String.format(Locale.ROOT,
                "steps=%s robots=%s wall_s=%s steps_per_s=%s robot_steps_per_s=%s messages=%s robots_removed=%s "
                        + "control_failed=%d geometry=%s robots_in=%s",
                s.get("steps"), s.get("robots"), s.get("wall_s"), s.get("steps_per_s"), s.get("robot_steps_per_s"),
                s.get("messages"), s.get("robots_removed"), controlFailed.size(),
                run.inProcessGeometry() ? "in-process" : "process",
                run.oneJvm() ? "one-jvm" : robotsInOneProcess ? "one-process"
                        + (connectionKind() == ConnectionOption.Connection.SHARED ? "" : "-per-robot") : "processes"));
        return code;
    }

    /** How robots in one process connect: as {@code --connection} says, else shared unless that cannot be. */
    private ConnectionOption.Connection connectionKind() {
        boolean perRobot = exchange.given() != null || run.design().refuses(Transport.SHARED) != null;
        return connection.given() != null ? connection.given()
                : perRobot ? ConnectionOption.Connection.PER_ROBOT : ConnectionOption.Connection.SHARED;
    }

    private List<String> exchangeArgs() {
        return exchange.given() == null ? List.of() : List.of("--exchange", exchange.given().name());
    }

    /**
     * The Environment's command line for a process of its own: the file, the steps, the ports (free ones unless
     * {@code --ports}), a free control port, robots it may start for the control port's add, the stream resets,
     * and the run's options as they were given.
     */
    private List<String> environmentArgs() {
        List<String> args = new ArrayList<>(List.of(env.file().toString(), "--steps", Long.toString(steps),
                "--robot-port", port(0), "--viewer-port", port(1), "--geometry-port", port(2), "--control-port", "0",
                "--launch-robots", "--web-port", Integer.toString(web.port())));
        args.addAll(resetArgs());
        args.addAll(run.given());
        return args;
    }

    private String port(int i) {
        return ports == null ? "0" : Integer.toString(ports.get(i));
    }

    /**
     * The Environment in this JVM, every robot in it: the world {@code spec} as the run's options say, on loopback
     * (free ports unless {@code --ports}), a free control port, held before step 1 if {@code startPaused}.
     */
    private EnvironmentServer.Plan planInThisJvm(WorldSpec spec, boolean startPaused) throws IOException {
        java.net.InetAddress loopback = java.net.InetAddress.getLoopbackAddress();
        SimulationKeys keys = SimulationKeys.fromEnvironment();
        if (web.problem(keys) != null) {
            throw new IllegalArgumentException(web.problem(keys));
        }
        Settings settings = run.applyTo(Settings.builder(), steps)
                .ports(loopback, Integer.parseInt(port(0)), Integer.parseInt(port(1)), Integer.parseInt(port(2)))
                .keys(keys).resetEvery(reset.messages())
                .robotsInThisJvm(EnvironmentServer.robotsInThisJvm(env.file(), spec)).build();
        return new EnvironmentServer.Plan(env.file(), spec, settings, 0, web.port(),
                EnvironmentDirectories.of(env.file()), false, startPaused, true);
    }

    private List<ChildProcesses.Child> startRobots(WorldSpec spec, ChildProcesses children, String robotPort)
            throws IOException {
        if (robotsInOneProcess) {
            List<String> args = new ArrayList<>(List.of("127.0.0.1", robotPort));
            args.addAll(resetArgs());
            args.addAll(exchangeArgs());
            args.addAll(List.of("--connection", connectionKind().name()));
            for (WorldSpec.RobotSpec r : spec.robots()) {
                args.add("--robot");
                args.add(r.name() + ":" + r.type() + ":" + r.control());
            }
            return List.of(children.startChild("robots", jvm.robot(), "robosim.hardware.MultiRobotMain", args,
                    null));
        }
        List<ChildProcesses.Child> started = new ArrayList<>();
        for (WorldSpec.RobotSpec r : spec.robots()) {
            List<String> args = new ArrayList<>(List.of(r.control(), r.name(), "127.0.0.1", robotPort, "--type",
                    r.type()));
            args.addAll(resetArgs());
            args.addAll(exchangeArgs());
            started.add(children.startChild("robot " + r.name(), jvm.robot(), "robosim.hardware.RobotMain",
                    args, null));
        }
        return started;
    }

    private List<String> resetArgs() {
        return List.of("--reset-every", Integer.toString(reset.messages()));
    }

    static Map<String, String> fields(String line) {
        Map<String, String> m = new HashMap<>();
        for (String part : line.trim().split("\\s+")) {
            int eq = part.indexOf('=');
            if (eq > 0) {
                m.put(part.substring(0, eq), part.substring(eq + 1));
            }
        }
        return m;
    }

    /** After a one-JVM run: the robots whose control code was still running after its end (none: it ended). */
    List<String> controlStillRunning() {
        return List.copyOf(controlStillRunning);
    }

    public static void main(String[] args) {
        System.exit(commandLine(new HeadlessRunner()).execute(args));
    }

    /** headless.sh's command line for {@code runner}: a bad option is one line. */
    static CommandLine commandLine(HeadlessRunner runner) {
        CommandLine cl = CommandLines.of("headless", runner);
        cl.setOverwrittenOptionsAllowed(true); // demo.sh's defaults, then the user's: the last one wins
        return cl;
    }
}

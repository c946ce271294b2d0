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
import java.util.concurrent.TimeoutException;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import robosim.environment.config.EnvironmentFileException;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.core.WorldSpec;
import robosim.protocol.PoseUpdate;
import robosim.protocol.SimulationEnd;
import robosim.protocol.ViewerClient;
import robosim.protocol.WorldSnapshot;

/**
 * {@code scripts/headless.sh --env FILE --steps N}: runs a whole simulation with every part as its
 * own OS process and prints, as its last line,
 * {@code steps=N robots=R wall_s=... steps_per_s=... robot_steps_per_s=...}.
 */
@Command(name = "headless.sh", mixinStandardHelpOptions = true,
        description = "Starts the Environment, the Geometry process and every robot named in the environment file "
                + "as separate processes, runs the given number of steps, stops them all and prints a summary.")
public final class HeadlessRunner implements Callable<Integer> {
    @Option(names = "--env", required = true, paramLabel = "FILE", description = "The environment file.")
    Path env;

    @Option(names = "--steps", defaultValue = "1000", description = "Steps to run (default: ${DEFAULT-VALUE}).")
    long steps;

    @Option(names = "--ports", paramLabel = "ROBOT,VIEWER,GEOMETRY", split = ",",
            description = "Environment ports (default: free ports picked by the system).")
    List<Integer> ports;

    @Option(names = "--robots-in-one-process",
            description = "Run every robot in one JVM, each with its own socket and threads.")
    boolean robotsInOneProcess;

    @Option(names = "--no-geometry", description = "Do collision and sonar inside the Environment.")
    boolean noGeometry;

    @Option(names = "--pose-log", paramLabel = "FILE.csv",
            description = "Write every robot's pose after every step: step,robot,x_m,y_m,heading_deg.")
    Path poseLog;

    @Option(names = "--progress", description = "Print the step and steps/s once a second.")
    boolean progress;

    @Option(names = "--coordinator", paramLabel = "DESIGN", defaultValue = "SEQUENTIAL",
            description = "The Environment's coordinator design: SEQUENTIAL (default), THREADS or TWO_THREADS.")
    String coordinator;

    @Option(names = "--exchange", paramLabel = "THREADING",
            description = "The robots' exchange threading: ONE_THREAD, SEND_RECEIVE, or, with "
                    + "--robots-in-one-process, SHARED (one thread for every robot; the default there).")
    String exchange;

    @Option(names = "--no-step-messages",
            description = "The Environment sends the step number only before step 0 (see environment.sh --help).")
    boolean noStepMessages;

    @Option(names = "--reset-every", paramLabel = "N",
            description = "Messages between object-stream resets, for every process (default: each process's own, "
                    + "256; 0 = never, for measurement only).")
    Integer resetEvery;

    @Option(names = "--speed", defaultValue = "0",
            description = "Run at most this many times real time (default: ${DEFAULT-VALUE} = as fast as possible).")
    double speed;

    @Option(names = "--viewer", description = "Open a Viewer2D window (needs a display); it stays open after the run.")
    boolean viewer;

    @Option(names = "--live-viewers", defaultValue = "0",
            description = "For measurement: connect this many headless live viewers (default: ${DEFAULT-VALUE}).")
    int liveViewers;

    @Option(names = "--live-viewer-fps", defaultValue = "30",
            description = "Updates a second the --live-viewers ask for, like a Viewer2D window (default: "
                    + "${DEFAULT-VALUE}; 0 = every step).")
    int liveViewerFps;

    @Option(names = "--frozen-viewers", defaultValue = "0",
            description = "For measurement: connect this many viewers that never read (default: ${DEFAULT-VALUE}).")
    int frozenViewers;

    @Option(names = "--jvm-opt", paramLabel = "OPTION",
            description = "An option for every child JVM, after the per-role ones; repeatable.")
    List<String> jvmOptions = new ArrayList<>();

    @Option(names = "--environment-jvm-opts", paramLabel = "OPTIONS", defaultValue = "-XX:+UseSerialGC",
            description = "JVM options for the Environment, space-separated (default: ${DEFAULT-VALUE}).")
    String environmentJvmOpts;

    @Option(names = "--geometry-jvm-opts", paramLabel = "OPTIONS", defaultValue = "-XX:+UseSerialGC",
            description = "JVM options for the Geometry process (default: ${DEFAULT-VALUE}).")
    String geometryJvmOpts;

    @Option(names = "--robot-jvm-opts", paramLabel = "OPTIONS",
            defaultValue = "-XX:+UseSerialGC -XX:TieredStopAtLevel=1",
            description = "JVM options for each robot process (default: ${DEFAULT-VALUE}: ten JVMs warming up "
                    + "with C1 only cost less CPU on a small machine; give '' for heavy control code).")
    String robotJvmOpts;

    @Option(names = "--profile", paramLabel = "DIR",
            description = "Record a Java Flight Recorder profile of the Environment and the Geometry process into "
                    + "DIR (environment.jfr, geometry.jfr); read them with 'jfr print' or JDK Mission Control.")
    Path profile;

    @Option(names = "--timeout-s", defaultValue = "0",
            description = "Give up after this long (default: ${DEFAULT-VALUE} = no limit).")
    long timeoutS;

    @Override
    public Integer call() throws Exception {
        WorldSpec spec;
        try {
            spec = new EnvironmentLoader().load(env);
        } catch (EnvironmentFileException e) {
            System.err.println(e.getMessage());
            return 2;
        }
        if (steps <= 0) {
            System.err.println("headless: --steps must be > 0, got " + steps);
            return 2;
        }
        if (liveViewers < 0 || frozenViewers < 0 || liveViewerFps < 0 || !(speed >= 0)) {
            System.err.println("headless: --speed, --live-viewers and --frozen-viewers must be >= 0");
            return 2;
        }
        if (ports != null && ports.size() != 3) {
            System.err.println("headless: --ports needs three ports ROBOT,VIEWER,GEOMETRY, got " + ports);
            return 2;
        }
        for (WorldSpec.RobotSpec r : spec.robots()) {
            if (r.control().isBlank()) {
                System.err.println(env + ": <robot name=\"" + r.name() + "\"> needs a control class (control=\"...\") "
                        + "for the headless runner");
                return 2;
            }
        }
        try (ChildProcesses children = new ChildProcesses(jvmOptions)) {
            return run(spec, children);
        }
    }

    private int run(WorldSpec spec, ChildProcesses children) throws Exception {
        CompletableFuture<Map<String, String>> listening = new CompletableFuture<>();
        CompletableFuture<Map<String, String>> summary = new CompletableFuture<>();
        List<String> envArgs = new ArrayList<>(List.of(env.toString(), "--steps", Long.toString(steps),
                "--robot-port", port(0), "--viewer-port", port(1), "--geometry-port", port(2), "--control-port",
                "0"));
        if (noGeometry) {
            envArgs.add("--no-geometry");
        }
        envArgs.add("--coordinator");
        envArgs.add(coordinator);
        if (noStepMessages) {
            envArgs.add("--no-step-messages");
        }
        envArgs.addAll(resetArgs());
        if (speed > 0) {
            envArgs.add("--speed");
            envArgs.add(Double.toString(speed));
        }
        Process environment = children.start("environment", profiled(opts(environmentJvmOpts), "environment"), "robosim.environment.EnvironmentMain", envArgs, line -> {
            if (line.startsWith("listening ")) {
                listening.complete(fields(line));
            } else if (line.startsWith("summary ")) {
                summary.complete(fields(line));
            } else {
                System.out.println(line);
            }
        });
        environment.onExit().thenRun(() -> listening.complete(Map.of()));
        Map<String, String> bound = listening.get(60, TimeUnit.SECONDS);
        if (bound.isEmpty()) {
            System.err.println("headless: the Environment exited with code " + environment.waitFor()
                    + " before listening");
            return environment.exitValue() == 2 ? 2 : 1;
        }
        String robotPort = bound.get("robots");
        int viewerPort = Integer.parseInt(bound.get("viewers"));
        ViewerClient viewer = watch(viewerPort);
        ExtraViewers extras = ExtraViewers.connect(viewerPort, liveViewers, liveViewerFps, frozenViewers);
        if (this.viewer) {
            // this Environment exits after its one run: the window keeps the last picture and stops
            // waiting for a next run on the same port soon after
            children.startDetached("viewer2d", "robosim.viewer.Viewer2DMain",
                    List.of("127.0.0.1", Integer.toString(viewerPort), "--next-run-wait-s", "5"));
        }
        if (!noGeometry) {
            List<String> geometryArgs = new ArrayList<>(List.of("127.0.0.1", bound.get("geometry")));
            geometryArgs.addAll(resetArgs());
            children.start("geometry", profiled(opts(geometryJvmOpts), "geometry"), "robosim.geometry.GeometryMain",
                    geometryArgs, null);
        }
        startRobots(spec, children, robotPort);
        long limit = timeoutS > 0 ? timeoutS : Long.MAX_VALUE / 2;
        if (!environment.waitFor(limit, TimeUnit.SECONDS)) {
            System.err.println("headless: no end after " + timeoutS + " s; stopping everything");
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
        if (viewer != null) {
            viewer.awaitEnd(60, TimeUnit.SECONDS);
        }
        extras.close();
        if (poseLogWriter != null) {
            poseLogWriter.close();
        }
        List<String> failed = children.awaitAll(30);
        if (!failed.isEmpty()) {
            System.err.println("headless: processes that did not end cleanly: " + failed);
            code = code == 0 ? 1 : code;
        }
        System.out.println(String.format(Locale.ROOT,
                "steps=%s robots=%s wall_s=%s steps_per_s=%s robot_steps_per_s=%s messages=%s geometry=%s robots_in=%s",
                s.get("steps"), s.get("robots"), s.get("wall_s"), s.get("steps_per_s"), s.get("robot_steps_per_s"),
                s.get("messages"), noGeometry ? "in-process" : "process",
                robotsInOneProcess ? "one-process" : "processes"));
        return code;
    }

    private PoseLog poseLogWriter;

    private List<String> exchangeArgs() {
        return exchange == null ? List.of() : List.of("--exchange", exchange);
    }

    private ViewerClient watch(int viewerPort) throws IOException, InterruptedException {
        if (poseLog == null && !progress) {
            return null;
        }
        poseLogWriter = poseLog == null ? null : new PoseLog(poseLog);
        ViewerClient viewer = ViewerClient.connect("127.0.0.1", viewerPort, poseLog != null, 10_000);
        viewer.start(new ViewerClient.Listener() {
            private long lastPrint = System.nanoTime();
            private long lastStep = -1;

            @Override
            public void snapshot(WorldSnapshot snapshot) {
                if (poseLogWriter != null) {
                    poseLogWriter.snapshot(snapshot);
                }
            }

            @Override
            public void update(PoseUpdate u) {
                if (poseLogWriter != null) {
                    poseLogWriter.update(u);
                }
                long now = System.nanoTime();
                if (lastStep < 0) {
                    lastPrint = now;
                    lastStep = u.step();
                } else if (progress && now - lastPrint >= 1_000_000_000L) {
                    double rate = (u.step() - lastStep) / ((now - lastPrint) / 1e9);
                    System.out.printf(Locale.ROOT, "step %d/%d  %.0f steps/s%n", u.step() + 1, steps, rate);
                    lastPrint = now;
                    lastStep = u.step();
                }
            }

            @Override
            public void end(SimulationEnd end) {
                if (progress) {
                    System.out.println("simulation over: " + end.reason());
                }
            }
        });
        return viewer;
    }

    private void startRobots(WorldSpec spec, ChildProcesses children, String robotPort) throws IOException {
        if (robotsInOneProcess) {
            List<String> args = new ArrayList<>(List.of("127.0.0.1", robotPort));
            args.addAll(resetArgs());
            args.addAll(exchangeArgs());
            for (WorldSpec.RobotSpec r : spec.robots()) {
                args.add("--robot");
                args.add(r.name() + ":" + r.type() + ":" + r.control());
            }
            children.start("robots", opts(robotJvmOpts), "robosim.hardware.MultiRobotMain", args, null);
        } else {
            for (WorldSpec.RobotSpec r : spec.robots()) {
                List<String> args = new ArrayList<>(List.of(r.control(), r.name(), "127.0.0.1", robotPort, "--type",
                        r.type()));
                args.addAll(resetArgs());
                args.addAll(exchangeArgs());
                children.start("robot " + r.name(), opts(robotJvmOpts), "robosim.hardware.RobotMain", args, null);
            }
        }
    }

    private List<String> resetArgs() {
        return resetEvery == null ? List.of() : List.of("--reset-every", Integer.toString(resetEvery));
    }

    /** Adds a flight recording of the whole process to {@code options} when --profile is given. */
    private List<String> profiled(List<String> options, String role) throws IOException {
        if (profile == null) {
            return options;
        }
        java.nio.file.Files.createDirectories(profile);
        List<String> withJfr = new ArrayList<>(options);
        withJfr.add("-XX:StartFlightRecording=filename=" + profile.resolve(role + ".jfr").toAbsolutePath()
                + ",settings=profile");
        return withJfr;
    }

    private static List<String> opts(String spaceSeparated) {
        return spaceSeparated == null || spaceSeparated.isBlank() ? List.of()
                : List.of(spaceSeparated.trim().split("\\s+"));
    }

    private String port(int i) {
        return ports == null ? "0" : Integer.toString(ports.get(i));
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

    public static void main(String[] args) {
        CommandLine cl = new CommandLine(new HeadlessRunner());
        cl.setOverwrittenOptionsAllowed(true); // demo.sh's defaults, then the user's: the last one wins
        cl.setParameterExceptionHandler((ex, a) -> {
            System.err.println("headless: " + ex.getMessage() + " (see --help)");
            return 2;
        });
        System.exit(cl.execute(args));
    }
}

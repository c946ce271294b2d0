package robosim.environment;

import java.io.IOException;
import java.net.InetAddress;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.function.Consumer;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import robosim.environment.config.EnvironmentFileException;
import robosim.environment.control.EnvironmentDirectories;
import robosim.environment.control.RobotLaunches;
import robosim.environment.core.WorldSpec;
import robosim.environment.run.Settings;
import robosim.environment.server.ServerOptions;
import robosim.protocol.CommandLines;
import robosim.protocol.Protocol;
import robosim.protocol.SimulationKeys;

/**
 * {@code scripts/environment.sh FILE.xml}: the Environment server in a process of its own: its options made into
 * an {@link EnvironmentServer.Plan}, run by {@link EnvironmentServer}, its lines on stdout. Exit codes: 0 done, 1 the run failed,
 * 2 bad input (file, option, port), 3 it lost a robot, 4 (--one-jvm) a robot's control code threw out of run.
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

    @Option(names = "--geometry-port", defaultValue = "" + Protocol.DEFAULT_GEOMETRY_PORT,
            description = "Port for the Geometry process (default: ${DEFAULT-VALUE}; 0 picks a free one).")
    int geometryPort;

    @Mixin
    ServerOptions server;

    @Option(names = "--steps", defaultValue = "0",
            description = "End after this many steps (default: ${DEFAULT-VALUE} = run until stopped).")
    long steps;

    @Mixin
    RunOptions run;

    @Option(names = "--geometry-timeout-ms", defaultValue = "" + Settings.DEFAULT_GEOMETRY_TIMEOUT_MS,
            description = "Count the Geometry process as lost if one step's round trip takes longer "
                    + "(default: ${DEFAULT-VALUE}; 0 = wait for ever).")
    long geometryTimeoutMs;

    @Mixin
    GeometryLossOption geometryLoss;

    @Option(names = "--launch-robots", description = "Let the control port's add NAME TYPE X Y HEADING CONTROL start "
            + "that robot's process on this machine (robosim.hardware.RobotMain on this class path; at most "
            + RobotLaunches.MAX + " at once), as headless.sh does; without it, add waits for a robot process started "
            + "elsewhere.")
    boolean launchRobots;

    @Option(names = "--start-paused", description = "Once every client is there, wait for start (or step N) "
            + "from the control port.")
    boolean startPaused;

    @Option(names = "--keep-running", negatable = true, description = "After a simulation ends, wait on the "
            + "control port for start, load or shutdown (default: on without --steps, off with --steps).")
    Boolean keepRunning;

    @Option(names = "--env-dir", paramLabel = "DIR",
            description = "A directory whose environment files the control port's load may read; repeat for "
                    + "more (default: the directory of FILE.xml). Nothing outside them is read.")
    List<Path> envDirs;

    /** Where its lines go (listening, running, left, summary): stdout. */
    private static final Consumer<String> STDOUT = line -> {
        System.out.println(line);
        System.out.flush();
    };

    @Override
    public Integer call() throws Exception {
        WorldSpec world;
        try {
            world = run.world(file);
        } catch (EnvironmentFileException e) {
            System.err.println(e.getMessage());
            return 2;
        }
        String bad = run.problem(steps);
        if (bad == null && (robotPort < 0 || robotPort > 65535 || geometryPort < 0 || geometryPort > 65535)) {
            bad = "--robot-port and --geometry-port must be from 0 to 65535, got " + robotPort + " and " + geometryPort;
        }
        if (bad == null && geometryTimeoutMs < 0) {
            bad = "--geometry-timeout-ms must be >= 0, got " + geometryTimeoutMs;
        }
        InetAddress bind = null;
        SimulationKeys keys = null;
        if (bad == null) {
            try {
                bind = server.bind();
                keys = SimulationKeys.fromEnvironment();
                bad = server.problem(keys, bind);
            } catch (IOException e) {
                bad = e instanceof java.net.UnknownHostException ? "--bind " + server.bindName() + ": no such address"
                        : e.getMessage();
            }
        }
        EnvironmentServer.Plan plan = null;
        if (bad == null) {
            try {
                Settings settings = run.applyTo(Settings.builder(), steps)
                        .ports(bind, robotPort, server.viewerPort(), geometryPort).keys(keys)
                        .maxConnections(server.maxConnections()).handshakeTimeoutMs(server.handshakeTimeoutMs())
                        .writeTimeoutMs(server.writeTimeoutMs()).geometryTimeoutMs(geometryTimeoutMs)
                        .onGeometryLoss(geometryLoss.policy()).resetEvery(server.resetEvery())
                        .robotsInThisJvm(run.oneJvm() ? EnvironmentServer.robotsInThisJvm(file, world) : null).build();
                plan = new EnvironmentServer.Plan(file, world, settings, server.controlPort(), server.webPort(),
                        envDirs == null ? EnvironmentDirectories.of(file) : new EnvironmentDirectories(envDirs),
                        keepRunning != null ? keepRunning : steps == 0, startPaused, launchRobots);
            } catch (IllegalArgumentException | IOException e) { // (the design refuses these settings; a directory)
                bad = e.getMessage();
            }
        }
        if (bad != null) {
            System.err.println("environment: " + bad);
            return 2;
        }
        return EnvironmentServer.run(plan, STDOUT);
    }

    public static void main(String[] args) {
        CommandLines.exit("environment", new EnvironmentMain(), args);
    }
}

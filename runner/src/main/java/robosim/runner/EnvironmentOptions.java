package robosim.runner;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import picocli.CommandLine.Option;
import robosim.environment.net.ClientWorkerCoordinator;

/** The headless runner's options for the Environment process, and its command line (a picocli mixin). */
final class EnvironmentOptions {
    @Option(names = "--ports", paramLabel = "ROBOT,VIEWER,GEOMETRY", split = ",",
            description = "Environment ports (default: free ports picked by the system).")
    List<Integer> ports;

    @Option(names = "--coordinator", paramLabel = "DESIGN", defaultValue = "THREADS",
            description = "The Environment's coordinator design: THREADS (the report's, the default), SEQUENTIAL or TWO_THREADS.")
    robosim.environment.net.CoordinatorDesign coordinator;

    @Option(names = "--no-step-messages",
            description = "The Environment sends the step number only before step 0 (see environment.sh --help).")
    boolean noStepMessages;

    @Option(names = "--speed", defaultValue = "0",
            description = "Run at most this many times real time (default: ${DEFAULT-VALUE} = as fast as possible).")
    double speed;

    @Option(names = "--step-timeout-ms", paramLabel = "MS",
            description = "Remove a robot that sends no request this long after its step was released (default: the "
                    + "Environment's, " + robosim.environment.net.Settings.DEFAULT_STEP_TIMEOUT_MS + "; 0 = wait for "
                    + "ever). A run that lost a robot exits " + HeadlessRunner.EXIT_ROBOTS_REMOVED + ".")
    Long stepTimeoutMs;

    @Option(names = "--on-robot-loss", paramLabel = "POLICY", defaultValue = "REMOVE",
            description = "When a robot's process dies mid-run: REMOVE (the default), HOLD (it stands where it is until "
                    + "a process says hello with its name, e.g. scripts/robot.sh, and takes it over) or WAIT (as HOLD, "
                    + "and the world waits for it); see environment.sh --help.")
    robosim.environment.net.RobotLoss onRobotLoss;

    @Option(names = "--param", paramLabel = "NAME=VALUE", description = "Give the environment file's parameter NAME "
            + "(a placeholder ${NAME:default}, or a world <param>) this value; repeat for more.")
    java.util.Map<String, String> params = new java.util.LinkedHashMap<>();

    @Option(names = "--seed", description = "The run's seed, in place of the file's (sensor noise, Robot.seed()).")
    Long seed;

    @Option(names = "--record", paramLabel = "FILE",
            description = "Record the run into FILE, a new file (scripts/record-tool.sh reads it).")
    Path record;

    @Option(names = "--web-port", paramLabel = "PORT", description = "Serve the browser viewer on this port, on loopback "
            + "(with ROBOSIM_KEYS over TLS; default: none; 0 picks a free one, said on the listening line).")
    Integer webPort;

    /** What is wrong with these options, or null. */
    String bad() {
        if (stepTimeoutMs != null && stepTimeoutMs < 0) {
            return "headless: --step-timeout-ms must be >= 0, got " + stepTimeoutMs;
        }
        if (webPort != null && (webPort < 0 || webPort > 65535)) {
            return "headless: --web-port must be from 0 to 65535, got " + webPort;
        }
        if (ports != null && ports.size() != 3) {
            return "headless: --ports needs three ports ROBOT,VIEWER,GEOMETRY, got " + ports;
        }
        return null;
    }

    List<String> args(Path env, long steps, boolean noGeometry, List<String> resetArgs) {
        List<String> envArgs = new ArrayList<>(List.of(env.toString(), "--steps", Long.toString(steps),
                "--robot-port", port(0), "--viewer-port", port(1), "--geometry-port", port(2), "--control-port",
                "0", "--coordinator", coordinator.name(), "--on-robot-loss", onRobotLoss.name(), "--launch-robots"));
        if (noGeometry) {
            envArgs.add("--no-geometry");
        }
        if (noStepMessages) {
            envArgs.add("--no-step-messages");
        }
        envArgs.addAll(resetArgs);
        if (speed > 0) {
            envArgs.add("--speed");
            envArgs.add(Double.toString(speed));
        }
        if (stepTimeoutMs != null) {
            envArgs.add("--step-timeout-ms");
            envArgs.add(Long.toString(stepTimeoutMs));
        }
        if (webPort != null) {
            envArgs.add("--web-port");
            envArgs.add(Integer.toString(webPort));
        }
        params.forEach((name, value) -> {
            envArgs.add("--param");
            envArgs.add(name + "=" + value);
        });
        if (seed != null) {
            envArgs.add("--seed");
            envArgs.add(Long.toString(seed));
        }
        if (record != null) {
            envArgs.add("--record");
            envArgs.add(record.toAbsolutePath().toString());
        }
        return envArgs;
    }

    private String port(int i) {
        return ports == null ? "0" : Integer.toString(ports.get(i));
    }
}

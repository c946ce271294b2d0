package robosim.environment;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import robosim.environment.config.EnvironmentFileException;
import robosim.environment.config.EnvironmentLoader;
import robosim.environment.core.WorldSpec;
import robosim.environment.run.CoordinatorDesign;
import robosim.environment.run.RobotLoss;
import robosim.environment.run.Settings;

/**
 * How a run of a world goes: its parameters and seed, its pace, the coordinator design, where collisions are
 * computed and where its robots run, its timeouts and losses, its recording (a picocli mixin of environment.sh and
 * headless.sh). {@link #applyTo} sets them on a run's {@link Settings}; {@link #given} says them again for an
 * Environment process of its own.
 */
public final class RunOptions {
    @Spec(Spec.Target.SELF)
    private CommandSpec spec;

    @Mixin
    private ParamOption params;

    @Option(names = "--seed", description = "The run's seed, in place of the file's seed attribute: sensor noise and "
            + "each robot's Robot.seed() come from it.")
    private Long seed;

    @Option(names = "--speed", description = "Run at most this many times real time, so a person can watch; 0 = as "
            + "fast as possible (default: 1, real time, for a session without --steps, driven by hand; 0 with --steps).")
    private Double speed;

    @Option(names = "--coordinator", paramLabel = "DESIGN", defaultValue = "THREADS",
            description = "The coordinator design: THREADS (the report's design and the default: a reading thread "
                    + "per robot, the simulation loop writes every response), SEQUENTIAL (the original's loop: one "
                    + "thread reads every robot in turn) or TWO_THREADS (a reading and a writing thread per robot). "
                    + "Measured against each other in docs/PERFORMANCE.md.")
    private CoordinatorDesign design;

    @Option(names = "--no-geometry",
            description = "Do collision and sonar in the Environment's process instead of in a Geometry process.")
    private boolean noGeometry;

    @Option(names = "--one-jvm", description = "Run every robot of the file (its Hardware Simulator and control code) "
            + "and collision and sonar in the Environment's JVM, through in-memory links: the same messages and "
            + "results as separate processes, without their start-up, sockets and serialization (robots that join "
            + "later still connect; environment/README.md says when to pick it).")
    private boolean oneJvm;

    @Option(names = "--step-timeout-ms", paramLabel = "MS", defaultValue = "" + Settings.DEFAULT_STEP_TIMEOUT_MS,
            description = "Drop a robot that sends no request this long after its step was released "
                    + "(default: ${DEFAULT-VALUE}; 0 = wait for ever). A run that lost a robot exits 3.")
    private long stepTimeoutMs;

    @Option(names = "--on-robot-loss", paramLabel = "POLICY", defaultValue = "REMOVE",
            description = "When a robot's connection closes or fails mid-run: REMOVE (take it out of the world; the "
                    + "default), HOLD (it stands where it is, messages to it are kept, and a robot process that says "
                    + "hello with its name, e.g. scripts/robot.sh, takes it over at the next step) or WAIT (as HOLD, "
                    + "but the world waits for it, at most the step timeout, then removes it).")
    private RobotLoss onRobotLoss;

    @Option(names = "--no-step-messages", description = "Send robots the step number only before step 0; they count "
            + "on (the report's untested idea; default: a step number after every response).")
    private boolean noStepMessages;

    @Option(names = "--record", paramLabel = "FILE", description = "Record the run into FILE (a new file; a later "
            + "simulation of the same Environment into FILE-2, FILE-3...): see scripts/record-tool.sh.")
    private Path record;

    @Option(names = "--record-without-readings", description = "Record without the robots' sensor readings (what "
            + "a sweep's metrics never read): a far smaller file where robots sense much.")
    private boolean recordWithoutReadings;

    @Option(names = "--output-dir", paramLabel = "DIR", description = "Where the world's loop functions write their "
            + "own files (made when they start; default: the working directory).")
    private Path outputDir;

    /** The world of {@code file} with these options' parameters and seed. */
    public WorldSpec world(Path file) throws EnvironmentFileException {
        WorldSpec world = new EnvironmentLoader().load(file, params.values());
        try {
            return seed == null ? world : world.withSeed(seed);
        } catch (IllegalArgumentException e) { // (that seed's draws place an entity nowhere)
            throw new EnvironmentFileException(e.getMessage());
        }
    }

    /** The parameters given. */
    public java.util.Map<String, String> params() {
        return params.values();
    }

    public CoordinatorDesign design() {
        return design;
    }

    /** Collision and sonar in the Environment's process (asked, or with every robot in its JVM). */
    public boolean inProcessGeometry() {
        return noGeometry || oneJvm;
    }

    /** Every robot of the file in the Environment's JVM. */
    public boolean oneJvm() {
        return oneJvm;
    }

    /**
     * The pace of a run of {@code steps} (0: until stopped): {@code --speed} when given; otherwise real time (1) for a
     * session without an end (robots driven by hand wait for people, so running flat out would only burn the CPU),
     * and as fast as possible (0) for a run of a set number of steps.
     */
    public double speed(long steps) {
        return speed != null ? speed : steps == 0 ? 1 : 0;
    }

    /** What is wrong with these options for a run of {@code steps}, or null. */
    public String problem(long steps) {
        double pace = speed(steps);
        if (steps < 0 || !(pace >= 0) || Double.isInfinite(pace) || stepTimeoutMs < 0) {
            return "--steps, --speed and --step-timeout-ms must be >= 0";
        }
        if (record != null && (Files.exists(record) || record.toAbsolutePath().getParent() == null
                || !Files.isDirectory(record.toAbsolutePath().getParent()))) {
            return "--record " + record + ": " + (Files.exists(record) ? "already exists (not overwritten)"
                    : "its directory does not exist");
        }
        if (outputDir != null && Files.exists(outputDir) && !Files.isDirectory(outputDir)) {
            return "--output-dir " + outputDir + ": not a directory";
        }
        return null;
    }

    /** Sets these options on {@code settings}, for a run of {@code steps} (0: until stopped). */
    public Settings.Builder applyTo(Settings.Builder settings, long steps) {
        return settings.record(record).recordReadings(!recordWithoutReadings).outputDir(outputDir).stepTimeoutMs(stepTimeoutMs).design(design)
                .inProcessGeometry(inProcessGeometry()).onRobotLoss(onRobotLoss).maxSteps(steps).speed(speed(steps))
                .stepMessages(!noStepMessages);
    }

    /**
     * These options as they were given on the command line (the last value of one given twice), for an Environment
     * in a process of its own; one not given is the Environment's default there too.
     */
    public List<String> given() {
        List<String> args = new ArrayList<>();
        for (OptionSpec o : spec.options()) {
            List<String> values = o.originalStringValues();
            if (!o.isMultiValue() && values.size() > 1) {
                values = values.subList(values.size() - 1, values.size());
            }
            for (String v : values) {
                args.add(o.longestName());
                if (o.arity().max() > 0) {
                    args.add(v);
                }
            }
        }
        return args;
    }
}

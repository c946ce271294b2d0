package robosim.rl;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import robosim.environment.core.WorldSpec;
import robosim.protocol.RobotProperties;
import robosim.sweep.MetricChoice;
import robosim.environment.metrics.Metrics;

/**
 * K copies of one world ({@link BatchWorld}), stepped together: one call applies every robot's action in every
 * world and leaves what they sensed in flat little-endian arrays, laid out world by world, robot by robot (the
 * learning link's batch, {@link BatchLink}). The worlds are shared out over {@code threads} threads: the caller's
 * (the owner of time: it steps its share, world 0 among them, and waits for the rest) and {@code threads - 1}
 * threads {@code rl-worlds[t]} ({@link StepCrew}), which step only when the caller steps. The same seed and the
 * same actions give the same arrays, bit for bit, whatever the threads.
 */
public final class BatchWorlds implements AutoCloseable {
    /** The built-in metrics of each world, their columns first (the registry's order, {@link Metrics}). */
    public static final List<String> METRICS = Metrics.names();
    /** A robot's action: linear velocity (mm/s), rotational velocity (deg/s), then its message's numbers. */
    public static final int VELOCITIES = 2;

    private final WorldSpec spec;
    private final List<RobotProperties> properties;
    private final int robots;
    private final int sonars;
    private final double[] sonarMaxMm;
    private final Settings settings;
    private final Path recordings;
    private final BatchWorld[] worlds;
    private final int threads;
    /** The threads beside the caller's, or null for one thread. */
    private final StepCrew crew;
    private final Object watchLock = new Object();
    private final byte[] sonar;
    private final byte[] pose;
    private final byte[] contact;
    private final byte[] messages;
    private final SensorColumns sensorColumns;
    private final ActuatorColumns actuatorColumns;
    private final byte[] readings;
    private final byte[] metrics;
    private final byte[] finished;
    /** The columns of {@link #metrics}: the built-ins, then the loop functions' the settings name. */
    private final List<String> metricNames;
    private final byte[] steps;

    /**
     * How a batch's worlds are stepped and what they tell.
     *
     * @param repeat time steps an action is held
     * @param messageSize numbers in a robot's message (0: none)
     * @param randomHeadings the robots' start headings drawn from each episode's seed
     * @param areaCellM the side of {@code area_covered}'s cells, m
     * @param threads threads that step the worlds (at most the worlds; no more than the cores, {@link StepCrew})
     * @param episodeMetric a metric of each episode's recording ({@link #measure}), or null
     * @param sensors each robot's sensors (its file's) read with each action's last time step, into
     *     {@link #readings()}; without, they are not read (no ray cast, no noise drawn)
     */
    public record Settings(int repeat, int messageSize, boolean randomHeadings, double areaCellM, int threads,
            MetricChoice episodeMetric, boolean sensors, boolean actuators, List<String> loopMetrics) {
        public Settings {
            if (!(areaCellM > 0) || Double.isInfinite(areaCellM)) {
                throw new IllegalArgumentException("the area cell must be a side > 0 m, got " + areaCellM);
            }
            loopMetrics = List.copyOf(loopMetrics);
            String bad = loopMetricsProblem(loopMetrics);
            if (bad != null) {
                throw new IllegalArgumentException(bad);
            }
        }

        /** What is wrong with these names of loop functions' metrics (not a report's name, a built-in's, twice), or null. */
        public static String loopMetricsProblem(List<String> names) {
            for (String name : names) {
                String bad = robosim.protocol.Report.problem(name, 0);
                if (bad != null || METRICS.contains(name) || names.indexOf(name) != names.lastIndexOf(name)) {
                    return "loop metric \"" + robosim.protocol.Printable.of(name, 64) + "\": " + (bad != null ? bad
                            : METRICS.contains(name) ? "a built-in metric's name" : "named twice");
                }
            }
            return null;
        }

        /** Without metrics of the world's loop functions. */
        public Settings(int repeat, int messageSize, boolean randomHeadings, double areaCellM, int threads,
                MetricChoice episodeMetric, boolean sensors, boolean actuators) {
            this(repeat, messageSize, randomHeadings, areaCellM, threads, episodeMetric, sensors, actuators, List.of());
        }

        /** Without acting through the robots' devices. */
        public Settings(int repeat, int messageSize, boolean randomHeadings, double areaCellM, int threads,
                MetricChoice episodeMetric, boolean sensors) {
            this(repeat, messageSize, randomHeadings, areaCellM, threads, episodeMetric, sensors, false);
        }

        /** Without the robots' sensors and devices. */
        public Settings(int repeat, int messageSize, boolean randomHeadings, double areaCellM, int threads,
                MetricChoice episodeMetric) {
            this(repeat, messageSize, randomHeadings, areaCellM, threads, episodeMetric, false, false);
        }

        /** Without an episode metric or the robots' sensors. */
        public Settings(int repeat, int messageSize, boolean randomHeadings, double areaCellM, int threads) {
            this(repeat, messageSize, randomHeadings, areaCellM, threads, null, false, false);
        }
    }

    /** {@code count} worlds of {@code spec}, as {@code settings} says; world w starts with seed {@code seed + w}. */
    public BatchWorlds(WorldSpec spec, int count, Settings settings) throws IOException {
        this.spec = spec;
        List<RobotProperties> p = new ArrayList<>();
        int most = 0;
        for (WorldSpec.RobotSpec r : spec.robots()) {
            RobotProperties model = robosim.devices.RobotTypes.properties(r.type());
            p.add(model);
            most = Math.max(most, model.sonars().size());
        }
        this.properties = List.copyOf(p);
        this.robots = p.size();
        this.sonars = most;
        this.sonarMaxMm = p.stream().mapToDouble(r -> r.sonars().stream().mapToDouble(s -> s.maxRangeMm()).max()
                .orElse(0)).toArray();
        this.settings = settings;
        int messageSize = settings.messageSize();
        this.recordings = settings.episodeMetric() == null ? null : Files.createTempDirectory("robosim-episodes-");
        this.sonar = new byte[count * robots * sonars * 4];
        this.pose = new byte[count * robots * 3 * 4];
        this.contact = new byte[count * robots];
        this.messages = new byte[count * robots * robots * messageSize * 4];
        this.sensorColumns = new SensorColumns(spec, settings.sensors());
        this.actuatorColumns = new ActuatorColumns(spec, settings.actuators(), VELOCITIES + messageSize);
        this.readings = new byte[count * robots * sensorColumns.width() * 4];
        this.metricNames = java.util.stream.Stream.concat(METRICS.stream(), settings.loopMetrics().stream()).toList();
        this.metrics = new byte[count * metricNames.size() * 8];
        this.steps = new byte[count * 8];
        this.finished = new byte[count];
        this.threads = Math.max(1, Math.min(settings.threads(), count));
        this.crew = this.threads == 1 ? null : new StepCrew(this.threads);
        this.worlds = new BatchWorld[count];
        for (int w = 0; w < count; w++) {
            worlds[w] = new BatchWorld(this, w);
        }
        long[] seeds = new long[count];
        boolean[] all = new boolean[count];
        for (int w = 0; w < count; w++) {
            seeds[w] = spec.seed() + w;
            all[w] = true;
        }
        try {
            step(null, all, seeds);
        } catch (IOException | RuntimeException e) {
            close();
            throw e;
        }
    }

    /**
     * One step of every world: world w starts a new episode with {@code seeds[w]} where {@code reset[w]}, else
     * applies its robots' actions ({@code actions}: world by world, robot by robot, {@link #actionFields()} each,
     * already checked: finite, velocities within {@link #limits}); with {@code actions} null the worlds not reset
     * stay as they are.
     */
    public void step(float[] actions, boolean[] reset, long[] seeds) throws IOException {
        try {
            if (crew == null) {
                stepShare(0, actions, reset, seeds);
            } else {
                crew.run(share -> stepShare(share, actions, reset, seeds));
            }
        } catch (IOException e) { // (a ProtocolException among them)
            throw e;
        } catch (VirtualMachineError e) {
            throw e;
        } catch (Exception | Error e) { // (a world that cannot go on: said as one failure, whatever it was)
            throw new IllegalStateException("a world's step failed: " + e, e);
        }
    }

    private void stepShare(int share, float[] actions, boolean[] reset, long[] seeds) throws IOException {
        for (int w = share; w < worlds.length; w += threads) {
            if (w == 0) {
                synchronized (watchLock) { // (a viewer that joins sees world 0 between steps; share 0 is the caller's)
                    stepWorld(0, actions, reset, seeds);
                }
            } else {
                stepWorld(w, actions, reset, seeds);
            }
        }
    }

    private void stepWorld(int w, float[] actions, boolean[] reset, long[] seeds) throws IOException {
        if (reset[w]) {
            worlds[w].reset(seeds[w]);
        } else if (actions != null) {
            worlds[w].act(actions, w * robots * actionFields());
        }
    }

    /** Each robot's limits, in world order: {max speed mm/s, max turn deg/s}. */
    public double[][] limits() {
        double[][] out = new double[robots][];
        for (int i = 0; i < robots; i++) {
            out[i] = new double[] {properties.get(i).maxSpeedMmPerS(), properties.get(i).maxTurnDegPerS()};
        }
        return out;
    }

    /** World 0, for a viewer; use it holding {@link #watchLock()} only. */
    BatchWorld watched() {
        return worlds[0];
    }

    /** Held while world 0 steps: whoever holds it sees world 0 between two steps. */
    Object watchLock() {
        return watchLock;
    }

    public int count() {
        return worlds.length;
    }

    public int robots() {
        return robots;
    }

    /** The most sonars of a robot of the world: each robot's row of {@link #sonar()} is this long (0s past its own). */
    public int sonars() {
        return sonars;
    }

    /** Robot {@code robot}'s farthest sonar range, mm (0 without sonars). */
    public double sonarMaxMm(int robot) {
        return sonarMaxMm[robot];
    }

    public int actionFields() {
        return VELOCITIES + settings.messageSize() + actuatorColumns.width();
    }

    /** Where each robot's devices lie in its action row (none unless the settings ask for them). */
    ActuatorColumns actuatorColumns() {
        return actuatorColumns;
    }

    public WorldSpec spec() {
        return spec;
    }

    public List<RobotProperties> properties() {
        return properties;
    }

    public int repeat() {
        return settings.repeat();
    }

    public int messageSize() {
        return settings.messageSize();
    }

    boolean randomHeadings() {
        return settings.randomHeadings();
    }

    double areaCellM() {
        return settings.areaCellM();
    }

    /** The metric of each episode's recording, or null. */
    public MetricChoice episodeMetric() {
        return settings.episodeMetric();
    }

    /** Where the episodes are recorded (with an episode metric). */
    Path recordings() {
        return recordings;
    }

    /**
     * The episode metric over world {@code w}'s episode so far, computed from its recording as a sweep measures a
     * run (the caller steps no world meanwhile).
     *
     * @throws IllegalStateException if the batch measures no metric
     */
    public double measure(int w) throws IOException {
        if (settings.episodeMetric() == null) {
            throw new IllegalStateException("no episode metric");
        }
        return worlds[w].measure();
    }

    /** float32 [worlds][robots][sonars], mm. */
    public byte[] sonar() {
        return sonar;
    }

    /** float32 [worlds][robots][3]: x mm, y mm, heading degrees. */
    public byte[] pose() {
        return pose;
    }

    /** uint8 [worlds][robots]: 1 if the robot touched something in the last action's time steps. */
    public byte[] contact() {
        return contact;
    }

    /** float32 [worlds][robots][robots][messageSize]: the last message each robot heard from each, zeros if none. */
    public byte[] messages() {
        return messages;
    }

    /**
     * float32 [worlds][robots][{@link SensorColumns#width()}]: each robot's sensors' readings of the last action's last
     * time step, in their sensors' columns, zeros where it has none.
     */
    public byte[] readings() {
        return readings;
    }

    /** Where each robot's sensors lie in {@link #readings()}. */
    SensorColumns sensorColumns() {
        return sensorColumns;
    }

    /** float64 [worlds][{@link #metricNames}]: each world's episode so far. */
    public byte[] metrics() {
        return metrics;
    }

    /** The column, among the loop metrics, of loop metric {@code name}; -1 when the batch does not name it. */
    int loopMetricColumn(String name) {
        return settings.loopMetrics().indexOf(name);
    }

    /**
     * The metrics' columns: the built-ins ({@link #METRICS}), then the loop functions' metrics the settings name, each
     * the newest value the world's loop functions reported in the episode (0 before their first report).
     */
    public List<String> metricNames() {
        return metricNames;
    }

    /** int64 [worlds]: time steps since each world's episode began. */
    public byte[] steps() {
        return steps;
    }

    /**
     * uint8 [worlds]: 1 where the world's loop functions have said its experiment is over (finished, or end) in this
     * episode: its robots' episodes end there.
     */
    public byte[] finished() {
        return finished;
    }

    @Override
    public void close() throws IOException {
        if (crew != null) {
            crew.close();
        }
        for (BatchWorld w : worlds) {
            if (w != null) {
                w.close();
            }
        }
        if (recordings != null) {
            try (java.util.stream.Stream<Path> files = Files.list(recordings)) {
                for (Path f : files.toList()) {
                    Files.deleteIfExists(f);
                }
            }
            Files.deleteIfExists(recordings);
        }
    }
}

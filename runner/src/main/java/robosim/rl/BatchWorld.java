package robosim.rl;

import java.io.IOException;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import robosim.devices.Drive;
import robosim.environment.core.ExperimentFailure;
import robosim.environment.core.InProcessGeometry;
import robosim.environment.core.SimulationCore;
import robosim.environment.core.WorldSpec;
import robosim.environment.metrics.MetricTally;
import robosim.protocol.CommEvent;
import robosim.protocol.RobotProperties;
import robosim.protocol.RobotView;
import robosim.protocol.SensorReading;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;
import robosim.protocol.WorldSnapshot;

/**
 * One world of a {@link BatchWorlds}: the Environment's simulation core and the Geometry engine of an environment
 * file, stepped inline (no threads, no links), its robots' requests made from an action each (a linear and a
 * rotational velocity, perhaps a message), and what the robots sensed written into the batch's arrays. Its episode
 * starts at {@link #reset}: a new world from the file with the episode's seed (and, if asked, headings drawn from
 * it), one step of standing still that reads the sonars, the core's tally of the built-in metrics
 * ({@link robosim.environment.metrics.MetricTally}), and, if the batch measures a metric of each episode, the
 * episode's {@link EpisodeRecording}. Not
 * thread-safe: one caller at a time (the batch hands each world to one thread a step).
 */
final class BatchWorld {
    private static final VarHandle FLOAT = MethodHandles.byteArrayViewVarHandle(float[].class, ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle DOUBLE = MethodHandles.byteArrayViewVarHandle(double[].class,
            ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle LONG = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.LITTLE_ENDIAN);

    private final BatchWorlds batch;
    private final int index;
    private final int robots;
    private final String[] names;
    private final Map<String, Integer> byName = new HashMap<>();
    private final double seconds;
    private final StepRequest[] requests;
    /** Each robot's sensors, asked for with the last time step of each action (the sonars with them). */
    private final List<String>[] sensors;
    private final StepRequest[] lastRequests;
    private final boolean[] touched;
    /** The newest value of each loop metric the batch names ({@link BatchWorlds#metricNames}), this episode. */
    private final double[] loopMetrics;
    /** Null unless the batch measures a metric of each episode's recording. */
    private final EpisodeRecording recording;
    private final StepResponse[] responses;
    private SimulationCore core;
    private InProcessGeometry geometry;
    private long step;
    private boolean newWorld;
    /** What the loop functions drew since the watched update was last taken ({@link #watchedUpdate}; world 0's). */
    private robosim.protocol.Traces drawnSince = robosim.protocol.Traces.NONE;

    BatchWorld(BatchWorlds batch, int index) {
        this.batch = batch;
        this.index = index;
        WorldSpec spec = batch.spec();
        this.robots = spec.robots().size();
        this.names = new String[robots];
        for (int i = 0; i < robots; i++) {
            names[i] = spec.robots().get(i).name();
            byName.put(names[i], i);
        }
        this.seconds = Drive.seconds(spec.timeStepMs());
        this.requests = new StepRequest[robots];
        @SuppressWarnings("unchecked")
        List<String>[] asked = new List[robots];
        for (int i = 0; i < robots; i++) {
            asked[i] = batch.sensorColumns().names(i);
        }
        this.sensors = asked;
        this.lastRequests = new StepRequest[robots];
        this.touched = new boolean[robots];
        this.loopMetrics = new double[batch.metricNames().size() - BatchWorlds.METRICS.size()];
        this.responses = new StepResponse[robots];
        this.recording = batch.episodeMetric() == null ? null
                : new EpisodeRecording(batch.recordings(), index, batch.episodeMetric(), batch.areaCellM());
    }

    /**
     * A new episode: the world of the file with {@code seed} (robots' headings drawn from it if the batch says so),
     * then one step of standing still, whose readings are the episode's first observation.
     */
    void reset(long seed) throws IOException {
        WorldSpec spec = batch.spec().withSeed(seed);
        if (batch.randomHeadings()) {
            SplittableRandom random = new SplittableRandom(seed);
            List<WorldSpec.RobotSpec> turned = new ArrayList<>();
            for (WorldSpec.RobotSpec r : spec.robots()) {
                turned.add(r.at(r.xMm(), r.yMm(), random.nextDouble(360)));
            }
            spec = spec.withRobots(turned);
        }
        List<RobotProperties> properties = batch.properties();
        robosim.loop.LoopFunctions kept = core == null ? null : core.loopFunctions();
        try {
            if (core != null && kept == null) {
                core.endExperiment(); // (loop functions that threw: destroyed once, their files closed)
            }
            core = new SimulationCore(spec, properties, batch.areaCellM());
            // (the world's loop functions: one instance, reset each episode; each world's files in its own folder)
            core.startExperiment(java.nio.file.Path.of("loop-world-" + index), kept);
        } catch (ExperimentFailure e) {
            throw new IOException(e.getMessage(), e);
        }
        geometry = new InProcessGeometry(core.map().geometryWorld());
        step = 0;
        newWorld = true;
        drawnSince = robosim.protocol.Traces.NONE; // (the new world goes to viewers whole)
        Arrays.fill(touched, false);
        Arrays.fill(loopMetrics, 0);
        forgetMessages();
        for (int i = 0; i < robots; i++) {
            requests[i] = new StepRequest(step, 0, 0, true, List.of(), sensors[i]);
        }
        if (recording != null) {
            recording.begin(core.startSnapshot()); // (as the loop functions' init left the world)
        }
        advance();
        write();
    }

    /**
     * Applies each robot's action, {@code actions[offset + robot * fields ...]}: velocities (mm/s, deg/s; finite,
     * bounded by the robot type's limits before they come here), then the message's numbers, then its devices'
     * values ({@link ActuatorColumns}, set in the first time step), for the batch's
     * repeat of time steps (the message goes out in the first, the sonars are read in the last), and writes what
     * the robots sensed.
     */
    void act(float[] actions, int offset) throws IOException {
        int fields = batch.actionFields();
        int repeat = batch.repeat();
        Arrays.fill(touched, false);
        forgetMessages();
        for (int r = 0; r < repeat; r++) {
            for (int i = 0; i < robots; i++) {
                int a = offset + i * fields;
                List<CommEvent> sent = r == 0 && batch.messageSize() > 0
                        ? List.of(new CommEvent(names[i], CommEvent.EVERYONE, MessageNumbers.text(actions, a + 2,
                        batch.messageSize())))
                        : List.of();
                boolean last = r == repeat - 1;
                requests[i] = new StepRequest(step, Drive.perStep(actions[a], seconds),
                        Drive.perStep(actions[a + 1], seconds), last, sent, last ? sensors[i] : List.of());
                if (r == 0) { // (the devices are set once; LEDs and messages hold, the gripper waits)
                    requests[i] = batch.actuatorColumns().apply(requests[i], i, actions, a);
                }
            }
            advance();
        }
        write();
    }

    /** One time step of the requests in hand (the world's step, its metrics counted), then the messages heard. */
    private void advance() throws IOException {
        try {
            core.step(step, requests, geometry);
        } catch (ExperimentFailure e) {
            throw new IOException(e.getMessage(), e);
        }
        core.tally();
        if (index == 0) { // (the world viewers may watch: what each step drew, kept for the next update they get)
            drawnSince = drawnSince.then(core.experimentTraces());
        }
        List<robosim.protocol.Report> reported = core.experimentReports();
        for (int r = 0; r < reported.size(); r++) { // (the loop metrics the batch names: each one's newest value)
            int column = batch.loopMetricColumn(reported.get(r).name());
            if (column >= 0) {
                loopMetrics[column] = reported.get(r).value();
            }
        }
        System.arraycopy(requests, 0, lastRequests, 0, robots);
        if (recording != null) {
            for (int i = 0; i < robots; i++) {
                responses[i] = core.response(i);
            }
            recording.step(core.viewerUpdate(), requests, responses);
        }
        for (int i = 0; i < robots; i++) {
            StepResponse response = core.response(i);
            touched[i] |= !response.contact().isEmpty();
            if (batch.messageSize() > 0) {
                for (CommEvent m : response.inbox()) {
                    Integer from = byName.get(m.from());
                    if (from != null) {
                        MessageNumbers.read(m.payload(), batch.messages(),
                                messagesAt(i) + from * batch.messageSize() * 4,
                                batch.messageSize());
                    }
                }
            }
        }
        step++;
    }

    /** Zeros for every message this world's robots heard: each action (and episode) hears its own. */
    private void forgetMessages() {
        if (batch.messageSize() > 0) {
            Arrays.fill(batch.messages(), messagesAt(0), messagesAt(robots), (byte) 0);
        }
    }

    private int messagesAt(int robot) {
        return ((index * robots + robot) * robots) * batch.messageSize() * 4;
    }

    /**
     * The sonars (each held to its robot's farthest range: noise may read beyond it), poses, contacts, metrics and
     * step of this world into the batch's arrays.
     */
    private void write() {
        int sonars = batch.sonars();
        byte[] sonar = batch.sonar();
        byte[] pose = batch.pose();
        byte[] contact = batch.contact();
        for (int i = 0; i < robots; i++) {
            StepResponse response = core.response(i);
            double[] ranges = response.sonarMm();
            int at = ((index * robots) + i) * sonars * 4;
            for (int s = 0; s < sonars; s++) {
                FLOAT.set(sonar, at + s * 4, s < ranges.length ? (float) Math.min(ranges[s], batch.sonarMaxMm(i)) : 0f);
            }
            int p = ((index * robots) + i) * 3 * 4;
            FLOAT.set(pose, p, (float) response.xMm());
            FLOAT.set(pose, p + 4, (float) response.yMm());
            FLOAT.set(pose, p + 8, (float) response.headingDeg());
            contact[index * robots + i] = (byte) (touched[i] ? 1 : 0);
            writeReadings(i, response);
        }
        byte[] metrics = batch.metrics();
        MetricTally tally = core.metrics();
        int m = index * (tally.size() + loopMetrics.length) * 8;
        for (int k = 0; k < tally.size(); k++) {
            DOUBLE.set(metrics, m + k * 8, tally.value(k));
        }
        for (int k = 0; k < loopMetrics.length; k++) {
            DOUBLE.set(metrics, m + (tally.size() + k) * 8, loopMetrics[k]);
        }
        LONG.set(batch.steps(), index * 8, step);
        batch.finished()[index] = (byte) (core.experimentEnd() != null ? 1 : 0);
    }

    /**
     * Robot {@code i}'s readings into its row of the batch's readings: each sensor's values in its columns, held to
     * its range; zeros where it has none, or a sensor gave none this step (it failed: its notice says why).
     */
    private void writeReadings(int i, StepResponse response) {
        SensorColumns columns = batch.sensorColumns();
        int width = columns.width();
        if (width == 0) {
            return;
        }
        byte[] readings = batch.readings();
        int row = ((index * robots) + i) * width * 4;
        Arrays.fill(readings, row, row + width * 4, (byte) 0);
        List<SensorColumns.Column> own = columns.of(i);
        List<SensorReading> got = response.readings();
        for (int k = 0; k < own.size(); k++) {
            SensorColumns.Column c = own.get(k);
            double[] values = null;
            for (int g = 0; g < got.size() && values == null; g++) {
                if (got.get(g).name().equals(c.name())) {
                    values = got.get(g).values();
                }
            }
            for (int v = 0; values != null && v < values.length && v < c.values().count(); v++) {
                double held = Math.max(c.values().low(), Math.min(c.values().high(), values[v]));
                FLOAT.set(readings, row + (c.offset() + v) * 4, (float) held);
            }
        }
    }

    /**
     * The world as it stands, for a viewer that joins (the caller holds the batch's watch lock): with what its loop
     * functions have left, their whole drawing among it.
     */
    WorldSnapshot snapshot() {
        return robosim.environment.core.EnvironmentMap.snapshot(core.map().spec(), batch.properties(), core.viewerUpdate()
                .posesOnly());
    }

    /**
     * The step's update for the viewers, drawing what the loop functions drew in every time step of the last action
     * (its {@code repeat} steps), not only its last (the caller holds the batch's watch lock).
     */
    robosim.protocol.PoseUpdate watchedUpdate() {
        robosim.protocol.PoseUpdate u = core.viewerUpdate().withPiece(drawnSince);
        drawnSince = robosim.protocol.Traces.NONE;
        return u;
    }

    /** True once after each reset: a viewer is sent the new world whole. */
    boolean takeNewWorld() {
        boolean was = newWorld;
        newWorld = false;
        return was;
    }

    SimulationCore core() {
        return core;
    }

    /** Robot {@code robot}'s view of the last step, for a viewer that watches it. */
    RobotView view(int robot) {
        return RobotView.of(step - 1, robot, names[robot], lastRequests[robot], core.response(robot));
    }

    /** The batch's episode metric over this world's episode so far (the batch measures one). */
    double measure() throws IOException {
        return recording.measure();
    }

    void close() throws IOException {
        try {
            if (core != null) {
                core.endExperiment();
            }
        } catch (ExperimentFailure e) {
            throw new IOException(e.getMessage(), e);
        } finally {
            if (recording != null) {
                recording.close();
            }
        }
    }

    int robot(String name) {
        Integer i = byName.get(name);
        return i == null ? -1 : i;
    }
}

package robosim.rl;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.net.Socket;
import java.nio.ByteOrder;
import java.util.List;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;
import org.msgpack.core.MessagePackException;
import org.msgpack.core.MessageUnpacker;
import org.msgpack.value.ValueType;
import robosim.environment.core.WorldSpec;
import robosim.protocol.link.LinkFrames;
import robosim.protocol.link.LinkHello;
import robosim.protocol.Printable;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotProperties;
import robosim.protocol.SonarSpec;

/**
 * The learning link (python/README.md, "Learning controllers"): a learner in another process steps a
 * {@link BatchWorlds} over one connection, in the robot link's frames ({@link LinkFrames}): a hello
 * {@code {link: "robosim-batch-link", version: 1, key}} within {@link LinkHello#DEADLINE_MS} ({@link LinkHello}), the welcome (the worlds,
 * robots and their limits, the arrays' shapes), then one request and one reply a step:
 * <ul>
 * <li>{@code ["step", ACTIONS, RESETS]}: ACTIONS a binary of float32 (little-endian), world by world, robot by robot,
 * the action's fields each; RESETS nil or a map world -> seed: those worlds begin a new episode instead (their
 * actions are not read). Reply {@code ["ok", BATCH]};
 * <li>{@code ["reset", SEEDS]}: SEEDS an array, one per world, a seed or nil (that world stays as it is). Reply
 * {@code ["ok", BATCH]};
 * <li>{@code ["measure", [WORLD, ...]]}: with an episode metric ({@code --episode-metric}), its value over each
 * world's episode so far, from the episode's recording. Reply {@code ["ok", [VALUE, ...]]};
 * <li>{@code ["bye"]}: reply {@code ["ok"]}, and the link ends.
 * </ul>
 * BATCH is a map of binaries, each a little-endian array (shapes in the welcome): {@code steps} (int64), {@code sonar},
 * {@code pose} (float32), {@code contact} (uint8), {@code metrics} (float64), {@code messages} (float32, when
 * messages have numbers), {@code readings} (float32, with {@code --sensors}, when the robots have sensors). A request that is not one, or actions not finite or not of the batch's size, is answered
 * {@code ["error", KIND, WHY]} (kinds {@code bad_call}, {@code value}) and the link goes on; velocities beyond a
 * robot's limits are held to them, and device values ({@code --actuators}: {@link ActuatorColumns}) to theirs. A world that cannot go on (an internal failure) is answered
 * {@code ["error", "failed", WHY]} and the link ends.
 */
public final class BatchLink {
    public static final String NAME = "robosim-batch-link";
    public static final int VERSION = 2;
    /** The arrays a learner observes besides each robot's sensors (a sensor may not take their names). */
    static final List<String> OBSERVED = List.of("sonar", "contact", "pose", "messages");
    /** What its hello must be: the link's name and version. */
    private static final LinkHello.Link HELLO = new LinkHello.Link(NAME, "learning link", VERSION, "learner", List.of());
    private static final VarHandle FLOAT = MethodHandles.byteArrayViewVarHandle(float[].class, ByteOrder.LITTLE_ENDIAN);

    private final Socket socket;
    private final DataInputStream in;
    private final DataOutputStream out;
    private final BatchWorlds batch;
    private final WatchedWorld watch;
    private final MessageBufferPacker reply = MessagePack.newDefaultBufferPacker();
    // (a step's buffers, made once the hello is accepted: a stranger's connection costs none of them)
    private float[] actions;
    private byte[] actionBytes;
    private boolean[] reset;
    private long[] seeds;
    private double[][] limits;
    private long stepsServed;

    BatchLink(Socket socket, BatchWorlds batch, WatchedWorld watch) throws IOException {
        this.socket = socket;
        this.in = new DataInputStream(new BufferedInputStream(socket.getInputStream()));
        this.out = new DataOutputStream(new BufferedOutputStream(socket.getOutputStream()));
        this.batch = batch;
        this.watch = watch;
    }

    /** The largest reply of {@code batch}, bytes (its arrays and their names). */
    static long replyBytes(int worlds, int robots, int sonars, int messageSize, int readings, int metrics) {
        return 256L + worlds * (8L + metrics * 8L + robots * (sonars * 4L + 12 + 1
                + (long) robots * messageSize * 4 + readings * 4L));
    }

    /**
     * The hello, checked ({@code key}: the secret the learner was given; a hello without it is refused), then the
     * welcome. A hello that is late, not this link's or of another version is refused, answered why if it came.
     *
     * @throws ProtocolException the refusal
     */
    void welcome(String key) throws IOException {
        LinkHello.read(HELLO, socket, in, out, key);
        actions = new float[batch.count() * batch.robots() * batch.actionFields()];
        actionBytes = new byte[actions.length * 4];
        reset = new boolean[batch.count()];
        seeds = new long[batch.count()];
        limits = batch.limits();
        LinkFrames.write(out, welcomeFrame());
    }

    private byte[] welcomeFrame() throws IOException {
        MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
        List<RobotProperties> properties = batch.properties();
        p.packMapHeader(23);
        p.packString("link").packString(NAME);
        p.packString("version").packInt(VERSION);
        p.packString("world").packString(batch.spec().name());
        p.packString("worlds").packInt(batch.count());
        p.packString("robots").packArrayHeader(batch.robots());
        batch.spec().robots().forEach(r -> pack(p, r.name()));
        p.packString("types").packArrayHeader(batch.robots());
        batch.spec().robots().forEach(r -> pack(p, r.type()));
        p.packString("sonars").packInt(batch.sonars());
        p.packString("sonar_angles_deg").packArrayHeader(batch.robots());
        for (RobotProperties r : properties) {
            p.packArrayHeader(r.sonars().size());
            for (SonarSpec s : r.sonars()) {
                p.packDouble(s.angleDeg());
            }
        }
        p.packString("sonar_max_mm").packArrayHeader(batch.robots());
        for (int i = 0; i < batch.robots(); i++) {
            p.packDouble(batch.sonarMaxMm(i));
        }
        p.packString("max_speed_mm_s").packArrayHeader(batch.robots());
        for (double[] l : limits) {
            p.packDouble(l[0]);
        }
        p.packString("max_turn_deg_s").packArrayHeader(batch.robots());
        for (double[] l : limits) {
            p.packDouble(l[1]);
        }
        p.packString("step_ms").packLong(batch.spec().timeStepMs());
        p.packString("repeat").packInt(batch.repeat());
        p.packString("message_size").packInt(batch.messageSize());
        p.packString("metrics").packArrayHeader(batch.metricNames().size());
        batch.metricNames().forEach(m -> pack(p, m));
        p.packString("arena_mm").packArrayHeader(4).packDouble(batch.spec().arena().minXMm())
                .packDouble(batch.spec().arena().minYMm()).packDouble(batch.spec().arena().maxXMm())
                .packDouble(batch.spec().arena().maxYMm());
        p.packString("seed").packLong(batch.spec().seed());
        p.packString("loop_functions").packBoolean(batch.spec().loopFunctions() != null);
        p.packString("readings").packInt(batch.sensorColumns().width());
        p.packString("sensors").packArrayHeader(batch.robots());
        for (int i = 0; i < batch.robots(); i++) { // (each robot's sensors: their boxes, from their descriptions)
            List<SensorColumns.Column> own = batch.sensorColumns().of(i);
            p.packArrayHeader(own.size());
            for (int k = 0; k < own.size(); k++) {
                SensorColumns.Column c = own.get(k);
                robosim.devices.DeviceSpec spec = batch.spec().robots().get(i).sensors().get(k);
                p.packMapHeader(7);
                p.packString("name").packString(c.name());
                p.packString("offset").packInt(c.offset());
                p.packString("type").packString(spec.kind());
                p.packString("count").packInt(c.values().count());
                p.packString("low").packArrayHeader(c.values().count()); // (each value's own: grouped fields differ)
                for (int v = 0; v < c.values().count(); v++) {
                    p.packDouble(c.values().low(v));
                }
                p.packString("high").packArrayHeader(c.values().count());
                for (int v = 0; v < c.values().count(); v++) {
                    p.packDouble(c.values().high(v));
                }
                p.packString("unit").packString(c.values().unit());
            }
        }
        p.packString("action_fields").packInt(batch.actionFields());
        p.packString("actuators").packArrayHeader(batch.robots());
        for (int i = 0; i < batch.robots(); i++) { // (each robot's devices: their fields in its action row)
            List<ActuatorColumns.Column> own = batch.actuatorColumns().of(i);
            p.packArrayHeader(own.size());
            for (ActuatorColumns.Column c : own) {
                p.packMapHeader(5);
                p.packString("name").packString(c.name());
                p.packString("offset").packInt(c.offset());
                p.packString("count").packInt(c.values().count());
                p.packString("low").packDouble(c.values().low());
                p.packString("high").packDouble(c.values().high());
            }
        }
        if (batch.episodeMetric() == null) {
            p.packString("episode_metric").packNil();
        } else {
            p.packString("episode_metric").packString(batch.episodeMetric().name());
        }
        return p.toByteArray();
    }

    /** Serves requests until the learner says bye or closes the link; returns the steps served. */
    long serve() throws IOException {
        while (true) {
            byte[] frame = LinkFrames.read(in);
            if (frame == null) {
                return stepsServed;
            }
            reply.clear();
            boolean bye = false;
            try (MessageUnpacker u = MessagePack.newDefaultUnpacker(frame)) {
                String call = call(u);
                switch (call) {
                    case "step" -> {
                        expectArguments(u, 2, call);
                        readActions(u);
                        readResets(u);
                        whole(u);
                        step(true);
                    }
                    case "reset" -> {
                        expectArguments(u, 1, call);
                        java.util.Arrays.fill(reset, false);
                        readSeeds(u);
                        whole(u);
                        step(false);
                    }
                    case "measure" -> {
                        expectArguments(u, 1, call);
                        measure(u);
                    }
                    case "bye" -> {
                        expectArguments(u, 0, call);
                        whole(u);
                        reply.packArrayHeader(1).packString("ok");
                        bye = true;
                    }
                    default -> throw new BadCall("bad_call", "no call \"" + Printable.of(call, 40)
                            + "\" (step, reset, measure, bye)");
                }
            } catch (BadCall e) {
                reply.clear();
                reply.packArrayHeader(3).packString("error").packString(e.kind).packString(e.getMessage());
            } catch (MessagePackException e) {
                reply.clear();
                reply.packArrayHeader(3).packString("error").packString("bad_call")
                        .packString("a request that is not one: " + LinkFrames.oneLine(e.getMessage()));
            }
            LinkFrames.write(out, reply.toByteArray());
            if (bye) {
                return stepsServed;
            }
        }
    }

    private int arguments;

    private String call(MessageUnpacker u) throws IOException {
        if (u.getNextFormat().getValueType() != ValueType.ARRAY) {
            throw new BadCall("bad_call", "a request is an array [CALL, ARG...]");
        }
        arguments = u.unpackArrayHeader() - 1;
        if (arguments < 0 || u.getNextFormat().getValueType() != ValueType.STRING) {
            throw new BadCall("bad_call", "a request begins with its call's name");
        }
        return u.unpackString();
    }

    /** The request read, nothing may follow it in its frame. */
    private static void whole(MessageUnpacker u) throws IOException {
        if (u.hasNext()) {
            throw new BadCall("bad_call", "a request frame holds more than its array");
        }
    }

    private void expectArguments(MessageUnpacker u, int count, String call) {
        if (arguments != count) {
            throw new BadCall("bad_call", call + " takes " + count + " arguments, not " + arguments);
        }
    }

    private void readActions(MessageUnpacker u) throws IOException {
        if (u.getNextFormat().getValueType() != ValueType.BINARY) {
            throw new BadCall("value", "the actions are a binary of float32");
        }
        int length = u.unpackBinaryHeader();
        if (length != actionBytes.length) {
            throw new BadCall("value", "actions of " + length + " bytes; this batch takes " + actionBytes.length + " ("
                    + batch.count() + " worlds x " + batch.robots() + " robots x " + batch.actionFields()
                    + " float32)");
        }
        u.readPayload(actionBytes);
        int fields = batch.actionFields();
        for (int i = 0; i < actions.length; i++) { // (all checked before any is taken)
            float v = (float) FLOAT.get(actionBytes, i * 4);
            if (!Float.isFinite(v)) {
                int robot = (i / fields) % batch.robots();
                throw new BadCall("value", "world " + i / fields / batch.robots() + ", robot "
                        + batch.spec().robots().get(robot).name() + ": action field " + i % fields + " is " + v);
            }
        }
        for (int i = 0; i < actions.length; i++) {
            float v = (float) FLOAT.get(actionBytes, i * 4);
            int field = i % fields;
            if (field < BatchWorlds.VELOCITIES) {
                double max = limits[(i / fields) % batch.robots()][field];
                v = (float) Math.max(-max, Math.min(max, v));
            } else if (field >= BatchWorlds.VELOCITIES + batch.messageSize()) {
                v = batch.actuatorColumns().held((i / fields) % batch.robots(), field, v);
            }
            actions[i] = v;
        }
    }

    private void readResets(MessageUnpacker u) throws IOException {
        java.util.Arrays.fill(reset, false);
        if (u.tryUnpackNil()) {
            return;
        }
        if (u.getNextFormat().getValueType() != ValueType.MAP) {
            throw new BadCall("value", "the resets are nil or a map world -> seed");
        }
        int n = u.unpackMapHeader();
        for (int i = 0; i < n; i++) {
            int w = world(u);
            seeds[w] = seed(u);
            reset[w] = true;
        }
    }

    private void readSeeds(MessageUnpacker u) throws IOException {
        if (u.getNextFormat().getValueType() != ValueType.ARRAY) {
            throw new BadCall("value", "the seeds are an array, one a world (a seed, or nil)");
        }
        int n = u.unpackArrayHeader();
        if (n != batch.count()) {
            throw new BadCall("value", n + " seeds for " + batch.count() + " worlds");
        }
        for (int w = 0; w < n; w++) {
            if (!u.tryUnpackNil()) {
                seeds[w] = seed(u);
                reset[w] = true;
            }
        }
    }

    private int world(MessageUnpacker u) throws IOException {
        if (u.getNextFormat().getValueType() != ValueType.INTEGER) {
            throw new BadCall("value", "a world is a number");
        }
        long w = u.unpackLong();
        if (w < 0 || w >= batch.count()) {
            throw new BadCall("value", "no world " + w + " (0 to " + (batch.count() - 1) + ")");
        }
        return (int) w;
    }

    private static long seed(MessageUnpacker u) throws IOException {
        if (u.getNextFormat().getValueType() != ValueType.INTEGER) {
            throw new BadCall("value", "a seed is a whole number");
        }
        try {
            return u.unpackLong();
        } catch (MessagePackException e) {
            throw new BadCall("value", "a seed is a signed 64-bit number");
        }
    }

    private void measure(MessageUnpacker u) throws IOException {
        if (batch.episodeMetric() == null) {
            throw new BadCall("bad_call", "this host measures no episode metric (--episode-metric)");
        }
        if (u.getNextFormat().getValueType() != ValueType.ARRAY) {
            throw new BadCall("value", "measure takes an array of worlds");
        }
        int n = u.unpackArrayHeader();
        if (n > batch.count()) {
            throw new BadCall("value", n + " worlds to measure of " + batch.count());
        }
        int[] which = new int[n];
        for (int i = 0; i < n; i++) {
            which[i] = world(u);
        }
        whole(u);
        double[] values = new double[n];
        for (int i = 0; i < n; i++) {
            try {
                values[i] = batch.measure(which[i]);
            } catch (VirtualMachineError e) {
                throw e;
            } catch (IOException | RuntimeException | Error e) { // (a metric class of one's own may throw anything)
                throw new BadCall("value", "metric " + batch.episodeMetric().name() + " of world " + which[i] + ": "
                        + LinkFrames.oneLine(e.toString()));
            }
        }
        reply.packArrayHeader(2).packString("ok").packArrayHeader(n);
        for (double v : values) {
            reply.packDouble(v);
        }
    }

    private void step(boolean act) throws IOException {
        try {
            batch.step(act ? actions : null, reset, seeds);
        } catch (IllegalStateException e) { // (a world that cannot go on: the learner is told, then the link ends)
            String why = LinkFrames.oneLine(e.getMessage());
            reply.clear();
            reply.packArrayHeader(3).packString("error").packString("failed").packString(why);
            LinkFrames.write(out, reply.toByteArray());
            throw new IOException(why, e);
        }
        if (watch != null) {
            watch.stepped();
        }
        stepsServed++;
        reply.packArrayHeader(2).packString("ok");
        boolean readings = batch.sensorColumns().width() > 0;
        boolean loop = batch.spec().loopFunctions() != null;
        reply.packMapHeader(5 + (batch.messageSize() > 0 ? 1 : 0) + (readings ? 1 : 0) + (loop ? 1 : 0));
        binary("steps", batch.steps());
        binary("sonar", batch.sonar());
        binary("pose", batch.pose());
        binary("contact", batch.contact());
        binary("metrics", batch.metrics());
        if (batch.messageSize() > 0) {
            binary("messages", batch.messages());
        }
        if (readings) {
            binary("readings", batch.readings());
        }
        if (loop) {
            binary("finished", batch.finished());
        }
    }

    private void binary(String name, byte[] bytes) throws IOException {
        reply.packString(name).packBinaryHeader(bytes.length);
        reply.addPayload(bytes); // (by reference, not copied: the frame's one copy is made before the next step)
    }

    private static void pack(MessageBufferPacker p, String s) {
        try {
            p.packString(s);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }


    /** A request answered with an error; the link goes on. */
    private static final class BadCall extends RuntimeException {
        private static final long serialVersionUID = 1L;
        private final String kind;

        BadCall(String kind, String why) {
            super(why, null, false, false);
            this.kind = kind;
        }
    }
}

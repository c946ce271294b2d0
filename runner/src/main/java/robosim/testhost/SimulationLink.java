package robosim.testhost;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.Socket;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.msgpack.core.MessageBufferPacker;
import org.msgpack.core.MessagePack;
import org.msgpack.core.MessagePackException;
import org.msgpack.core.MessageUnpacker;
import org.msgpack.value.Value;
import robosim.hardware.ControlFailure;
import robosim.hardware.link.RobotLink;
import robosim.protocol.Printable;
import robosim.protocol.link.LinkFrames;
import robosim.protocol.link.LinkHello;
import robosim.testkit.Contact;
import robosim.testkit.Pose;
import robosim.testkit.Received;
import robosim.testkit.Simulation;

/**
 * The simulation link (python/README.md, "Testing controllers"): a tester in another process (Python's
 * {@code robosim.testing}) starts simulations of the testkit ({@link Simulation}) in this JVM, steps them and asks
 * them what the Java testkit answers, over one connection in the robot link's frames ({@link LinkFrames}): a hello
 * {@code {link: "robosim-simulation-link", version: 1, key}} ({@link LinkHello}), the welcome, then one request
 * {@code [CALL, ARG...]} and one answer at a time:
 * <ul>
 * <li>{@code ["start", {world, params, seed, expect_failure, step_timeout_ms, pose_log, history}]}: the environment
 * file {@code world} (a path), its parameters (a map of texts), the seed (or nil: the file's), the robots whose control
 * code may fail (an array), the step timeout (or nil: 10 s), a new file for the poses of the steps {@code drive} runs
 * ({@code --pose-log}'s CSV; or nil), whether to keep every message and contact for {@code received} and
 * {@code contacts} (a boolean, or nil: true; the ROS 2 bridge keeps none). Its robots whose control is {@code ros2} are driven by the link
 * ({@link DrivenRobot}). Answer {@code ["ok", {id, robots}]};
 * <li>{@code ["run", ID, N]}: N more steps (a world with driven robots: refused). Answer {@code ["ok", STEPS]}, or,
 * when control code failed (a robot not expected to, each said once), {@code ["failed", [FAILURE, ...], STEPS]};
 * <li>{@code ["drive", ID, {ROBOT: [MM_PER_S, DEG_PER_S], ...}]}: one step, each driven robot at its command (one
 * not named stands still). Answer {@code ["ok", FRAME]} (the ROS 2 bridge's step,
 * {@link robosim.runner.BridgeFrames}), or {@code ["failed", ...]} as {@code run}'s;
 * <li>{@code ["world", ID]}: the world as the ROS 2 bridge needs it ({@link robosim.runner.BridgeFrames}).
 * <li>{@code ["steps", ID]}, {@code ["robots", ID]}, {@code ["pose", ID, ROBOT]} ({@code [x_mm, y_mm, heading_deg]}),
 * {@code ["sonar", ID, ROBOT]}, {@code ["reading", ID, ROBOT, SENSOR]} (nil if none), {@code ["received", ID, ROBOT]}
 * ({@code [[step, from, text], ...]}), {@code ["contacts", ID, ROBOT]} ({@code [[step, with], ...]}),
 * {@code ["failure", ID, ROBOT]} (FAILURE or nil), {@code ["reports", ID, ROBOT]} (a map),
 * {@code ["metric", ID, NAME]}, {@code ["metrics", ID]} (a map), {@code ["ended", ID, ROBOT]} (a text or nil),
 * {@code ["viewer_port", ID]}: {@code ["ok", VALUE]};
 * <li>{@code ["close", ID]}: the simulation ends. Answer {@code ["ok", nil]} or {@code ["failed", [FAILURE, ...],
 * STEPS]};
 * <li>{@code ["headless", {args, log, recording}]}: a headless run, {@code headless.sh ARGS} in this JVM as a sweep's
 * warm worker runs one ({@code robosim.runner.RunHost}), its output into the file {@code log}, its metrics from the
 * recording {@code recording} (a path, or nil) if the arguments make it. Answer {@code ["ok", {exit_code, broke,
 * error, summary, metrics}]}: {@code broke} says why this host takes no more headless runs (the run left something
 * running), or nil;
 * <li>{@code ["bye"]}: every simulation still open ends; answer {@code ["ok", nil]}, and the link ends.
 * </ul>
 * FAILURE is a map {@code {robot, step, summary, account}}: the account a Python controller's traceback, or a Java
 * stack trace. A request that is not one, a robot or simulation there is not, or a file that cannot be read, is
 * answered {@code ["error", KIND, WHY]} (kinds {@code bad_call}, {@code value}; {@code failed}: the call failed
 * inside, a run's log that cannot be written, a fault of RoboSim's), and the link goes on; so is an answer over
 * the frame's bound.
 */
final class SimulationLink {
    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(SimulationLink.class);
    /** The fields a start's map may have (the class comment says what each is). */
    private static final List<String> START_FIELDS = List.of("world", "params", "seed", "expect_failure",
            "step_timeout_ms", "pose_log", "history");
    static final String NAME = "robosim-simulation-link";
    static final int VERSION = 1;
    /** The most simulations open at once. */
    static final int MAX_OPEN = 64;
    private static final LinkHello.Link HELLO = new LinkHello.Link(NAME, "simulation link", VERSION, "tester",
            List.of());

    private final Socket socket;
    private final DataInputStream in;
    private final DataOutputStream out;
    private final Map<Long, Open> open = new LinkedHashMap<>();
    private long next = 1;
    private long served;
    /** Headless runs in this JVM, one at a time, as a sweep's warm worker runs them (the user's control classes). */
    private final robosim.runner.RunHost runs = new robosim.runner.RunHost(
            robosim.runner.ControlClassLoader.entries(System.getenv("ROBOSIM_CLASSPATH")));
    /** Why this host runs no more headless runs (one left something running), or null. */
    private String broke;

    /**
     * An open simulation, the robots whose control code may fail, the robots whose failure was said, and the robots
     * the link drives ({@code control="ros2"}), by name.
     */
    private record Open(Simulation sim, Set<String> expected, Set<String> said, Map<String, DrivenRobot> driven,
            robosim.runner.PoseLog poseLog) {
    }

    /** A headless run that could not be made (its log not writable): answered {@code ["error", "failed", why]}. */
    private static final class HeadlessFailed extends Exception {
        private static final long serialVersionUID = 1L;

        HeadlessFailed(IOException cause) {
            super(cause);
        }
    }

    /** A request the link cannot take: answered {@code ["error", kind, message]}. */
    private static final class BadCall extends RuntimeException {
        private static final long serialVersionUID = 1L;
        final String kind;

        BadCall(String kind, String why) {
            super(why, null, false, false);
            this.kind = kind;
        }
    }

    SimulationLink(Socket socket) throws IOException {
        this.socket = socket;
        this.in = new DataInputStream(new BufferedInputStream(socket.getInputStream()));
        this.out = new DataOutputStream(new BufferedOutputStream(socket.getOutputStream()));
    }

    /**
     * The hello, checked ({@code key}: the secret the tester was given), then the welcome.
     *
     * @throws robosim.protocol.ProtocolException the refusal (answered why where it came)
     */
    void welcome(String key) throws IOException {
        LinkHello.read(HELLO, socket, in, out, key);
        MessageBufferPacker p = MessagePack.newDefaultBufferPacker();
        p.packMapHeader(2).packString("link").packString(NAME).packString("version").packInt(VERSION);
        LinkFrames.write(out, p.toByteArray());
    }

    /** Serves requests until the tester says bye or closes the link; every simulation it left open ends. */
    long serve() throws IOException {
        try {
            while (true) {
                byte[] frame = LinkFrames.read(in);
                if (frame == null) {
                    return served;
                }
                served++;
                MessageBufferPacker reply = MessagePack.newDefaultBufferPacker();
                boolean bye = false;
                try (MessageUnpacker u = MessagePack.newDefaultUnpacker(frame)) {
                    Value request = u.unpackValue();
                    if (u.hasNext()) {
                        throw new BadCall("bad_call", "a request frame holds more than its array");
                    }
                    bye = answer(request, reply);
                } catch (BadCall e) {
                    reply.clear();
                    reply.packArrayHeader(3).packString("error").packString(e.kind)
                            .packString(LinkFrames.oneLine(e.getMessage()));
                } catch (IllegalArgumentException | IllegalStateException e) { // (the testkit's refusals)
                    reply.clear();
                    reply.packArrayHeader(3).packString("error").packString("value")
                            .packString(LinkFrames.oneLine(String.valueOf(e.getMessage())));
                } catch (MessagePackException e) {
                    reply.clear();
                    reply.packArrayHeader(3).packString("error").packString("bad_call")
                            .packString("a request that is not one: " + LinkFrames.oneLine(e.getMessage()));
                } catch (RuntimeException | HeadlessFailed e) { // (a fault of the call's, not of the link: it goes on)
                    reply.clear();
                    reply.packArrayHeader(3).packString("error").packString("failed")
                            .packString(LinkFrames.oneLine(e.getCause() != null ? e.getCause().toString() : e.toString()));
                }
                if (reply.getBufferSize() > LinkFrames.MAX_BYTES) {
                    reply.clear();
                    reply.packArrayHeader(3).packString("error").packString("value").packString("the answer is over "
                            + "the link's " + LinkFrames.MAX_BYTES + " bytes (ask for less: received and contacts "
                            + "hold the whole run so far)");
                }
                LinkFrames.write(out, reply.toByteArray());
                if (bye) {
                    return served;
                }
            }
        } finally {
            for (Open o : open.values()) {
                close(o);
            }
            open.clear();
        }
    }

    /** Packs the answer to {@code request} into {@code reply}; true if it is the bye. */
    private boolean answer(Value request, MessageBufferPacker reply) throws IOException, HeadlessFailed {
        if (!request.isArrayValue() || request.asArrayValue().size() == 0
                || !request.asArrayValue().get(0).isStringValue()) {
            throw new BadCall("bad_call", "a request is an array [CALL, ARG...]");
        }
        List<Value> args = request.asArrayValue().list();
        String call = args.get(0).asStringValue().asString();
        switch (call) {
            case "start" -> {
                arguments(args, 1, "start: [\"start\", {" + String.join(", ", START_FIELDS) + "}]");
                long id = start(args.get(1));
                Open o = open.get(id);
                reply.packArrayHeader(2).packString("ok").packMapHeader(2);
                reply.packString("id").packLong(id);
                reply.packString("robots");
                packTexts(reply, o.sim().robots());
            }
            case "run" -> {
                arguments(args, 2, "run: [\"run\", ID, N]");
                Open o = opened(args.get(1));
                long n = whole(args.get(2), "N");
                if (!o.driven().isEmpty()) {
                    throw new BadCall("value", "run: robots " + o.driven().keySet() + " are driven by the link "
                            + "(control ros2): step this world with drive");
                }
                List<ControlFailure> failed = new ArrayList<>();
                try {
                    o.sim().run(n);
                } catch (AssertionError e) { // (control code failed: the testkit says it once; so do we, all of it)
                    failed.addAll(unsaid(o));
                }
                failed.addAll(unsaid(o));
                packOutcome(reply, o, failed);
            }
            case "drive" -> {
                arguments(args, 2, "drive: [\"drive\", ID, {ROBOT: [MM_PER_S, DEG_PER_S], ...}]");
                drive(opened(args.get(1)), args.get(2), reply);
            }
            case "close" -> {
                arguments(args, 1, "close: [\"close\", ID]");
                Open o = opened(args.get(1));
                open.remove(args.get(1).asIntegerValue().toLong());
                List<ControlFailure> failed = close(o);
                if (failed.isEmpty()) {
                    reply.packArrayHeader(2).packString("ok").packNil();
                } else {
                    packOutcome(reply, o, failed);
                }
            }
            case "headless" -> {
                arguments(args, 1, "headless: [\"headless\", {args, log, recording}]");
                headless(args.get(1), reply);
            }
            case "bye" -> {
                arguments(args, 0, "bye: [\"bye\"]");
                reply.packArrayHeader(2).packString("ok").packNil();
                return true;
            }
            default -> {
                if (args.size() < 2) {
                    throw new BadCall("bad_call", "no call \"" + Printable.of(call, 40) + "\" without a simulation "
                            + "(start, run, drive, steps, robots, world, pose, sonar, reading, received, contacts, "
                            + "failure, reports, metric, metrics, ended, viewer_port, close, headless, bye)");
                }
                Simulation sim = opened(args.get(1)).sim();
                reply.packArrayHeader(2).packString("ok");
                ask(call, args, sim, reply);
            }
        }
        return false;
    }

    /** Packs what {@code call} asks of {@code sim} (a question that changes nothing). */
    private static void ask(String call, List<Value> args, Simulation sim, MessageBufferPacker reply)
            throws IOException {
        switch (call) {
            case "steps" -> {
                arguments(args, 1, "steps: [\"steps\", ID]");
                reply.packLong(sim.steps());
            }
            case "robots" -> {
                arguments(args, 1, "robots: [\"robots\", ID]");
                packTexts(reply, sim.robots());
            }
            case "metrics" -> {
                arguments(args, 1, "metrics: [\"metrics\", ID]");
                packNumbers(reply, sim.metrics());
            }
            case "metric" -> {
                arguments(args, 2, "metric: [\"metric\", ID, NAME]");
                reply.packDouble(sim.metric(text(args.get(2), "NAME")));
            }
            case "viewer_port" -> {
                arguments(args, 1, "viewer_port: [\"viewer_port\", ID]");
                reply.packInt(sim.viewerPort());
            }
            case "world" -> {
                arguments(args, 1, "world: [\"world\", ID]");
                world(sim, reply);
            }
            case "reading" -> {
                arguments(args, 3, "reading: [\"reading\", ID, ROBOT, SENSOR]");
                double[] r = sim.reading(text(args.get(2), "ROBOT"), text(args.get(3), "SENSOR"));
                if (r == null) {
                    reply.packNil();
                } else {
                    packDoubles(reply, r);
                }
            }
            default -> askOfRobot(call, args, sim, reply);
        }
    }

    /** Packs what {@code call} asks of one robot of {@code sim}. */
    private static void askOfRobot(String call, List<Value> args, Simulation sim, MessageBufferPacker reply)
            throws IOException {
        if (args.size() != 3) {
            throw new BadCall("bad_call", "no call \"" + Printable.of(call, 40) + "\" of " + (args.size() - 1)
                    + " arguments (a robot's: pose, sonar, received, contacts, failure, reports, ended, with ID and "
                    + "ROBOT)");
        }
        String robot = text(args.get(2), "ROBOT");
        switch (call) {
            case "pose" -> {
                Pose p = sim.pose(robot);
                reply.packArrayHeader(3).packDouble(p.xMm()).packDouble(p.yMm()).packDouble(p.headingDeg());
            }
            case "sonar" -> packDoubles(reply, sim.sonar(robot));
            case "received" -> {
                List<Received> all = sim.received(robot);
                reply.packArrayHeader(all.size());
                for (Received r : all) {
                    reply.packArrayHeader(3).packLong(r.step()).packString(r.from()).packString(r.text());
                }
            }
            case "contacts" -> {
                List<Contact> all = sim.contacts(robot);
                reply.packArrayHeader(all.size());
                for (Contact c : all) {
                    reply.packArrayHeader(2).packLong(c.step()).packString(c.with());
                }
            }
            case "failure" -> {
                ControlFailure f = sim.failure(robot);
                if (f == null) {
                    reply.packNil();
                } else {
                    packFailure(reply, f);
                }
            }
            case "reports" -> packNumbers(reply, sim.reports(robot));
            case "ended" -> {
                String end = sim.ended(robot);
                if (end == null) {
                    reply.packNil();
                } else {
                    reply.packString(end);
                }
            }
            default -> throw new BadCall("bad_call", "no call \"" + Printable.of(call, 40) + "\" (start, run, drive, "
                    + "steps, robots, world, pose, sonar, reading, received, contacts, failure, reports, metric, "
                    + "metrics, ended, viewer_port, close, headless, bye)");
        }
    }

    /**
     * A headless run ({@code headless.sh ARGS}, the runner in this JVM, as a sweep's warm worker runs one: its
     * control classes loaded afresh, its output into {@code log}), then what it gave: its exit code, the summary
     * line's fields, its metrics (every built-in one and every report, from {@code recording} when the run made
     * it) and, for a run that failed, its reason. A run that left something running (threads, control code) is
     * {@code broke}: this host runs no more headless runs after it.
     */
    private void headless(Value spec, MessageBufferPacker reply) throws IOException, HeadlessFailed {
        if (broke != null) {
            throw new BadCall("value", "this host runs no more headless runs: " + broke);
        }
        if (!spec.isMapValue()) {
            throw new BadCall("bad_call", "headless takes a map {args, log, recording}");
        }
        Map<String, Value> fields = new LinkedHashMap<>();
        for (Map.Entry<Value, Value> e : spec.asMapValue().entrySet()) {
            String name = text(e.getKey(), "a field's name");
            if (!List.of("args", "log", "recording").contains(name)) {
                throw new BadCall("bad_call", "headless: no field \"" + Printable.of(name, 40) + "\" (args, log, "
                        + "recording)");
            }
            fields.put(name, e.getValue());
        }
        Value given = fields.get("args");
        if (given == null || !given.isArrayValue()) {
            throw new BadCall("bad_call", "headless: args is an array of texts (headless.sh's arguments)");
        }
        List<String> runArgs = new ArrayList<>();
        for (Value v : given.asArrayValue()) {
            runArgs.add(text(v, "an argument"));
        }
        Path log = Path.of(text(fields.get("log"), "log"));
        Value rec = fields.get("recording");
        Path recording = rec == null || rec.isNilValue() ? null : Path.of(text(rec, "recording"));
        robosim.runner.HeadlessRuns.Ended ended;
        robosim.runner.RunLog lines;
        try {
            ended = runs.run(runArgs, log);
            broke = ended.broke();
            lines = robosim.runner.RunLog.read(log);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted during a headless run", e);
        } catch (IOException e) { // (the log could not be written or read: the call's failure, not the link's)
            throw new HeadlessFailed(e);
        }
        Map<String, Double> metrics = Map.of();
        String error = ended.broke() != null ? ended.broke() : ended.code() == 0 ? "" : lines.lastError();
        if (recording != null && java.nio.file.Files.exists(recording)) {
            try {
                metrics = robosim.sweep.RunMetrics.of(recording, List.of(), robosim.sweep.RunMetrics.DEFAULT_AREA_CELL_M);
            } catch (IOException | RuntimeException e) {
                error = error.isEmpty() ? "metrics: " + e.getMessage() : error;
            }
        }
        reply.packArrayHeader(2).packString("ok").packMapHeader(5);
        reply.packString("exit_code").packInt(ended.code());
        reply.packString("broke");
        if (ended.broke() == null) {
            reply.packNil();
        } else {
            reply.packString(ended.broke());
        }
        reply.packString("error").packString(LinkFrames.oneLine(error));
        Map<String, String> summary = lines.summary();
        reply.packString("summary").packMapHeader(summary.size());
        for (Map.Entry<String, String> e : summary.entrySet()) {
            reply.packString(e.getKey()).packString(e.getValue());
        }
        reply.packString("metrics");
        packNumbers(reply, metrics);
    }

    private long start(Value spec) {
        if (open.size() >= MAX_OPEN) {
            throw new BadCall("value", MAX_OPEN + " simulations are open: close one first");
        }
        if (!spec.isMapValue()) {
            throw new BadCall("bad_call", "start takes a map {" + String.join(", ", START_FIELDS) + "}");
        }
        Map<String, Value> fields = new LinkedHashMap<>();
        for (Map.Entry<Value, Value> e : spec.asMapValue().entrySet()) {
            String name = text(e.getKey(), "a field's name");
            if (!START_FIELDS.contains(name)) {
                throw new BadCall("bad_call", "start: no field \"" + Printable.of(name, 40) + "\" ("
                        + String.join(", ", START_FIELDS) + ")");
            }
            fields.put(name, e.getValue());
        }
        if (!fields.containsKey("world")) {
            throw new BadCall("bad_call", "start: no world (an environment file's path)");
        }
        Simulation.Builder b = Simulation.of(Path.of(text(fields.get("world"), "world")));
        Value params = fields.get("params");
        if (params != null && !params.isNilValue()) {
            if (!params.isMapValue()) {
                throw new BadCall("bad_call", "start: params is a map of names to texts");
            }
            for (Map.Entry<Value, Value> e : params.asMapValue().entrySet()) {
                b.param(text(e.getKey(), "a parameter's name"), text(e.getValue(), "a parameter's value"));
            }
        }
        Value seed = fields.get("seed");
        if (seed != null && !seed.isNilValue()) {
            b.seed(whole(seed, "seed"));
        }
        Set<String> expected = new HashSet<>();
        Value expect = fields.get("expect_failure");
        if (expect != null && !expect.isNilValue()) {
            if (!expect.isArrayValue()) {
                throw new BadCall("bad_call", "start: expect_failure is an array of robots' names");
            }
            for (Value v : expect.asArrayValue()) {
                String robot = text(v, "a robot's name");
                b.expectFailure(robot);
                expected.add(robot);
            }
        }
        Value timeout = fields.get("step_timeout_ms");
        if (timeout != null && !timeout.isNilValue()) {
            b.stepTimeout(Duration.ofMillis(whole(timeout, "step_timeout_ms")));
        }
        Value history = fields.get("history");
        if (history != null && !history.isNilValue()) {
            if (!history.isBooleanValue()) {
                throw new BadCall("bad_call", "start: history is true or false");
            }
            b.history(history.asBooleanValue().getBoolean());
        }
        Map<String, DrivenRobot> driven = new LinkedHashMap<>();
        b.controls(r -> {
            if (!robosim.protocol.ControlScripts.isRos2(r.control())) {
                return null;
            }
            DrivenRobot d = new DrivenRobot(r.name(), r.type(), r.sensors());
            driven.put(r.name(), d);
            return d;
        });
        Value log = fields.get("pose_log");
        robosim.runner.PoseLog poseLog = null;
        if (log != null && !log.isNilValue()) {
            Path file = Path.of(text(log, "pose_log"));
            try {
                poseLog = new robosim.runner.PoseLog(file, java.nio.file.StandardOpenOption.CREATE_NEW,
                        java.nio.file.StandardOpenOption.WRITE);
            } catch (IOException e) {
                throw new BadCall("value", "start: the pose log " + Printable.of(file.toString(), 200)
                        + " cannot be made (" + (e instanceof java.nio.file.FileAlreadyExistsException
                        ? "it exists already" : Printable.of(String.valueOf(e.getMessage()), 200)) + ")");
            }
        }
        Simulation sim;
        try {
            sim = b.start();
        } catch (RuntimeException e) {
            closeQuietly(poseLog);
            throw e;
        }
        if (poseLog != null) {
            poseLog.names(sim.robots());
        }
        long id = next++;
        open.put(id, new Open(sim, expected, new HashSet<>(), driven, poseLog));
        return id;
    }

    /** Packs the world as the ROS 2 bridge needs it ({@link robosim.runner.BridgeFrames#world}). */
    private static void world(Simulation sim, MessageBufferPacker reply) throws IOException {
        robosim.environment.core.WorldSpec w = sim.world();
        List<robosim.runner.BridgeFrames.Robot> robots = new ArrayList<>();
        for (robosim.environment.core.WorldSpec.RobotSpec r : w.robots()) {
            robots.add(new robosim.runner.BridgeFrames.Robot(r.name(), robosim.devices.RobotTypes.properties(r.type()),
                    robosim.protocol.ControlScripts.isRos2(r.control()), r.sensors()));
        }
        robosim.runner.BridgeFrames.world(reply, w.timeStepMs(), w.arena(), w.obstacles(), robots);
    }

    /**
     * One step of {@code o}'s world with each driven robot's command (one not named stands still; a robot the link
     * does not drive, or a value that is not a finite number, is refused before anything is sent), answered with the
     * step's frame ({@link robosim.runner.BridgeFrames#step}: every robot's pose, each driven robot's state), or, when control code
     * failed, as {@code run} is.
     */
    private static void drive(Open o, Value commands, MessageBufferPacker reply) throws IOException {
        if (!commands.isMapValue()) {
            throw new BadCall("bad_call", "drive: the commands are a map {ROBOT: [MM_PER_S, DEG_PER_S], ...}");
        }
        Map<String, double[]> given = new LinkedHashMap<>();
        for (Map.Entry<Value, Value> e : commands.asMapValue().entrySet()) {
            String robot = text(e.getKey(), "a robot's name");
            if (!o.driven().containsKey(robot)) {
                throw new BadCall("value", "drive: " + Printable.of(robot, 40) + " is not a robot driven by the link "
                        + "(those whose control is ros2: " + o.driven().keySet() + ")");
            }
            Value v = e.getValue();
            if (!v.isArrayValue() || v.asArrayValue().size() != 2 || !finite(v.asArrayValue().get(0))
                    || !finite(v.asArrayValue().get(1))) {
                throw new BadCall("value", "drive: " + robot + "'s command is [MM_PER_S, DEG_PER_S], two finite "
                        + "numbers");
            }
            given.put(robot, new double[] {v.asArrayValue().get(0).asNumberValue().toDouble(),
                    v.asArrayValue().get(1).asNumberValue().toDouble()});
        }
        List<DrivenRobot> commanded = new ArrayList<>();
        for (DrivenRobot d : o.driven().values()) {
            if (o.sim().ended(d.name()) == null) { // (one that left takes no command: it would wait for ever)
                double[] c = given.getOrDefault(d.name(), new double[2]);
                d.command(c[0], c[1]);
                commanded.add(d);
            }
        }
        List<ControlFailure> failed = new ArrayList<>();
        try {
            o.sim().run(1);
        } catch (AssertionError e) {
            failed.addAll(unsaid(o));
        } catch (RuntimeException e) { // (the step did not run: its commands are taken back, for the next drive's)
            for (DrivenRobot d : commanded) {
                d.withdraw();
            }
            throw e;
        }
        failed.addAll(unsaid(o));
        Map<String, DrivenRobot.State> states = new LinkedHashMap<>();
        for (DrivenRobot d : commanded) {
            if (o.sim().ended(d.name()) == null) { // (a robot still in the world has its state within the step's time)
                try {
                    DrivenRobot.State s = d.state(STATE_WAIT_MS);
                    if (s != null) {
                        states.put(d.name(), s);
                    }
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                    throw new IOException("interrupted while a driven robot's state was awaited", e);
                }
            }
        }
        if (!failed.isEmpty()) {
            packOutcome(reply, o, failed);
            return;
        }
        List<String> names = o.sim().robots();
        double[] x = new double[names.size()];
        double[] y = new double[names.size()];
        double[] h = new double[names.size()];
        for (int i = 0; i < names.size(); i++) {
            Pose p = o.sim().pose(names.get(i));
            x[i] = p.xMm();
            y[i] = p.yMm();
            h[i] = p.headingDeg();
        }
        if (o.poseLog() != null) { // (buffered, as headless.sh's: written out as it fills and at the close)
            o.poseLog().update(new robosim.protocol.PoseUpdate(o.sim().steps() - 1, x, y, h));
        }
        reply.packArrayHeader(2).packString("ok");
        robosim.runner.BridgeFrames.step(reply, o.sim().steps(), x, y, h);
        reply.packMapHeader(states.size());
        for (Map.Entry<String, DrivenRobot.State> e : states.entrySet()) {
            DrivenRobot.State s = e.getValue();
            reply.packString(e.getKey());
            robosim.runner.BridgeFrames.state(reply, s.sonarMm(), s.readings(), o.driven().get(e.getKey()).sensors(),
                    s.received());
        }
    }

    /** How long a driven robot's state is awaited once its step is done, ms (its control thread reads its senses). */
    private static final long STATE_WAIT_MS = 10_000;

    private static boolean finite(Value v) {
        return v.isNumberValue() && Double.isFinite(v.asNumberValue().toDouble());
    }

    private static void closeQuietly(robosim.runner.PoseLog log) {
        if (log != null) {
            try {
                log.close();
            } catch (IOException e) {
                LOG.warn("the pose log could not be closed: {}", Printable.of(String.valueOf(e.getMessage()), 200));
            }
        }
    }

    /** Ends {@code o}'s simulation (and its pose log); the failures of its control code not said before. */
    private static List<ControlFailure> close(Open o) {
        closeQuietly(o.poseLog());
        List<ControlFailure> failed = new ArrayList<>();
        try {
            o.sim().close();
        } catch (AssertionError e) {
            failed.addAll(unsaid(o));
        }
        failed.addAll(unsaid(o));
        return failed;
    }

    /** The failures of {@code o}'s control code of robots not expected to fail, not said yet (now said). */
    private static List<ControlFailure> unsaid(Open o) {
        List<ControlFailure> fresh = new ArrayList<>();
        for (String robot : o.sim().robots()) {
            ControlFailure f = o.sim().failure(robot);
            if (f != null && !o.expected().contains(robot) && o.said().add(robot)) {
                fresh.add(f);
            }
        }
        return fresh;
    }

    private static void packOutcome(MessageBufferPacker reply, Open o, List<ControlFailure> failed) throws IOException {
        if (failed.isEmpty()) {
            reply.packArrayHeader(2).packString("ok").packLong(o.sim().steps());
            return;
        }
        reply.packArrayHeader(3).packString("failed").packArrayHeader(failed.size());
        for (ControlFailure f : failed) {
            packFailure(reply, f);
        }
        reply.packLong(o.sim().steps());
    }

    private static void packFailure(MessageBufferPacker reply, ControlFailure f) throws IOException {
        reply.packMapHeader(4);
        reply.packString("robot").packString(f.robot());
        reply.packString("step").packLong(f.step());
        reply.packString("summary").packString(f.summary());
        reply.packString("account").packString(account(f.thrown()));
    }

    /** What control code threw, whole: a controller's own account (a traceback), or a Java stack trace. */
    private static String account(Throwable thrown) {
        if (thrown instanceof RobotLink.ControllerFailure c) {
            return c.account();
        }
        StringWriter w = new StringWriter();
        thrown.printStackTrace(new PrintWriter(w));
        return w.toString();
    }

    private Open opened(Value id) {
        long n = whole(id, "ID");
        Open o = open.get(n);
        if (o == null) {
            throw new BadCall("value", "no simulation " + n + " is open");
        }
        return o;
    }

    private static void arguments(List<Value> args, int n, String shape) {
        if (args.size() != n + 1) {
            throw new BadCall("bad_call", shape);
        }
    }

    private static String text(Value v, String what) {
        if (v == null || !v.isStringValue()) {
            throw new BadCall("bad_call", what + " is a text");
        }
        return v.asStringValue().asString();
    }

    private static long whole(Value v, String what) {
        if (!v.isIntegerValue() || !v.asIntegerValue().isInLongRange()) {
            throw new BadCall("bad_call", what + " is a whole number");
        }
        return v.asIntegerValue().toLong();
    }

    private static void packTexts(MessageBufferPacker p, List<String> texts) throws IOException {
        p.packArrayHeader(texts.size());
        for (String t : texts) {
            p.packString(t);
        }
    }

    private static void packDoubles(MessageBufferPacker p, double[] values) throws IOException {
        p.packArrayHeader(values.length);
        for (double v : values) {
            p.packDouble(v);
        }
    }

    private static void packNumbers(MessageBufferPacker p, Map<String, Double> values) throws IOException {
        p.packMapHeader(values.size());
        for (Map.Entry<String, Double> e : values.entrySet()) {
            p.packString(e.getKey()).packDouble(e.getValue());
        }
    }
}

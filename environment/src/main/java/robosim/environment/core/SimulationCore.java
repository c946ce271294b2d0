package robosim.environment.core;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import robosim.devices.Drive;
import robosim.environment.metrics.MetricTally;
import robosim.environment.metrics.RunStart;
import robosim.environment.metrics.StepView;
import robosim.geometry.Kinematics;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.PoseUpdate;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotProperties;
import robosim.protocol.SensorReading;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * One simulated world and its step, the one every stepper runs (the Environment's {@code Run}, the learning host's
 * worlds, {@code bench/Engine.java}), as a straight sequence of phases ({@link #step}, like ARGoS's
 * {@code CSpace::Update}): gather (route COMMEVENTs, bound each ACTION by the robot's speed limits), resolve (the one
 * Geometry request of the step, every ACTION and SONAR request, resolved by a {@link Geometry}: in this process at
 * once, or by a Geometry process whose answer comes later, {@link #answer}), apply (poses from the distances Geometry
 * returns), tag, sense (sonar from the answer, the other SENSOR requests from each robot's {@code RobotSensor}s, on
 * the world after every move; noise from the world's one seeded generator, in robot order), respond; and, once the
 * step's responses have gone out, tally ({@link #tally}: the built-in metrics, {@link MetricTally}, count the step as
 * it went out). A world's loop functions ({@link ExperimentCode}) run before gather and after respond. Deterministic: the same world and the same requests give the same
 * responses, bit for bit. Not thread-safe; one caller.
 */
public final class SimulationCore {
    /**
     * What resolves a step's Geometry request: its answer, valid until the next request, or null when the answer
     * comes later (to {@link #answer}).
     */
    public interface Geometry {
        GeometryStepResponse resolve(GeometryStepRequest request);
    }

    private static final double EPS = 1e-9;
    /** Where loop functions a stepper did not start write their files. */
    private static final java.nio.file.Path WORKING_DIRECTORY = java.nio.file.Path.of("");

    private final EnvironmentMap map;
    private final MessageRouter router;
    private final StepSensing sensing;
    private final RobotActuators actuators;
    private int robots;
    private double[] maxMoveMm;
    private double[] maxTurnDeg;
    private int[] sonarCount;
    private int[] rayCount;
    /** Whether each robot slides along what blocks it (its type's {@code slides}). */
    private boolean[] slides;
    private GeometryStepRequest geometryRequest;
    private StepResponse[] responses;
    /** The requests of the step gathered and not yet completed. */
    private StepRequest[] pending;
    /** The requests of the last step completed (the caller's array; read by the tally only). */
    private StepRequest[] lastRequests;
    /**
     * Every distinct "tagger>target" so far, first time first (bounded by robots x (robots +
     * obstacles)); replaced, never changed, when a new pair appears.
     */
    private List<String> tags = List.of();
    private long lastStep = -1;
    /** The built-in metrics, counted step by step, and what they see of the last step. */
    private final MetricTally tally;
    private final StepView released = new Released();
    /** The world's loop functions ({@link LoopSpec}), or null for a world without. */
    private final ExperimentCode experiment;
    /** The robots the last step went out to, as its tally was told. */
    private java.util.function.IntPredicate wentOut = robot -> false;

    /** The world of {@code spec}, each robot as its {@code properties} say, its metrics not counted. */
    public SimulationCore(WorldSpec spec, List<RobotProperties> properties) {
        this(spec, properties, Double.NaN);
    }

    /**
     * The world of {@code spec}, each robot as its {@code properties} say, its built-in metrics counted at each
     * {@link #tally} (area in cells of {@code areaCellM}; NaN: not counted, {@link #tally} does nothing).
     */
    public SimulationCore(WorldSpec spec, List<RobotProperties> properties, double areaCellM) {
        this.map = new EnvironmentMap(spec, properties);
        this.robots = map.robotCount();
        Map<String, Integer> index = new HashMap<>();
        for (int i = 0; i < robots; i++) {
            index.put(map.name(i), i);
        }
        this.router = new MessageRouter(index, robots, spec.commRangeMm(), spec.maxMessageBytes());
        this.actuators = new RobotActuators(spec, properties);
        this.sensing = new StepSensing(spec, properties, map, actuators);
        this.maxMoveMm = new double[robots];
        this.maxTurnDeg = new double[robots];
        this.sonarCount = new int[robots];
        this.rayCount = new int[robots];
        this.slides = new boolean[robots];
        for (int i = 0; i < robots; i++) {
            limits(i, properties.get(i));
        }
        this.geometryRequest = new GeometryStepRequest(robots, map.objectCount());
        this.responses = new StepResponse[robots];
        this.tally = Double.isNaN(areaCellM) ? null : new MetricTally(new RunStart(spec.arena(), areaCellM, released));
        this.experiment = spec.loopFunctions() == null ? null
                : new ExperimentCode(spec.loopFunctions(), map, actuators, router, sensing);
    }

    /**
     * The world's loop functions begin (their init, before step 0), their own files going to {@code directory}: a new
     * instance of their class, or {@code kept} (the instance of an earlier run of the same world, null for none),
     * reset. A stepper that does not call this starts them in the working directory at step 0. Nothing for a world
     * without loop functions.
     *
     * @throws ExperimentFailure if they cannot be made, or throw
     */
    public void startExperiment(java.nio.file.Path directory, robosim.loop.LoopFunctions kept) {
        if (experiment != null) {
            experiment.start(directory, kept);
        }
    }

    /** The loop functions' instance (for a later run of the world to reset), or null. */
    public robosim.loop.LoopFunctions loopFunctions() {
        return experiment == null ? null : experiment.code();
    }

    /** What the loop functions drew in the last step completed (nothing: nothing, or no loop functions). */
    public robosim.protocol.Traces experimentTraces() {
        return experiment == null ? robosim.protocol.Traces.NONE : experiment.tracesOfStep();
    }

    /** The metrics the loop functions reported for the last step completed (none: none, or no loop functions). */
    public List<robosim.protocol.Report> experimentReports() {
        return experiment == null ? List.of() : experiment.reports();
    }

    /** Why the loop functions ended the run, after the last step completed; null while it goes on (or it has none). */
    public String experimentEnd() {
        return experiment == null ? null : experiment.endReason();
    }

    /**
     * The run is over: the loop functions' destroy, once.
     *
     * @throws ExperimentFailure if it throws
     */
    public void endExperiment() {
        if (experiment != null) {
            experiment.destroy();
        }
    }

    private void limits(int i, RobotProperties p) {
        double seconds = Drive.seconds(map.spec().timeStepMs());
        maxMoveMm[i] = Drive.perStep(p.maxSpeedMmPerS(), seconds);
        maxTurnDeg[i] = Drive.perStep(p.maxTurnDegPerS(), seconds);
        sonarCount[i] = p.sonars().size();
        rayCount[i] = p.rays().size();
        robosim.devices.RobotType type = robosim.devices.RobotTypes.known(p.type());
        slides[i] = type != null && type.slides();
    }

    /**
     * Robot {@code robot} joins the world at its spec's pose, between steps (none prepared): it is the last
     * in world order and takes part from the next step prepared. Returns its index.
     */
    public int add(WorldSpec.RobotSpec robot, RobotProperties p) {
        if (pending != null) {
            throw new IllegalStateException("a robot joins between steps only");
        }
        int i = map.add(robot, p);
        actuators.add(i, robot, p);
        sensing.add(i, robot, p);
        router.add(i, robot.name());
        robots = i + 1;
        maxMoveMm = java.util.Arrays.copyOf(maxMoveMm, robots);
        maxTurnDeg = java.util.Arrays.copyOf(maxTurnDeg, robots);
        sonarCount = java.util.Arrays.copyOf(sonarCount, robots);
        rayCount = java.util.Arrays.copyOf(rayCount, robots);
        slides = java.util.Arrays.copyOf(slides, robots);
        limits(i, p);
        geometryRequest = new GeometryStepRequest(robots, map.objectCount());
        StepResponse[] more = java.util.Arrays.copyOf(responses, robots);
        more[i] = new StepResponse(lastStep, 0, 0, "", robot.xMm(), robot.yMm(), robot.headingDeg(),
                StepSensing.none(), List.of(), List.of());
        responses = more;
        return i;
    }

    public EnvironmentMap map() {
        return map;
    }

    /**
     * Removes a robot from the world (kept once, in the {@link EnvironmentMap}): from the next step it
     * neither moves, blocks, echoes nor can be sensed or tagged, messages to it are refused (the sender
     * gets a notice), and viewers are told.
     */
    public void depart(int robot) {
        map.depart(robot);
        sensing.depart(robot);
        int held = map.carried(robot);
        if (held >= 0) {
            map.carry(held, -1); // (it stays where it was let go)
        }
    }

    /**
     * Robot {@code robot} is away but stays in the world ({@code --on-robot-loss HOLD} or {@code WAIT}): it
     * sends no request, so it stands still where it is, blocks and echoes; messages to it are kept for its
     * return ({@code away} false), when its first response carries them, in order.
     */
    public void away(int robot, boolean away) {
        router.away(robot, away);
        map.hold(robot, away);
    }

    /**
     * Robot {@code robot}'s response to the last step will not be sent (it left during the step): its
     * messages go back to its inbox, for its return, and its response (for viewers and the recording) says
     * that nothing reached it.
     */
    public void withhold(int robot) {
        StepResponse r = responses[robot];
        router.putBack(robot, r.inbox());
        responses[robot] = new StepResponse(r.step(), r.movedMm(), r.turnedDeg(), r.contact(), r.xMm(), r.yMm(),
                r.headingDeg(), r.sonarMm(), List.of(), List.of(), r.readings(), r.tagged()).withGripped(r.gripped());
    }

    /** Robot {@code robot} has joined and takes part from the next step: messages to it wait for it. */
    public void arriving(int robot) {
        router.away(robot, true);
    }

    /** True while robot {@code robot} takes part (it has not left). */
    public boolean present(int robot) {
        return !map.isGone(robot);
    }

    /**
     * Step {@code k} of the world: {@code requests[i]} is robot i's request, or null for a robot that sends none
     * (departed, or away): it stands still. The array is read until the step is complete, so it must not change in
     * between. Returns true once the step is complete ({@link #response(int)} holds each robot's answer), false when
     * {@code geometry} answers later: then the step completes at {@link #answer}.
     *
     * @throws ProtocolException if a request is not for step k or holds a non-finite number, or an answer at once
     *     is not a valid answer to the step's request
     * @throws ExperimentFailure if the world's loop functions throw
     */
    public boolean step(long k, StepRequest[] requests, Geometry geometry) throws ProtocolException {
        GeometryStepRequest request = gather(k, requests);
        GeometryStepResponse answer = geometry.resolve(request);
        if (answer == null) {
            return false;
        }
        answer(answer);
        return true;
    }

    /**
     * The rest of the step whose Geometry request was answered later: apply, tag, sense, respond (the tally is the
     * caller's, once the responses have gone out: {@link #tally}).
     *
     * @throws ProtocolException if {@code g} is not a valid answer to the step's Geometry request
     * @throws ExperimentFailure if the world's loop functions throw
     */
    public void answer(GeometryStepResponse g) throws ProtocolException {
        if (pending == null) {
            throw new IllegalStateException("no step waits for an answer");
        }
        GeometryAnswerCheck.check(geometryRequest, g, sonarCount, rayCount, map.spec().obstacles().size(),
                map.spec().arena(), map.spec().scenery().objects());
        StepRequest[] requests = pending;
        pending = null;
        lastRequests = requests;
        long k = geometryRequest.step();
        apply(g);
        sensing.stepped();
        String[] tagged = tag(requests);
        senseAndRespond(k, g, requests, tagged);
        lastStep = k;
        if (experiment != null) {
            experiment.postStep(k);
        }
    }

    /**
     * Gather: each robot's request checked (for step {@code k}, finite), its messages routed, its move and turn
     * bounded by its speed limits; the step's Geometry request, valid until the next step.
     */
    private GeometryStepRequest gather(long k, StepRequest[] requests) throws ProtocolException {
        if (experiment != null) {
            experiment.start(WORKING_DIRECTORY, null); // (once; a stepper that did not start it)
            experiment.preStep(k);
        }
        geometryRequest.setStep(k);
        for (int i = 0; i < robots; i++) {
            StepRequest q = requests[i];
            double move = 0;
            double turn = 0;
            int flags = 0;
            if (q != null) {
                if (q.step() != k) {
                    throw new ProtocolException(map.name(i) + " sent a request for step " + q.step() + " in step " + k);
                }
                move = bounded(i, "move", q.moveMm(), maxMoveMm[i], "mm");
                turn = bounded(i, "turn", q.turnDeg(), maxTurnDeg[i], "deg");
                flags |= q.wantsSonar() ? GeometryStepRequest.SONAR : 0;
                flags |= sensing.wantsRays(i, q.sensors()) ? GeometryStepRequest.RAYS : 0;
                flags |= gripper(i, q.gripper()) ? GeometryStepRequest.GRIP : 0;
                flags |= slides[i] ? GeometryStepRequest.SLIDE : 0;
                router.route(i, map.name(i), q.messages(), map);
                actuators.set(i, q.actuations(), router, map.name(i));
            }
            geometryRequest.set(i, map.xMm(i), map.yMm(i), map.headingDeg(i), turn, move, (byte) flags);
            if (map.isGone(i)) {
                geometryRequest.setAbsent(i);
            }
        }
        for (int o = 0; o < map.objectCount(); o++) {
            geometryRequest.setObject(o, map.objectXMm(o), map.objectYMm(o), map.objectHeadingDeg(o),
                    map.objectGone(o) ? GeometryStepRequest.GONE : map.carrier(o));
        }
        pending = requests;
        return geometryRequest;
    }

    /**
     * What robot i's gripper does this step: let go of what it holds at once ({@code RELEASE}); true when it is to
     * take what is in reach after the step's move ({@code GRIP}, and it has a gripper and holds nothing; else a
     * notice).
     */
    private boolean gripper(int i, StepRequest.Gripper asked) {
        if (asked == StepRequest.Gripper.STAY) {
            return false;
        }
        if (map.properties(i).gripper() == null) {
            router.notice(i, map.name(i) + " has no gripper");
            return false;
        }
        int held = map.carried(i);
        if (asked == StepRequest.Gripper.RELEASE) {
            if (held >= 0) {
                map.carry(held, -1);
            }
            return false;
        }
        return held < 0;
    }

    /**
     * Apply: each robot's pose from the distance moved and the angle turned that Geometry returns, each object's pose
     * as Geometry returns it, and what each gripper took.
     */
    private void apply(GeometryStepResponse g) {
        for (int i = 0; i < robots; i++) {
            double h = Kinematics.turn(map.headingDeg(i), g.turnedDeg(i));
            double moved = g.movedMm(i);
            map.setPose(i, map.xMm(i) + Kinematics.dx(h, moved), map.yMm(i) + Kinematics.dy(h, moved), h);
        }
        for (int k = 0; k < g.slideCount(); k++) { // (a wheeled swarm robot's slide along what blocked it)
            int i = g.slideRobot(k);
            map.setPose(i, map.xMm(i) + g.slideXMm(k), map.yMm(i) + g.slideYMm(k), map.headingDeg(i));
        }
        for (int o = 0; o < map.objectCount(); o++) {
            map.setObjectPose(o, g.objectXMm(o), g.objectYMm(o), g.objectHeadingDeg(o));
        }
        for (int k = 0; k < g.gripCount(); k++) {
            if (g.gripObject(k) >= 0) {
                map.carry(g.gripObject(k), g.gripRobot(k));
            }
        }
    }

    /**
     * Sense (sonar from the answer, the plug-in sensors on the world after every move) and respond: each robot's
     * response to step {@code k}, with its messages and notices.
     */
    private void senseAndRespond(long k, GeometryStepResponse g, StepRequest[] requests, String[] tagged) {
        int range = 0;
        int ray = 0;
        for (int i = 0; i < robots; i++) {
            double[] sonar = StepSensing.none();
            if (geometryRequest.wantsSonar(i)) {
                sonar = sensing.sonar(i, g, range);
                range += sonarCount[i];
            }
            StepRequest q = requests[i];
            List<SensorReading> readings = q == null ? List.of() : sensing.read(i, q.sensors(), router, g, ray);
            if (geometryRequest.wantsRays(i)) {
                ray += rayCount[i];
            }
            StepResponse r = new StepResponse(k, g.movedMm(i), g.turnedDeg(i), contactName(g, i), map.xMm(i),
                    map.yMm(i), map.headingDeg(i), sonar, router.takeInbox(i), router.takeNotices(i), readings,
                    tagged == null || tagged[i] == null ? "" : tagged[i]);
            int held = map.carried(i);
            responses[i] = held < 0 ? r : r.withGripped(map.spec().scenery().objects().get(held).name());
        }
    }

    /** The tag ACTION, after every move: each tagger's nearest robot or obstacle in range, or null. */
    private String[] tag(StepRequest[] requests) {
        String[] tagged = null;
        for (int i = 0; i < robots; i++) {
            if (requests[i] != null && requests[i].wantsTag()) {
                if (tagged == null) {
                    tagged = new String[robots];
                }
                tagged[i] = Tags.nearest(map, i, map.spec().tagRangeMm());
                String pair = map.name(i) + ">" + tagged[i];
                if (!tagged[i].isEmpty() && !tags.contains(pair)) {
                    List<String> more = new ArrayList<>(tags);
                    more.add(pair);
                    tags = List.copyOf(more);
                }
            }
        }
        return tagged;
    }

    private double bounded(int robot, String what, double value, double max, String unit) throws ProtocolException {
        if (!Double.isFinite(value)) {
            throw new ProtocolException(map.name(robot) + " asked to " + what + " by " + value);
        }
        if (Math.abs(value) > max + EPS) {
            router.notice(robot, what + " of " + value + " " + unit + " limited to " + max + " " + unit
                    + " per step by the robot's speed limit");
            return Math.copySign(max, value);
        }
        return value;
    }

    private String contactName(GeometryStepResponse g, int robot) {
        int index = g.contactIndex(robot);
        return switch (g.contactKind(robot)) {
            case GeometryStepResponse.CONTACT_ROBOT -> map.name(index);
            case GeometryStepResponse.CONTACT_OBSTACLE -> map.spec().obstacles().get(index).name();
            case GeometryStepResponse.CONTACT_ARENA -> "arena";
            case GeometryStepResponse.CONTACT_OBJECT -> map.spec().scenery().objects().get(index).name();
            default -> "";
        };
    }

    /**
     * The last step's poses and sonar ranges for viewers: a new immutable update (the ranges are
     * the responses' own arrays, which nobody changes).
     */
    public PoseUpdate viewerUpdate() {
        double[][] sonar = new double[robots][];
        for (int i = 0; i < robots; i++) {
            sonar[i] = responses[i].sonarMm();
        }
        PoseUpdate u = map.poses(lastStep, sonar, tags, actuators.leds());
        return experiment == null ? u : u.withExperiment(experiment.paint(), experiment.lightsNow(),
                experiment.reports(), experiment.tracesOfStep(), experiment.tracesWhole(), map.objectsGone());
    }

    /**
     * The world before step 0, as a viewer that joins then (and a recording's first snapshot) starts from: every robot's
     * and object's pose, and what the loop functions' init made of it: the floor's paint, the lights, the objects taken
     * out. Not their drawing: it comes with step 0's update, as to a viewer that was there before (and so once).
     */
    public PoseUpdate startUpdate() {
        PoseUpdate u = map.poses(-1);
        return experiment == null ? u : u.withExperiment(experiment.paint(), experiment.lightsNow(), List.of(),
                robosim.protocol.Traces.NONE, robosim.protocol.Traces.NONE, map.objectsGone());
    }

    /** The world before step 0 as a snapshot (a recording's first): {@link #startUpdate}'s. */
    public robosim.protocol.WorldSnapshot startSnapshot() {
        return EnvironmentMap.snapshot(map.spec(), map.properties(), startUpdate().posesOnly());
    }

    /** Every tag so far, "tagger>target", oldest first. */
    public List<String> tags() {
        return tags;
    }

    /** Robot i's response to the last step. */
    public StepResponse response(int robot) {
        return responses[robot];
    }

    /**
     * Tally: the built-in metrics count the last step as it went out to every robot that took part (its request was
     * in): the last phase of a step whose responses all go out as computed.
     */
    public void tally() {
        tally(robot -> lastRequests[robot] != null);
    }

    /**
     * Tally, for a stepper that releases the responses itself (the Environment's {@code Run}): the metrics count the
     * last step as it went out, to the robots {@code released} says took part in it, their responses as they went out
     * (a robot that left during the step took part, its move and its contact count, but a response withheld from it
     * delivered nothing: {@link #withhold}).
     */
    public void tally(java.util.function.IntPredicate released) {
        if (tally != null) {
            wentOut = released;
            tally.step(this.released);
        }
    }

    /** The built-in metrics of the run so far, as of the last {@link #tally}; null for a world that counts none. */
    public MetricTally metrics() {
        return tally;
    }

    /** The world after the last step (before the first: every robot at its start pose), as the metrics see it. */
    private final class Released implements StepView {
        @Override
        public int robots() {
            return robots;
        }

        @Override
        public double xMm(int robot) {
            return map.xMm(robot);
        }

        @Override
        public double yMm(int robot) {
            return map.yMm(robot);
        }

        @Override
        public boolean tookPart(int robot) {
            return lastStep >= 0 && wentOut.test(robot);
        }

        @Override
        public boolean touching(int robot) {
            return !responses[robot].contact().isEmpty();
        }

        @Override
        public int delivered(int robot) {
            return responses[robot].inbox().size();
        }

        @Override
        public int tags() {
            return tags.size();
        }

        @Override
        public int departed() {
            return map.departedCount();
        }
    }

    public long messagesDelivered() {
        return router.delivered();
    }

    /** Messages not delivered: unknown or departed recipient, or larger than the limit. */
    public long messagesUndeliverable() {
        return router.undeliverable() + router.tooLarge();
    }

    /** Messages dropped because the recipient was out of communication range. */
    public long messagesOutOfRange() {
        return router.outOfRange();
    }
}

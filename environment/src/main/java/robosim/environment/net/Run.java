package robosim.environment.net;

import robosim.protocol.Printable;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.core.JoinRule;
import robosim.environment.core.SimulationCore;
import robosim.environment.core.SpawnPlacer;
import robosim.environment.core.WorldSpec;
import robosim.environment.server.ViewerSink;
import robosim.environment.server.Viewers;
import robosim.protocol.Arena;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.Limits;
import robosim.protocol.PoseUpdate;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotProperties;
import robosim.protocol.RobotView;
import robosim.protocol.RobotWelcome;
import robosim.protocol.StepNumbers;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;
import robosim.protocol.WorldSnapshot;

/**
 * One simulation run, as its one owner of time, the {@link SimulationLoop}, drives it; loop thread only.
 * It alone holds the step, the phase and what has been released; its robots are a {@link Roster} of
 * {@link RobotSlot}s, each with its state.
 *
 * <p>Its life: {@code WAITING} for every robot the file names (each hello registered) and a Geometry
 * process; {@code STARTING} (the core is built, Geometry is sent the world); then each step in three
 * stages, {@link #advance} moving on as far as it can after every event:
 * <ol>
 * <li>{@code COLLECTING}: every running robot's request comes in ({@link #request});</li>
 * <li>{@code RESOLVING}: the core prepares the step and the {@link GeometryLink} resolves it (in-process at
 *     once, or Geometry's answer comes back as an event); the core completes it;</li>
 * <li>{@code RELEASING}: at the {@link ReleasePoint} (pause, step N, pace, a full recording viewer) every
 *     running robot gets its response with the next step number, viewers the poses, the recording the
 *     step; then departures held back during the step take effect and returning robots take part.</li>
 * </ol>
 * and {@code ENDED}, once, with the reason. Robots come and go between steps only: a robot lost, joining,
 * coming back or removed while a step is resolved or released changes the world at that step's end (a
 * hello waits for it), so the others' poses never depend on when a socket closed or a hello came.
 */
final class Run {
    private static final Logger LOG = LoggerFactory.getLogger(Run.class);

    /** Robots one run lets join, at most (each join grows the world and sends Geometry the world). */
    static final int MAX_JOINS = 10_000;
    /** Robots added from the control port and not joined yet, at most. */
    static final int MAX_ADDED = 64;

    enum Phase { WAITING, STARTING, COLLECTING, RESOLVING, RELEASING, ENDED }

    private final ClientWorkerCoordinator coordinator;
    private final Settings settings;
    private final WorldSpec spec;
    private final Admission admission;
    private final RunListener listener;
    private final Design design;
    private final PublishedRun record = new PublishedRun();
    private final Roster roster;
    private final GeometryLink geometry;
    private final RunControl control;
    private final Viewers viewers;
    private final ReleasePoint releasePoint;
    /** Shared connections with a frame to write once the loop has done what it does now. */
    private final SharedOutput output = new SharedOutput();
    /** The requests of robots in the Environment's JVM, on their way in. */
    private final InMemoryRequests inMemory;
    private final long stepTimeoutNanos;
    /** Hellos that came while a step was being resolved: answered once it is complete. */
    private final List<LoopEvent> heldHellos = new ArrayList<>();
    /** Robots whose departure waits for the end of the step under way, in the order they left. */
    private final List<RobotSlot> leaving = new ArrayList<>();
    /** Robots the control port added that have not joined yet, by name (read by robot workers' handshakes). */
    private final Map<String, JoinRule> added;

    private Phase phase = Phase.WAITING;
    private SimulationCore core;
    /** Steps computed so far: the step being collected or resolved is this one. */
    private long step;
    /** The steps whose responses have gone out. */
    private long released;
    /** When the last step's responses went out: robots are timed from here. */
    private long releasedNanos;
    /** Requests in for the step being collected. */
    private int arrived;
    private boolean beginHeld;
    private boolean robotsTold;
    private boolean toldEveryoneAway;
    /** Who is connected, or in which state, changed since the status last saw it. */
    private boolean rosterChanged = true;
    /** The world has grown since viewers and the recording last had a snapshot. */
    private boolean grown;
    private int joins;
    private SpawnPlacer placer;
    /** The run's recording, once it has begun ({@code --record}), else null. */
    private volatile RunRecorder recorder;

    Run(ClientWorkerCoordinator coordinator, RunListener listener) {
        this.coordinator = coordinator;
        this.settings = coordinator.settings();
        this.spec = coordinator.spec();
        this.admission = coordinator.admission();
        this.listener = listener;
        this.design = coordinator.design();
        this.added = admission.added();
        this.roster = new Roster(spec);
        this.geometry = new GeometryLink(settings);
        this.control = new RunControl(settings.speed(), spec.timeStepMs(), this::publishPhase);
        this.viewers = coordinator.viewers().list();
        this.inMemory = new InMemoryRequests(coordinator::post);
        this.releasePoint = new ReleasePoint(control, viewers, record, listener, settings.speed());
        this.stepTimeoutNanos = settings.stepTimeoutMs() <= 0 ? Long.MAX_VALUE : settings.stepTimeoutMs() * 1_000_000L;
    }

    // ---- what other threads read --------------------------------------------------------------------------

    /** What the loop publishes for other threads (status, summary). */
    PublishedRun record() {
        return record;
    }

    /** The run's viewers (their list is safe for any thread). */
    Viewers viewers() {
        return viewers;
    }

    /** The recording, once it has begun (any thread). */
    RunRecorder recorder() {
        return recorder;
    }

    /** Before the loop starts: hold before step 0 until resumed. */
    void startPaused() {
        control.startPaused();
    }

    // ---- the loop's questions -------------------------------------------------------------------------------

    boolean ended() {
        return phase == Phase.ENDED;
    }

    /** When the computed step may go out by the pace (ns), if it waits for it; else far in the future. */
    long paceDue() {
        return phase == Phase.RELEASING ? releasePoint.paceDue(step) : Long.MAX_VALUE;
    }

    /** True while requests of robots in this JVM wait to be applied: the loop advances again without waiting. */
    boolean busy() {
        return inMemory.pending();
    }

    /** Where the requests of robots in the Environment's JVM come in. */
    InMemoryRequests inMemory() {
        return inMemory;
    }

    /** The last request owed by robots in this JVM has come (or the last one owing has gone). */
    void inMemoryArrived() {
        inMemory.take(this);
    }

    /** True from the start until the end: a pause or step N acts on this run. */
    private boolean running() {
        return phase != Phase.WAITING && phase != Phase.ENDED;
    }

    private String name(int i) {
        return roster.get(i).name;
    }

    /** The index of the robot of this name in the world now, or -1. */
    private int indexOf(String robotName) {
        return core != null ? core.map().spec().indexOf(robotName) : spec.indexOf(robotName);
    }

    // ---- moving on ------------------------------------------------------------------------------------------

    /** Moves the run on as far as it can go now, then writes what shared connections were given. */
    void advance(long now) {
        move(now);
        if (inMemory.settle(this)) {
            move(now); // (what it gives now is applied at the next advance: the loop looks at its inbox between)
        }
        output.flush();
    }

    private void move(long now) {
        while (true) {
            switch (phase) {
                case WAITING -> {
                    if (roster.count(RobotSlot.State.CONNECTED) < roster.size() || !geometry.canStart()) {
                        return;
                    }
                    start();
                }
                case STARTING -> {
                    if (!geometry.ready() || !begin(now)) {
                        return;
                    }
                    startRecording(); // (before step 0 is computed: the world as it starts)
                }
                case COLLECTING -> {
                    int runningNow = roster.count(RobotSlot.State.RUNNING);
                    if (runningNow == 0 && !roster.anyAway()) {
                        finish("every robot has left", false);
                        return;
                    }
                    if (arrived < runningNow || roster.worldWaits(settings.onRobotLoss())) {
                        return;
                    }
                    if (runningNow == 0) {
                        waitForAnyone(); // (nobody to step for: the world waits for a robot to come back)
                        return;
                    }
                    resolve();
                }
                case RELEASING -> {
                    if (!releasePoint.pass(now, step, released)) {
                        return;
                    }
                    release();
                }
                default -> {
                    return; // RESOLVING waits for an event, ENDED is over
                }
            }
        }
    }

    private void start() {
        List<RobotProperties> properties = new ArrayList<>(roster.size());
        for (RobotSlot s : roster.all()) {
            properties.add(s.properties);
            roster.set(s, RobotSlot.State.RUNNING);
        }
        core = new SimulationCore(spec, properties);
        geometry.start(core.map().geometryWorld());
        phase = Phase.STARTING;
        rosterChanged = true;
        LOG.info("all {} robot(s) connected: running{}", roster.size(),
                settings.maxSteps() > 0 ? " for " + settings.maxSteps() + " steps" : "");
    }

    /** Sends every robot step 0, unless the run is to hold before it; true if the run has begun. */
    private boolean begin(long now) {
        if (control.holdWanted()) {
            if (!beginHeld) {
                beginHeld = true;
                control.held(released);
                coordinator.started();
                LOG.info("every client is here; paused before step 1 (start or step from the control port)");
                viewers.announce(new RunState(released, RunState.Phase.PAUSED));
            }
            return false;
        }
        if (beginHeld) {
            beginHeld = false;
            control.unheld(now, 0);
        }
        viewers.announce(new RunState(released, RunState.Phase.RUNNING));
        record.begin(now);
        control.restartPace(now, 0);
        releasedNanos = now;
        phase = Phase.COLLECTING;
        for (RobotSlot s : roster.all()) {
            if (s.running()) {
                try {
                    s.peer.begin(0);
                } catch (IOException e) {
                    s.peer.drop();
                    leave(s, "could not send it the first step: " + e.getMessage(), false);
                }
            }
        }
        bringBackReturning();
        design.begun(coordinator, roster);
        coordinator.started();
        listener.started(roster.size());
        return true;
    }

    // ---- stage 1: collecting -----------------------------------------------------------------------------

    /** A robot's request for the step being collected; one out of turn drops it. */
    void request(RobotPeer peer, StepRequest request) {
        RobotSlot s = roster.of(peer);
        if (s == null || !s.running() || phase == Phase.ENDED || core == null) {
            return; // gone already, or the run is over: nothing to do with it
        }
        if (phase != Phase.COLLECTING || request.step() != step || s.request != null) {
            peer.drop();
            leave(s, "sent a request for step " + request.step() + " out of turn (step " + step + " is due)", false);
            return;
        }
        s.request = request;
        arrived++;
    }

    // ---- stage 2: resolving ------------------------------------------------------------------------------

    private void resolve() {
        StepRequest[] batch = roster.takeRequests();
        arrived = 0;
        GeometryStepRequest prepared;
        try {
            prepared = core.prepare(step, batch);
        } catch (ProtocolException e) {
            finish("step " + StepNumbers.shown(step) + " failed: " + e.getMessage(), false);
            return;
        }
        phase = Phase.RESOLVING;
        GeometryStepResponse answer = geometry.resolve(prepared);
        if (answer != null) {
            complete(answer, null);
        }
    }

    /** Completes the step from an answer; {@code from}: the Geometry process that gave it, or null (in-process). */
    private void complete(GeometryStepResponse answer, GeometryClientWorker from) {
        try {
            core.complete(answer);
        } catch (ProtocolException e) {
            if (from == null) {
                finish("step " + StepNumbers.shown(step) + " failed: " + e.getMessage(), false);
            } else {
                geometryLost(from, "gave a bad answer: " + e.getMessage());
            }
            return;
        }
        geometry.resolved();
        roster.resolved();
        step++;
        phase = Phase.RELEASING;
    }

    String geometryJoins(GeometryClientWorker worker) {
        return phase == Phase.ENDED ? LoopEvent.OVER : geometry.join(worker);
    }

    void geometryReady(GeometryClientWorker worker) {
        int before = geometry.attaches();
        if (phase == Phase.RESOLVING) {
            control.restartPace(System.nanoTime(), step); // a step that waited for Geometry: no rush after
        }
        geometry.attached(worker);
        if (geometry.attaches() > before) {
            record.geometryAttaches = geometry.attaches();
            listener.geometryAttached(step);
        }
    }

    void geometryAnswer(GeometryClientWorker worker, GeometryStepResponse answer) {
        GeometryStepResponse a = geometry.answer(worker, answer);
        if (a != null && phase == Phase.RESOLVING) {
            complete(a, worker);
        }
    }

    void geometryLost(GeometryClientWorker worker, String why) {
        int before = geometry.losses();
        GeometryStepResponse a = geometry.lost(worker, Printable.of(why), step);
        if (geometry.losses() > before) {
            record.geometryLosses = geometry.losses();
            listener.geometryLost(step);
        }
        if (a != null && phase == Phase.RESOLVING) {
            complete(a, null);
        }
    }

    // ---- stage 3: releasing ------------------------------------------------------------------------------

    /** Every robot's response with the next step number (or the end), then the poses to every viewer. */
    private void release() {
        control.releasing();
        boolean last = settings.maxSteps() > 0 && step >= settings.maxSteps();
        SimulationEnd end = last ? new SimulationEnd(step - 1, "completed " + step + " steps") : null;
        if (last) {
            // the outcome is on record before any robot hears of it
            record.endReason = end.reason();
            record.completed = true;
        }
        List<RobotSlot> slots = roster.all();
        for (int i = 0; i < slots.size(); i++) { // (every step: no iterator)
            RobotSlot s = slots.get(i);
            if (!s.running()) {
                continue;
            }
            if (s.leaving != null) {
                core.withhold(s.index); // it left during this step: it goes at the step's end, and gets nothing more
                continue;
            }
            try {
                s.peer.deliver(core.response(s.index), step, end);
            } catch (IOException e) {
                s.peer.drop();
                core.withhold(s.index);
                leave(s, "could not send its response: " + e.getMessage(), false);
            }
        }
        long now = System.nanoTime();
        released = step;
        record.released(released, now);
        record.messages(core.messagesDelivered(), core.messagesOutOfRange(), core.messagesUndeliverable());
        RunRecorder rec = recorder;
        boolean recording = rec != null && rec.recording();
        if (!viewers.isEmpty() || recording) {
            PoseUpdate update = core.viewerUpdate();
            WorldSnapshot grownWorld = null;
            if (grown) {
                grown = false;
                grownWorld = core.map().snapshot(step - 1);
            }
            if (!viewers.isEmpty()) {
                viewers.publish(grownWorld, update, this::viewOf);
            }
            if (recording) {
                record(rec, grownWorld, update);
            }
        }
        releasedNanos = now;
        if (last) {
            robotsTold = true;
            finish(end.reason(), true);
        } else {
            phase = Phase.COLLECTING;
            applyLeaving();
            bringBackReturning();
            publish();
            control.settle(released, false); // (step N callers answered once the status shows the step's end)
        }
    }

    /**
     * The step just released, to the recording: the viewers' update, the requests and responses of those that
     * took part (one that left during it: what it asked, and that nothing reached it).
     */
    private void record(RunRecorder rec, WorldSnapshot grownWorld, PoseUpdate update) {
        StepRequest[] asked = new StepRequest[roster.size()];
        StepResponse[] responses = new StepResponse[roster.size()];
        for (RobotSlot s : roster.all()) {
            if (s.running()) {
                asked[s.index] = s.released;
                responses[s.index] = core.response(s.index);
            }
        }
        rec.step(grownWorld, update, asked, responses);
    }

    /** Robot i's view of the step just released, for a viewer that watches it; null if it did not take part. */
    private RobotView viewOf(int i) {
        if (i >= roster.size() || !roster.get(i).running()) {
            return null;
        }
        return RobotView.of(step - 1, i, name(i), roster.get(i).released, core.response(i));
    }

    // ---- deadlines -----------------------------------------------------------------------------------------

    /** Deadlines: a Geometry process late with its answer, robots late with requests. */
    void tick(long now) {
        inMemory.take(this); // (what has come is not late, whether or not everything owed is in)
        GeometryClientWorker late = geometry.overdue(now);
        if (late != null) {
            LOG.warn("Geometry process has not answered within {} ms (step {}); dropping it",
                    settings.geometryTimeoutMs(), StepNumbers.shown(step));
            geometryLost(late, "no answer within " + settings.geometryTimeoutMs() + " ms");
        }
        if (phase != Phase.COLLECTING) {
            return;
        }
        if (roster.count(RobotSlot.State.WAITED) > 0) {
            for (RobotSlot s : roster.all()) {
                if (s.state == RobotSlot.State.WAITED && now - s.awayNanos > stepTimeoutNanos) {
                    leaveWorld(s, "did not come back within " + settings.stepTimeoutMs() + " ms (step timeout)");
                }
            }
        }
        if (now - releasedNanos > stepTimeoutNanos) {
            for (RobotSlot s : roster.all()) {
                if (s.running() && s.request == null && (s.backNanos == 0 || now - s.backNanos > stepTimeoutNanos)) {
                    s.peer.drop();
                    leave(s, "sent no request for step " + StepNumbers.shown(step) + " within " + settings.stepTimeoutMs()
                            + " ms (step timeout)", false);
                    if (design.readsInWorldOrder()) {
                        break; // the stepper reads in world order: only the robot it waits for is late
                    }
                }
            }
        }
    }

    // ---- robots saying hello -------------------------------------------------------------------------------

    /** A robot's hello: answered now, or once the step being resolved is complete. */
    void hello(LoopEvent.RobotJoins j) {
        if (phase == Phase.RESOLVING) {
            heldHellos.add(j); // (a robot joins between steps: after this one is resolved)
            return;
        }
        j.verdict().complete(register(j));
        rosterChanged = true;
    }

    /** A shared connection's hellos: answered now, their welcomes in one frame, or once the step is complete. */
    void hello(LoopEvent.SharedJoins s) {
        if (phase == Phase.RESOLVING) {
            heldHellos.add(s);
            return;
        }
        s.connection().outputTo(output);
        boolean anyWelcomed = false;
        for (LoopEvent.RobotJoins j : s.joins()) {
            String refusal = register(j);
            if (refusal != null) {
                s.connection().replies().welcome(((SharedRobot) j.worker()).slot(), RobotWelcome.refused(refusal));
            }
            anyWelcomed |= refusal == null;
            j.verdict().complete(refusal);
        }
        if (anyWelcomed) {
            s.connection().flush(); // (the welcomes go out before any step number)
        } // (else the connection is no robot of the world: its own thread writes the refusals, not the loop)
        s.answered().complete(true);
        rosterChanged = true;
    }

    /** Between steps: answers the hellos held while a step was resolved, moving on after each. */
    void answerHeldHellos() {
        while (!heldHellos.isEmpty() && phase != Phase.RESOLVING) {
            heldHellos.remove(0).apply(this);
            advance(System.nanoTime());
        }
    }

    /** A robot's hello, already checked against the file: null (its welcome is sent) or the refusal. */
    private String register(LoopEvent.RobotJoins j) {
        if (phase != Phase.WAITING) {
            int live = indexOf(j.hello().name());
            return live >= 0 ? rejoin(j.worker(), j.hello(), roster.get(live)) : join(j.worker(), j.hello());
        }
        if (j.index() < 0) {
            return "the simulation has not started: a robot that joins a running world says hello once it runs";
        }
        RobotSlot s = roster.get(j.index());
        if (s.peer != null) {
            return "robot " + s.name + " is already connected";
        }
        try {
            j.worker().welcome(admission.welcome(s.index));
        } catch (IOException e) {
            return "its welcome could not be sent: " + e.getMessage();
        }
        j.worker().assign(s.index);
        s.peer = j.worker();
        s.properties = j.hello().properties();
        roster.set(s, RobotSlot.State.CONNECTED);
        LOG.info("robot {} connected ({} of {})", s.name, roster.count(RobotSlot.State.CONNECTED), roster.size());
        return null;
    }

    /**
     * A hello naming a robot of the world after the start: null (its welcome, with its current pose, is sent,
     * and it takes part from the next step) or the refusal.
     */
    private String rejoin(RobotPeer worker, RobotHello hello, RobotSlot s) {
        if (phase == Phase.ENDED) {
            return LoopEvent.OVER;
        }
        String noReturn = settings.onRobotLoss() == RobotLoss.REMOVE ? " (a lost robot may come back only when the "
                + "Environment runs with --on-robot-loss HOLD or WAIT)" : "";
        if (s.state == RobotSlot.State.GONE || s.leaving != null && s.leaving.forGood()) {
            return "robot " + s.name + " has been removed from the simulation" + noReturn;
        }
        if (!s.peer.closed()) {
            return "robot " + s.name + " is already connected (a new process takes over only once the old "
                    + "connection has closed)";
        }
        if (s.running() && s.leaving == null) {
            leave(s, "its connection closed", false); // before the loop heard of it: it hears now
        }
        if (!noReturn.isEmpty()) {
            return "robot " + s.name + " has left the simulation" + noReturn;
        }
        if (s.state == RobotSlot.State.RETURNING || s.state == RobotSlot.State.JOINING || s.takeover) {
            return "robot " + s.name + " is already coming back on another connection";
        }
        if (!hello.properties().equals(s.properties)) {
            return "robot " + s.name + " comes back with " + Admission.difference(hello.properties(), s.properties);
        }
        double x = core.map().xMm(s.index);
        double y = core.map().yMm(s.index);
        double heading = core.map().headingDeg(s.index);
        try {
            worker.welcome(admission.welcome(core.map().spec().robots().get(s.index).at(x, y, heading),
                    roster.names()));
        } catch (IOException e) {
            return "its welcome could not be sent: " + e.getMessage();
        }
        worker.assign(s.index);
        s.peer = worker;
        if (s.running()) {
            s.takeover = true; // (it leaves at the end of this step; the new connection takes over then)
        } else {
            roster.set(s, RobotSlot.State.RETURNING);
        }
        rosterChanged = true;
        record.states = roster.states();
        LOG.info("robot {} says hello again: it takes part from the next step, at ({}, {}) mm heading {} deg", s.name,
                mm(x), mm(y), deg(heading));
        if (phase == Phase.COLLECTING && s.leaving == null) {
            bringBack(s); // the step being collected is its first
        }
        return null;
    }

    /** A hello after the start naming no robot of the world now: null (welcome sent, robot added) or the refusal. */
    private String join(RobotPeer worker, RobotHello hello) {
        String name = hello.name();
        if (phase == Phase.ENDED) {
            return LoopEvent.OVER;
        }
        JoinRule rule = admission.rule(name);
        String fixed = design.refusesJoins();
        if (fixed != null) {
            return fixed;
        }
        if (rule == null) {
            return "no robot named \"" + Printable.of(name, 64) + "\" in " + spec.source() + " may join";
        }
        if (JoinRule.badName(name) != null) {
            return JoinRule.badName(name);
        }
        if (joins >= MAX_JOINS) {
            return "this run has let " + MAX_JOINS + " robots join, the most one run may";
        }
        long members = 0;
        for (RobotSlot s : roster.all()) {
            members += s.rule == rule && s.state != RobotSlot.State.GONE ? 1 : 0;
        }
        if (members >= rule.max()) {
            return "the rule " + rule.allow() + " of " + spec.source() + " lets at most " + rule.max()
                    + " robot(s) take part at once";
        }
        if (roster.size() >= Limits.MAX_ROBOTS) {
            return "the world holds " + roster.size() + " robots, the most it may";
        }
        StringBuilder why = new StringBuilder();
        double[] at = placer().place(rule, core.map(), why);
        if (at == null) {
            return rule.spawn() == null
                    ? "robot " + name + "'s start pose (" + rule.template().xMm() / 1000 + ", "
                            + rule.template().yMm() / 1000 + ") m in " + spec.source() + " is taken: " + why
                    : "the spawn region of " + rule.allow() + " in " + spec.source() + " has no free pose for "
                            + name + " (" + why + ")";
        }
        WorldSpec.RobotSpec robot = rule.robot(name, at[0], at[1]);
        List<String> names = roster.names();
        names.add(name);
        try {
            worker.welcome(admission.welcome(robot, names));
        } catch (IOException e) {
            return "its welcome could not be sent: " + e.getMessage();
        }
        boolean byAdd = added.remove(name) != null; // (an added robot joins once; it may come back by name)
        admission.joined().put(name, rule);
        joins++;
        int i = core.add(robot, hello.properties());
        RobotSlot s = roster.add(name, rule, RobotSlot.State.JOINING);
        if (s.index != i) {
            throw new IllegalStateException("robot " + name + " joined the core at " + i + " and the roster at " + s.index);
        }
        worker.assign(i);
        s.peer = worker;
        s.properties = hello.properties();
        s.sinceStep = step;
        core.arriving(i);
        grown = true;
        geometry.worldChanged(core.map().geometryWorld());
        rosterChanged = true;
        record.states = roster.states();
        LOG.info("robot {} joins at ({}, {}) mm heading {} deg ({}): it takes part from the next step", name,
                mm(at[0]), mm(at[1]), deg(robot.headingDeg()), byAdd ? "added from the control port" : (rule.spawn() == null
                        ? "any-time" : rule.allow()) + " of " + spec.source());
        listener.robotJoined(name, step);
        if (phase == Phase.COLLECTING) {
            bringBack(s); // the step being collected is its first
        }
        return null;
    }

    /** A coordinate for a log line, to the millimetre. */
    private static long mm(double v) {
        return Math.round(v);
    }

    /** A heading for a log line, to a tenth of a degree. */
    private static double deg(double v) {
        return Math.round(v * 10) / 10.0;
    }

    /** "an ArRobot", "a Scout". */
    private static String withArticle(String type) {
        return ("AEIOUaeiou".indexOf(type.isEmpty() ? 'x' : type.charAt(0)) >= 0 ? "an " : "a ") + type;
    }

    private SpawnPlacer placer() {
        if (placer == null) {
            placer = new SpawnPlacer(spec);
        }
        return placer;
    }

    // ---- robots leaving and coming back -------------------------------------------------------------------

    /** A robot's connection has closed or failed. */
    void left(RobotPeer peer, String why) {
        RobotSlot s = roster.of(peer);
        if (s == null || phase == Phase.ENDED) {
            return;
        }
        rosterChanged = true;
        if (phase == Phase.WAITING) {
            s.peer = null;
            s.properties = null;
            roster.set(s, RobotSlot.State.EXPECTED);
            LOG.warn("robot {} left before the start ({}); waiting for it again", s.name, Printable.of(why));
            return;
        }
        switch (s.state) {
            case JOINING -> roster.set(s, RobotSlot.State.RUNNING); // it went before it took part: lost like any robot
            case HELD, WAITED, GONE -> {
                return;
            }
            case RETURNING -> {
                roster.set(s, awayState()); // the new connection went before it took over: away as before
                return;
            }
            default -> s.takeover = false; // (a take-over said hello before the old loss took effect, and went too)
        }
        leave(s, why, false);
    }

    /**
     * Robot {@code s} no longer takes part: it is removed ({@code forGood}, or {@code --on-robot-loss REMOVE}),
     * or held for its return. While a step is being resolved or released (its request is already in that
     * step) this happens at the end of that step instead.
     */
    private void leave(RobotSlot s, String why, boolean forGood) {
        if (phase == Phase.RESOLVING || phase == Phase.RELEASING) {
            if (s.leaving == null) {
                s.leaving = new RobotSlot.Leaving(why, forGood);
                leaving.add(s);
                LOG.info("robot {} lost during step {} ({}); it stops taking part at the step's end",
                        s.name, StepNumbers.shown(phase == Phase.RELEASING ? step - 1 : step), Printable.of(why));
            } else if (forGood) {
                s.leaving = new RobotSlot.Leaving(s.leaving.why(), true);
            }
            return;
        }
        leaveNow(s, why, forGood);
    }

    /** As {@link #leave}, between steps. */
    private void leaveNow(RobotSlot s, String why, boolean forGood) {
        if (s.state.away()) {
            if (forGood) {
                leaveWorld(s, Printable.of(why));
            }
            return;
        }
        rosterChanged = true;
        if (s.request != null) {
            s.request = null;
            arrived--;
        }
        String safe = Printable.of(why);
        if (forGood || settings.onRobotLoss() == RobotLoss.REMOVE) {
            leaveWorld(s, safe);
            return;
        }
        s.sinceStep = step;
        s.awayNanos = System.nanoTime();
        roster.set(s, s.takeover ? RobotSlot.State.RETURNING : awayState());
        s.takeover = false;
        core.away(s.index, true);
        record.states = roster.states(); // (before the log line: whoever reads it sees the state)
        LOG.warn("robot {} lost at step {} ({}); it stands where it is until a robot process says hello as {}{}",
                s.name, StepNumbers.shown(step), safe, s.name, settings.onRobotLoss() == RobotLoss.WAIT
                        ? ", and the world waits for it" + limit() : "");
        listener.robotHeld(s.name, step, safe);
    }

    /** Where a lost robot stands under the loss policy (HOLD or WAIT). */
    private RobotSlot.State awayState() {
        return settings.onRobotLoss() == RobotLoss.WAIT ? RobotSlot.State.WAITED : RobotSlot.State.HELD;
    }

    private String limit() {
        return settings.stepTimeoutMs() > 0 ? " (at most " + settings.stepTimeoutMs() + " ms: the step timeout)" : "";
    }

    /** Takes robot {@code s} out of the world for good; {@code why} is safe to print. */
    private void leaveWorld(RobotSlot s, String why) {
        roster.set(s, RobotSlot.State.GONE);
        s.takeover = false;
        s.sinceStep = step;
        core.depart(s.index);
        rosterChanged = true;
        Departure d = new Departure(s.name, step, why);
        record.departures.add(d);
        record.states = roster.states();
        LOG.warn("robot {} left at step {} ({}); it is removed from the world and the others go on", d.robot(),
                StepNumbers.shown(step), why);
        listener.robotLeft(d);
    }

    /** The departures held back during the step just released take effect now. */
    private void applyLeaving() {
        if (leaving.isEmpty()) {
            return;
        }
        List<RobotSlot> due = List.copyOf(leaving);
        leaving.clear();
        for (RobotSlot s : due) {
            RobotSlot.Leaving l = s.leaving;
            s.leaving = null;
            if (s.state != RobotSlot.State.GONE) {
                leaveNow(s, l.why(), l.forGood());
            }
        }
    }

    /** Robots whose new connection, or whose join, waits for the next step take part from the step being collected. */
    private void bringBackReturning() {
        if (roster.count(RobotSlot.State.RETURNING) + roster.count(RobotSlot.State.JOINING) == 0) {
            return;
        }
        for (RobotSlot s : roster.all()) {
            if (s.state == RobotSlot.State.RETURNING || s.state == RobotSlot.State.JOINING) {
                bringBack(s);
            }
        }
    }

    /** Robot {@code s}'s new connection takes part from the step being collected: it gets that step's number. */
    private void bringBack(RobotSlot s) {
        boolean joined = s.state == RobotSlot.State.JOINING;
        roster.set(s, RobotSlot.State.RUNNING);
        core.away(s.index, false);
        toldEveryoneAway = false;
        rosterChanged = true;
        record.states = roster.states();
        s.backNanos = System.nanoTime(); // its step timeout runs from now, as the others' did from their step
        if (joined) {
            LOG.info("robot {} takes part from step {}", s.name, StepNumbers.shown(step));
        } else {
            LOG.info("robot {} is back at step {}, where it stood since step {}", s.name, StepNumbers.shown(step),
                    StepNumbers.shown(s.sinceStep));
            listener.robotReturned(s.name, step);
        }
        try {
            s.peer.begin(step);
        } catch (IOException e) {
            s.peer.drop();
            leave(s, "could not send it step " + step + ": " + e.getMessage(), false);
        }
    }

    /** True while the world waits because every robot in it is away. */
    private boolean everyoneAway() {
        return toldEveryoneAway;
    }

    /** Every robot in the world is away: the world waits (said once) until one comes back or joins. */
    private void waitForAnyone() {
        if (!toldEveryoneAway) {
            toldEveryoneAway = true;
            LOG.warn("every robot is away at step {}: the world waits until one comes back", StepNumbers.shown(step));
        }
    }

    // ---- the control port ----------------------------------------------------------------------------------

    void pause(CompletableFuture<Void> held) {
        control.pause(held, running() && !everyoneAway()); // (nothing steps: held now)
    }

    void resume(CompletableFuture<Void> applied) {
        control.resume(released);
        advance(System.nanoTime()); // (a run that may begin now begins before the answer)
        publishPhase();
        applied.complete(null);
    }

    void stepN(long n, CompletableFuture<Long> done) {
        control.stepN(n, done, released, running());
    }

    /**
     * The control port's {@code add}: null (a hello with the rule's name joins at its pose, once) or why not.
     * The name must be new (not in the world, not added already), the pose inside the arena and free now.
     */
    String add(JoinRule rule) {
        rosterChanged = true;
        String name = rule.allow();
        String fixed = design.refusesJoins();
        if (fixed != null) {
            return fixed;
        }
        if (phase == Phase.ENDED || phase == Phase.WAITING) {
            return "the simulation is " + (phase == Phase.ENDED ? "over" : "not running yet: add robots once it runs");
        }
        if (added.size() >= MAX_ADDED) {
            return MAX_ADDED + " added robots wait for their hello already (remove NAME cancels one)";
        }
        if (indexOf(name) >= 0 || added.containsKey(name)) {
            return "a robot named " + name + " is " + (added.containsKey(name) ? "added already" : "in the simulation");
        }
        WorldSpec.RobotSpec r = rule.template();
        Arena arena = spec.arena();
        if (r.xMm() - r.radiusMm() < arena.minXMm() || r.xMm() + r.radiusMm() > arena.maxXMm()
                || r.yMm() - r.radiusMm() < arena.minYMm() || r.yMm() + r.radiusMm() > arena.maxYMm()) {
            return "(" + r.xMm() / 1000 + ", " + r.yMm() / 1000 + ") m is not inside the arena for a " + r.type();
        }
        StringBuilder why = new StringBuilder();
        if (placer().place(rule, core.map(), why) == null) {
            return "(" + r.xMm() / 1000 + ", " + r.yMm() / 1000 + ") m is taken: " + why;
        }
        added.put(name, rule);
        LOG.info("robot {} added from the control port: {} at ({}, {}) mm heading {} deg; it joins when it says hello",
                name, withArticle(r.type()), mm(r.xMm()), mm(r.yMm()), deg(r.headingDeg()));
        return null;
    }

    /** The control port's {@code remove NAME}: null (removed now, or at the end of the step in progress) or why not. */
    String remove(String name) {
        rosterChanged = true;
        int i = indexOf(name);
        String shown = "\"" + Printable.of(name, 64) + "\"";
        if (i < 0) {
            if (added.remove(name) != null) {
                LOG.info("robot {}, added from the control port, is no longer let in (removed before it joined)", name);
                return null;
            }
            return "no robot named " + shown + " in this simulation";
        }
        if (core == null || phase == Phase.ENDED) {
            return "the simulation is " + (phase == Phase.ENDED ? "over" : "not running yet");
        }
        RobotSlot s = roster.get(i);
        if (s.state == RobotSlot.State.GONE) {
            return "robot " + shown + " has already left";
        }
        if (!s.peer.closed()) { // (not dropped: what it sends is ignored from now on, and it closes when told)
            s.peer.end(new SimulationEnd(step - 1, "removed from the simulation from the control port"), s.peer.begun());
        }
        leave(s, "removed from the control port", true);
        return null;
    }

    // ---- viewers and the recording -------------------------------------------------------------------------

    /** A viewer joins: it gets the snapshot it starts from, then the run's state (or its end). */
    void addViewer(ViewerSink viewer, CompletableFuture<WorldSnapshot> snapshot) {
        viewers.add(viewer);
        snapshot.complete(snapshot());
        if (phase == Phase.ENDED) {
            viewer.queue().end(endMessage());
        } else {
            viewer.queue().state(new RunState(released, phase == Phase.WAITING ? RunState.Phase.WAITING
                    : control.holding() ? RunState.Phase.PAUSED : RunState.Phase.RUNNING));
        }
    }

    /** A viewer's worker has ended; one the connection watch cut off is reported as dropped. */
    void viewerLeft(ViewerSink viewer, String why, boolean cutOff) {
        if (viewers.remove(viewer, why) && cutOff) {
            listener.viewerDropped(viewer.viewerName(), why);
        }
    }

    /** The world as a viewer that joins now starts from: the last step's poses, or the start poses. */
    private WorldSnapshot snapshot() {
        if (core != null) {
            return core.map().snapshot(step - 1);
        }
        RobotProperties[] said = new RobotProperties[roster.size()];
        for (RobotSlot s : roster.all()) {
            said[s.index] = s.properties;
        }
        return StartSnapshot.of(spec, said);
    }

    /** With {@code --record}: opens the recording at the start, from the world as a viewer would get it. */
    private void startRecording() {
        if (settings.record() == null || recorder != null) {
            return;
        }
        try {
            recorder = new RunRecorder(settings.record(), snapshot());
        } catch (IOException e) {
            LOG.error("cannot record into {}: {}", settings.record(), e.toString());
        }
    }

    // ---- publishing -----------------------------------------------------------------------------------------

    /** Publishes the run's state for the status, and who is connected if that changed; after every event. */
    void publish() {
        publishPhase();
        if (rosterChanged) {
            rosterChanged = false;
            publishRoster();
        }
    }

    private void publishPhase() {
        record.phase = switch (phase) {
            case WAITING -> RunStatus.State.WAITING;
            case ENDED -> RunStatus.State.ENDED;
            default -> control.pausedNow() || beginHeld ? RunStatus.State.PAUSED : RunStatus.State.RUNNING;
        };
        record.geometry = geometry.where(phase == Phase.ENDED);
    }

    /** Publishes the robots that have said hello and whether each takes part, and every robot's state. */
    private void publishRoster() {
        List<PublishedRun.Member> members = new ArrayList<>();
        for (RobotSlot s : roster.all()) {
            if (s.peer != null) {
                members.add(new PublishedRun.Member(s.name, s.peer, s.state != RobotSlot.State.GONE));
            }
        }
        record.roster = List.copyOf(members);
        List<RobotState> states = roster.states();
        if (!added.isEmpty()) { // (robots the control port added that have not said hello yet, by name)
            states = new ArrayList<>(states);
            for (String name : new java.util.TreeSet<>(added.keySet())) {
                states.add(new RobotState(name, RobotState.ADDED, -1));
            }
            states = List.copyOf(states);
        }
        record.states = states;
    }

    // ---- the end -------------------------------------------------------------------------------------------

    /** Ends the run (once): robots, viewers and Geometry are told why; held hellos are refused. */
    void finish(String reason, boolean asPlanned) {
        if (phase == Phase.ENDED) {
            return;
        }
        boolean started = phase != Phase.WAITING;
        if (started) {
            applyLeaving(); // (the departures held back are on record)
        }
        phase = Phase.ENDED;
        record.endReason = reason;
        record.completed = asPlanned;
        record.endNanos = System.nanoTime();
        SimulationEnd end = endMessage();
        if (!robotsTold) {
            robotsTold = true;
            for (RobotSlot s : roster.all()) {
                if (s.peer != null && !s.peer.closed() && s.state != RobotSlot.State.GONE) {
                    s.peer.end(end, s.peer.begun());
                }
            }
        }
        viewers.end(end);
        geometry.end(end);
        RunRecorder rec = recorder;
        if (rec != null) {
            rec.end(end);
        }
        rosterChanged = true;
        LOG.info("simulation over after {} steps: {}", released, Printable.of(reason));
        listener.ended(record.summary(roster.size()));
        closeOut();
    }

    /**
     * Once the run is over (and by the loop, last, whatever happened): the end goes out to shared connections,
     * whoever still waits is answered (held hellos refused, pause and step N callers) and the last state is
     * published. Again does nothing more.
     */
    void closeOut() {
        output.flush();
        heldHellos.forEach(LoopEvent::refuse);
        heldHellos.clear();
        publish();
        control.settle(released, true);
    }

    /** The end; its last step is the last whose responses went out (a step computed and held by the pace is not). */
    private SimulationEnd endMessage() {
        return new SimulationEnd(released - 1, record.endReason);
    }
}

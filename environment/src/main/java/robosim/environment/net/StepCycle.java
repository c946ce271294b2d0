package robosim.environment.net;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.core.SimulationCore;
import robosim.environment.core.WorldSpec;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotProperties;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.WorldSnapshot;

/**
 * The step cycle as the {@link SimulationLoop} runs it, one phase after another: waiting for every
 * client, starting (the Geometry process is sent the world), collecting the step's requests, resolving
 * (Geometry's round trip), releasing (the hold point: pause, step N, pace, a full recording viewer;
 * then every response goes out), and ended. Loop thread only.
 */
final class StepCycle {
    private static final Logger LOG = LoggerFactory.getLogger(StepCycle.class);

    enum Phase { WAITING, STARTING, COLLECTING, RESOLVING, RELEASING, ENDED }

    private final ClientWorkerCoordinator coordinator;
    private final Settings settings;
    private final WorldSpec spec;
    private final ClientWorkerCoordinator.RunListener listener;
    private final RunRecord record = new RunRecord();
    private final GeometryLink geometry;
    private final RunControl control;
    private final Viewers viewers;
    private final RobotPeer[] robots;
    private final long stepTimeoutNanos;
    private StepRequest[] requests;
    private StepRequest[] inFlight;
    private SimulationCore core;
    /** Each robot's properties from its hello (null until it has said it), in world order. */
    private final RobotProperties[] registered;
    private boolean everyoneHere;
    private Phase phase = Phase.WAITING;
    private boolean beginPending;
    private boolean robotsTold;
    private boolean rosterChanged;
    /** The computed step waits for a full recording viewer. */
    private boolean heldForViewer;
    private int arrived;
    private int activeCount;
    /** Steps computed so far: the step being collected or resolved is this one. */
    private long step;
    private long released;
    private long releasedNanos;

    StepCycle(ClientWorkerCoordinator coordinator, ClientWorkerCoordinator.RunListener listener) {
        this.coordinator = coordinator;
        this.settings = coordinator.settings();
        this.spec = coordinator.spec();
        this.listener = listener;
        int n = spec.robots().size();
        this.robots = new RobotPeer[n];
        this.registered = new RobotProperties[n];
        this.requests = new StepRequest[n];
        this.inFlight = new StepRequest[n];
        this.geometry = new GeometryLink(settings);
        this.control = new RunControl(settings.speed(), spec.timeStepMs(), this::publishPhase);
        this.viewers = new Viewers(settings.viewerWriteTimeoutMs(), listener);
        this.stepTimeoutNanos = settings.stepTimeoutMs() <= 0 ? Long.MAX_VALUE : settings.stepTimeoutMs() * 1_000_000L;
    }

    RobotPeer[] robots() {
        return robots;
    }

    GeometryLink geometry() {
        return geometry;
    }

    Viewers viewers() {
        return viewers;
    }

    RunRecord record() {
        return record;
    }

    RunControl control() {
        return control;
    }

    boolean waiting() {
        return phase == Phase.WAITING;
    }

    boolean ended() {
        return phase == Phase.ENDED;
    }

    boolean present(int i) {
        return core != null && core.present(i);
    }

    /** True once, after robots took part or left without the loop's register seeing it (a departure). */
    boolean takeRosterChange() {
        boolean c = rosterChanged;
        rosterChanged = false;
        return c;
    }

    /** Publishes the run's state for the status; after every event, so it is never stale. */
    void publishPhase() {
        record.phase = statusPhase();
        record.geometry = geometry.where(phase == Phase.ENDED);
    }

    // ---- starting ----------------------------------------------------------------------------------

    /** Each robot's properties from its hello, in world order; filled in by the loop's registration. */
    RobotProperties[] registered() {
        return registered;
    }

    /** Before the start: whether every robot has said hello (the loop's registration keeps this). */
    void everyoneHere(boolean all) {
        everyoneHere = all;
    }

    /** Moves the run on as far as it can go now; called after every event and deadline check. */
    void advance(long now) {
        while (true) {
            switch (phase) {
                case WAITING -> {
                    if (!everyoneHere || !geometry.canStart()) {
                        return;
                    }
                    start();
                }
                case STARTING -> {
                    if (!geometry.ready() || !begin(now)) {
                        return;
                    }
                }
                case COLLECTING -> {
                    if (activeCount == 0) {
                        finish("every robot has left", false);
                        return;
                    }
                    if (arrived < activeCount) {
                        return;
                    }
                    compute();
                }
                case RELEASING -> {
                    if (!mayRelease(now)) {
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
        core = new SimulationCore(spec, List.of(registered));
        geometry.start(core.map().geometryWorld());
        activeCount = robots.length;
        phase = Phase.STARTING;
        LOG.info("all {} robot(s) connected: running{}", robots.length,
                settings.maxSteps() > 0 ? " for " + settings.maxSteps() + " steps" : "");
    }

    /** Sends every robot step 0, unless the run is to hold before it; true if the run has begun. */
    private boolean begin(long now) {
        if (control.holdWanted()) {
            if (!beginPending) {
                beginPending = true;
                control.held(released);
                coordinator.started();
                LOG.info("every client is here; paused before step 0 (start or step from the control port)");
                viewers.announce(new RunState(released, RunState.Phase.PAUSED));
            }
            return false;
        }
        if (beginPending) {
            beginPending = false;
            control.unheld(now, 0);
        }
        viewers.announce(new RunState(released, RunState.Phase.RUNNING));
        record.begin(now);
        control.restartPace(now, 0);
        releasedNanos = now;
        phase = Phase.COLLECTING;
        for (int i = 0; i < robots.length; i++) {
            if (!core.present(i)) {
                continue;
            }
            try {
                robots[i].begin(0);
            } catch (IOException e) {
                robots[i].drop();
                depart(i, "could not send it the first step: " + e.getMessage());
            }
        }
        if (settings.design() == ClientWorkerCoordinator.Design.SEQUENTIAL) {
            SequentialReader.start(coordinator, robots);
        }
        coordinator.started();
        listener.started(robots.length);
        return true;
    }

    // ---- collecting, resolving -----------------------------------------------------------------------

    void request(RobotPeer worker, StepRequest request) {
        int i = worker.index();
        if (i < 0 || robots[i] != worker || core == null || !core.present(i) || phase == Phase.ENDED) {
            return; // gone already, or the run is over: nothing to do with it
        }
        if (phase != Phase.COLLECTING || request.step() != step || requests[i] != null) {
            worker.drop();
            depart(i, "sent a request for step " + request.step() + " out of turn (step " + step + " is due)");
            return;
        }
        requests[i] = request;
        arrived++;
    }

    private void compute() {
        StepRequest[] batch = requests;
        requests = inFlight;
        inFlight = batch;
        arrived = 0;
        GeometryStepRequest prepared;
        try {
            prepared = core.prepare(step, batch);
        } catch (ProtocolException e) {
            finish("step " + step + " failed: " + e.getMessage(), false);
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
                finish("step " + step + " failed: " + e.getMessage(), false);
            } else {
                geometryLost(from, "gave a bad answer: " + e.getMessage());
            }
            return;
        }
        Arrays.fill(inFlight, null);
        step++;
        record.stepsComputed = step;
        phase = Phase.RELEASING;
    }

    void geometryReady(GeometryClientWorker worker) {
        int before = geometry.attaches();
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

    // ---- releasing ------------------------------------------------------------------------------------

    /** When the computed step may go out by the pace (ns), if it waits for it; else far in the future. */
    long paceDue() {
        return phase == Phase.RELEASING && !control.holdWanted() && settings.speed() > 0 ? control.paceDue(step)
                : Long.MAX_VALUE;
    }

    /** The release point: false while a pause, the pace or a full recording viewer holds the step. */
    private boolean mayRelease(long now) {
        if (control.holdWanted()) {
            if (!control.holding()) {
                control.held(released);
                viewers.announce(new RunState(released, RunState.Phase.PAUSED));
            }
            return false;
        }
        if (control.holding()) {
            control.unheld(now, step - 1); // pace on from here: no rush to catch up the pause
            record.resumed(now);
            viewers.announce(new RunState(released, RunState.Phase.RUNNING));
        }
        if (settings.speed() > 0 && control.paceDue(step) - now > 0) {
            return false;
        }
        if (!viewers.haveRoom()) {
            if (!heldForViewer) {
                heldForViewer = true;
                LOG.debug("step {} waits for a recording viewer that is {} updates behind", step - 1,
                        ViewerQueue.RECORDING_BACKLOG);
                listener.heldForViewer(step - 1);
            }
            return false;
        }
        heldForViewer = false;
        return true;
    }

    /** Every robot's response with the next step number (or the end), then the poses to every viewer. */
    private void release() {
        control.releasing();
        boolean last = settings.maxSteps() > 0 && step >= settings.maxSteps();
        SimulationEnd end = last ? new SimulationEnd(step - 1, "completed " + step + " steps") : null;
        for (int i = 0; i < robots.length; i++) {
            if (!core.present(i)) {
                continue;
            }
            try {
                robots[i].deliver(core.response(i), step, end);
            } catch (IOException e) {
                robots[i].drop();
                depart(i, "could not send its response: " + e.getMessage());
            }
        }
        long now = System.nanoTime();
        released = step;
        record.released(released, now);
        record.messages(core.messagesDelivered(), core.messagesOutOfRange(), core.messagesUndeliverable());
        control.settle(released, false);
        if (!viewers.isEmpty()) {
            viewers.publish(core.viewerUpdate());
        }
        releasedNanos = now; // robots are timed from here
        if (last) {
            robotsTold = true;
            finish(end.reason(), true);
        } else {
            phase = Phase.COLLECTING;
        }
    }

    // ---- robots leaving, deadlines --------------------------------------------------------------------

    /** Robot i's connection has closed or failed. */
    void leave(int i, String why) {
        if (core != null && core.present(i) && phase != Phase.ENDED) {
            depart(i, why);
        }
    }

    /** Robot i no longer takes part; it stands where it is. */
    private void depart(int i, String why) {
        core.depart(i);
        activeCount--;
        rosterChanged = true;
        if (requests[i] != null) {
            requests[i] = null;
            arrived--;
        }
        String safe = Printable.of(why);
        ClientWorkerCoordinator.Departure d = new ClientWorkerCoordinator.Departure(spec.robots().get(i).name(), step,
                safe);
        record.departures.add(d);
        LOG.warn("robot {} left at step {} ({}); it is removed from the world and the others go on", d.robot(), step,
                safe);
        listener.robotLeft(d);
    }

    /** Deadlines: a viewer stuck in a write, a Geometry process late with its answer, robots late with requests. */
    void tick(long now) {
        viewers.dropStuck(now);
        GeometryClientWorker late = geometry.overdue(now);
        if (late != null) {
            LOG.warn("Geometry process has not answered step {} within {} ms; dropping it", step,
                    settings.geometryTimeoutMs());
            geometryLost(late, "no answer within " + settings.geometryTimeoutMs() + " ms");
        }
        if (phase == Phase.COLLECTING && now - releasedNanos > stepTimeoutNanos) {
            boolean sequential = settings.design() == ClientWorkerCoordinator.Design.SEQUENTIAL;
            for (int i = 0; i < robots.length; i++) {
                if (core.present(i) && requests[i] == null) {
                    robots[i].drop();
                    depart(i, "sent no request for step " + step + " within " + settings.stepTimeoutMs()
                            + " ms (step timeout)");
                    if (sequential) {
                        break; // the stepper reads in world order: only the robot it waits for is late
                    }
                }
            }
        }
    }

    // ---- viewers and run control -----------------------------------------------------------------------

    void addViewer(ViewerClientWorker viewer, CompletableFuture<WorldSnapshot> snapshot) {
        viewers.add(viewer);
        snapshot.complete(snapshot());
        if (phase == Phase.ENDED) {
            viewer.queue().end(endMessage());
        } else {
            viewer.queue().state(new RunState(released, phase == Phase.WAITING ? RunState.Phase.WAITING
                    : control.holding() ? RunState.Phase.PAUSED : RunState.Phase.RUNNING));
        }
    }

    /** The world as a viewer that joins now starts from: the last step's poses, or the start poses. */
    private WorldSnapshot snapshot() {
        return core != null ? core.map().snapshot(step - 1) : StartSnapshot.of(spec, registered);
    }

    void pause(CompletableFuture<Void> held) {
        control.pause(held, phase != Phase.WAITING && phase != Phase.ENDED);
    }

    void resume() {
        control.resume(released);
    }

    void stepN(long n, CompletableFuture<Long> done) {
        control.stepN(n, done, released, phase != Phase.WAITING && phase != Phase.ENDED);
    }

    /** The status's name for the run's state now. */
    private String statusPhase() {
        return switch (phase) {
            case WAITING -> "WAITING";
            case ENDED -> "ENDED";
            default -> control.pausedNow() || beginPending ? "PAUSED" : "RUNNING";
        };
    }

    // ---- the end ---------------------------------------------------------------------------------------

    /** Ends the run (once): robots, viewers and Geometry are told why; the ports close. */
    void finish(String reason, boolean asPlanned) {
        if (phase == Phase.ENDED) {
            return;
        }
        boolean started = phase != Phase.WAITING;
        phase = Phase.ENDED;
        record.endReason = reason;
        record.completed = asPlanned;
        record.endNanos = System.nanoTime();
        SimulationEnd end = endMessage();
        if (!robotsTold) {
            robotsTold = true;
            for (int i = 0; i < robots.length; i++) {
                if (robots[i] != null && (!started || core == null || core.present(i))) {
                    robots[i].end(end, robots[i].begun());
                }
            }
        }
        viewers.end(end);
        geometry.end(end);
        control.settle(released, true);
        rosterChanged = true;
        LOG.info("simulation over after {} steps: {}", step, reason);
        listener.ended(record.summary(robots.length));
    }

    SimulationEnd endMessage() {
        return new SimulationEnd(step - 1, record.endReason);
    }
}

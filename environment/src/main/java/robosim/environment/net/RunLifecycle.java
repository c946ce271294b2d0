package robosim.environment.net;

import java.io.IOException;
import java.util.List;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.core.SimulationCore;
import robosim.environment.core.WorldSpec;
import robosim.protocol.RobotProperties;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;

/**
 * The life of one run, as the {@link SimulationLoop} drives it: waiting for every client, starting (the
 * Geometry process is sent the world), beginning (step 0 to every robot, or a hold before it), robots
 * leaving, viewers joining, the status, and the end. {@link StepCycle} adds the step itself. Loop thread
 * only.
 */
abstract class RunLifecycle {
    static final Logger LOG = LoggerFactory.getLogger(RunLifecycle.class);

    enum Phase { WAITING, STARTING, COLLECTING, RESOLVING, RELEASING, ENDED }

    final ClientWorkerCoordinator coordinator;
    final Settings settings;
    final WorldSpec spec;
    final RunListener listener;
    final RunRecord record = new RunRecord();
    final GeometryLink geometry;
    final RunControl control;
    final Viewers viewers;
    final ReleasePoint releasePoint;
    RobotPeer[] robots;
    /** Robots that left during the step being resolved or released: they go at its end. */
    boolean[] leaving;
    final long stepTimeoutNanos;
    StepRequest[] requests;
    StepRequest[] inFlight;
    SimulationCore core;
    /** Each robot's properties from its hello (null until it has said it), in world order. */
    RobotProperties[] registered;
    boolean everyoneHere;
    Phase phase = Phase.WAITING;
    boolean beginPending;
    boolean robotsTold;
    boolean rosterChanged;
    int arrived;
    int activeCount;
    /** Steps computed so far: the step being collected or resolved is this one. */
    long step;
    long released;
    long releasedNanos;
    /** The run's recording, once it has begun ({@code --record}), else null. */
    volatile RunRecorder recorder;

    RunLifecycle(ClientWorkerCoordinator coordinator, RunListener listener) {
        this.coordinator = coordinator;
        this.settings = coordinator.settings();
        this.spec = coordinator.spec();
        this.listener = listener;
        int n = spec.robots().size();
        this.robots = new RobotPeer[n];
        this.leaving = new boolean[n];
        this.registered = new RobotProperties[n];
        this.requests = new StepRequest[n];
        this.inFlight = new StepRequest[n];
        this.geometry = new GeometryLink(settings);
        this.control = new RunControl(settings.speed(), spec.timeStepMs(), this::publishPhase);
        this.viewers = new Viewers(settings.writeTimeoutMs(), listener);
        this.releasePoint = new ReleasePoint(control, viewers, record, listener, settings.speed());
        this.stepTimeoutNanos = settings.stepTimeoutMs() <= 0 ? Long.MAX_VALUE : settings.stepTimeoutMs() * 1_000_000L;
    }

    RobotPeer[] robots() {
        return robots;
    }

    /** Robot i's name (world order: the file's robots, then those that joined, in the order they did). */
    String name(int i) {
        return core != null ? core.map().name(i) : spec.robots().get(i).name();
    }

    /** Every robot's name now, in world order. */
    List<String> names() {
        List<String> names = new java.util.ArrayList<>(robots.length);
        for (int i = 0; i < robots.length; i++) {
            names.add(name(i));
        }
        return names;
    }

    /** The index of the robot of this name in the world now, or -1. */
    int indexOf(String robotName) {
        return core != null ? core.map().spec().indexOf(robotName) : spec.indexOf(robotName);
    }

    /** One more robot has joined (between steps): every per-robot array holds n. */
    void grow(int n) {
        robots = java.util.Arrays.copyOf(robots, n);
        leaving = java.util.Arrays.copyOf(leaving, n);
        registered = java.util.Arrays.copyOf(registered, n);
        requests = java.util.Arrays.copyOf(requests, n);
        inFlight = java.util.Arrays.copyOf(inFlight, n);
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

    void start() {
        core = new SimulationCore(spec, List.of(registered));
        geometry.start(core.map().geometryWorld());
        activeCount = robots.length;
        phase = Phase.STARTING;
        LOG.info("all {} robot(s) connected: running{}", robots.length,
                settings.maxSteps() > 0 ? " for " + settings.maxSteps() + " steps" : "");
    }

    /** Sends every robot step 0, unless the run is to hold before it; true if the run has begun. */
    boolean begin(long now) {
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
            if (!core.present(i) || away(i)) {
                continue;
            }
            try {
                robots[i].begin(0);
            } catch (IOException e) {
                robots[i].drop();
                depart(i, "could not send it the first step: " + e.getMessage());
            }
        }
        bringBackReturning();
        if (settings.design() == CoordinatorDesign.SEQUENTIAL) {
            SequentialReader.start(coordinator, robots);
        }
        coordinator.started();
        listener.started(robots.length);
        return true;
    }

    // ---- robots leaving and coming back ({@link RosterCycle}) ------------------------------------------

    /** Robot i no longer takes part (at the step's end if one is under way). */
    abstract void depart(int i, String why);

    /** The departures held back during the step just released take effect now. */
    abstract void departDeferred();

    /** Robots whose new connection waits for the next step take part from the step being collected. */
    abstract void bringBackReturning();

    /** True if robot i is in the world but away (lost under {@code HOLD} or {@code WAIT}). */
    abstract boolean away(int i);

    // ---- run control -----------------------------------------------------------------------------------

    /** True from the start until the end: a pause or step N acts on this run. */
    boolean running() {
        return phase != Phase.WAITING && phase != Phase.ENDED;
    }

    /** The steps whose responses have gone out. */
    long released() {
        return released;
    }

    /** The status's name for the run's state now. */
    private RunStatus.State statusPhase() {
        return switch (phase) {
            case WAITING -> RunStatus.State.WAITING;
            case ENDED -> RunStatus.State.ENDED;
            default -> control.pausedNow() || beginPending ? RunStatus.State.PAUSED : RunStatus.State.RUNNING;
        };
    }

    // ---- the end ---------------------------------------------------------------------------------------

    /** Ends the run (once): robots, viewers and Geometry are told why; the ports close. */
    void finish(String reason, boolean asPlanned) {
        if (phase == Phase.ENDED) {
            return;
        }
        boolean started = phase != Phase.WAITING;
        if (started && core != null) {
            phase = Phase.COLLECTING; // between steps: the held-back departures are on record
            departDeferred();
        }
        phase = Phase.ENDED;
        record.endReason = reason;
        record.completed = asPlanned;
        record.endNanos = System.nanoTime();
        SimulationEnd end = endMessage();
        if (!robotsTold) {
            robotsTold = true;
            for (int i = 0; i < robots.length; i++) {
                if (robots[i] != null && !robots[i].closed() && (!started || core == null || core.present(i))) {
                    robots[i].end(end, robots[i].begun());
                }
            }
        }
        viewers.end(end);
        geometry.end(end);
        if (recorder != null) {
            recorder.end(end);
        }
        control.settle(released, true);
        rosterChanged = true;
        LOG.info("simulation over after {} steps: {}", step, Printable.of(reason));
        listener.ended(record.summary(robots.length));
    }

    SimulationEnd endMessage() {
        return new SimulationEnd(step - 1, record.endReason);
    }
}

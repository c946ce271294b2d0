package robosim.environment.run;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.function.LongSupplier;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.core.ExperimentFailure;
import robosim.environment.core.JoinRule;
import robosim.environment.core.SimulationCore;
import robosim.environment.core.WorldSpec;
import robosim.environment.metrics.AreaCoveredMetric;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.Printable;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotProperties;
import robosim.protocol.RunState;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepNumbers;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;
import robosim.protocol.WorldSnapshot;

/**
 * One simulation run: time and the order of a step, nothing else; driven by whoever holds it (the
 * {@link SimulationLoop}'s thread, or a test by hand), one call at a time. It is built from the world, the
 * settings, a clock and where its outputs go, and knows no socket, thread or transport: robots are
 * {@link RobotPeer}s, Geometry a {@link GeometryPeer}, viewers and the recording {@link ReleaseListener}s.
 *
 * <p>{@link #advance} moves it on as far as it can, stage after stage: it starts once every robot the file names
 * and a Geometry process are there; then each step is collected (every running robot's request is in), resolved
 * (the core prepares it and the {@link GeometryLink} resolves it: in-process at once, or Geometry's answer comes
 * back as an event; the core completes it), released (at the {@link ReleasePoint}: pause, step N, pace, a full
 * recording viewer; every running robot gets its response with the next step number, the listeners the world
 * after it), and published. Where a stage waits for an event it stops, and the next event moves it on.
 *
 * <p>Its parts own their state: {@link Progress} (the phase and the step counts), the {@link Roster} (the robots
 * and their lifecycle), the {@link Admission} (who comes in), {@link RunControl} and the {@link ReleasePoint}
 * (pause, step N, pace), the {@link GeometryLink}, and the {@link StatusBoard} (what other threads read).
 */
public final class Run {
    private static final Logger LOG = LoggerFactory.getLogger(Run.class);

    private final WorldSpec spec;
    private final Settings settings;
    private final LongSupplier clock;
    private final RunListener listener;
    private final List<ReleaseListener> outputs;
    private final Progress progress = new Progress();
    private final PublishedRun published;
    private final Roster roster;
    private final Admission admission;
    private final GeometryLink geometry;
    private final RunControl control;
    private final ReleasePoint releasePoint;
    private final StatusBoard status;
    /** What a listener may read of the step just released. */
    private final ReleaseListener.Step releasedStep = new ReleaseListener.Step() {
        @Override
        public boolean tookPart(int i) {
            return i < roster.size() && roster.get(i).running();
        }

        @Override
        public StepRequest request(int i) {
            return roster.get(i).released();
        }

        @Override
        public StepResponse response(int i) {
            return core.response(i);
        }
    };
    private SimulationCore core;
    /** The world as last released, from step 0 on; null before. */
    private ReleasedWorld world;
    /** When the last step's responses went out: robots are timed from here. */
    private long releasedNanos;
    private boolean beginHeld;
    /** The robots have been told the end (with their last response). */
    private boolean robotsTold;

    /**
     * A run of the world {@code spec} as {@code settings} say, whose robots' hellos were checked by {@code check},
     * reading time from {@code clock} (ns), telling {@code listener} what happens and {@code outputs} (viewers,
     * the recording) every step it releases.
     */
    public Run(WorldSpec spec, Settings settings, HelloCheck check, LongSupplier clock, RunListener listener,
            List<ReleaseListener> outputs) {
        this.spec = spec;
        this.settings = settings;
        this.clock = clock;
        this.listener = listener;
        this.outputs = List.copyOf(outputs);
        this.published = new PublishedRun(clock);
        this.geometry = new GeometryLink(settings, clock);
        this.control = new RunControl(settings.speed(), spec.timeStepMs(), this::publish);
        this.roster = new Roster(spec, progress, settings, clock, listener, this::publish);
        this.admission = new Admission(spec, settings, check, roster, progress, geometry, listener, this::publish);
        this.status = new StatusBoard(published, progress, control, geometry, roster, admission);
        this.releasePoint = new ReleasePoint(control, this.outputs, published, listener, settings.speed());
    }

    /** What the run publishes for other threads: its status, its summary, the world it released. */
    public PublishedRun published() {
        return published;
    }

    /** Before the run is driven: it holds before step 0 until resumed. */
    public void startPaused() {
        control.startPaused();
    }

    boolean ended() {
        return progress.over();
    }

    /** When the computed step may go out by the pace (ns), if it waits for it; else far in the future. */
    long paceDue() {
        return progress.phase() == Progress.Phase.RELEASING ? releasePoint.paceDue(progress.step()) : Long.MAX_VALUE;
    }

    // ---- moving on -------------------------------------------------------------------------------------------

    /**
     * Moves the run on as far as it can go now: it starts, begins, then, step after step, collects, resolves and
     * releases, until a stage must wait for an event (a request, Geometry's answer, the pace, a resume).
     */
    void advance(long now) {
        boolean moved = true;
        while (moved) {
            moved = switch (progress.phase()) {
                case WAITING -> start();
                case STARTING -> begin(now);
                case COLLECTING -> collected() && resolve();
                case RELEASING -> release(now);
                case RESOLVING, ENDED -> false; // (Geometry's answer comes as an event; the end is the end)
            };
        }
    }

    /** Publishes the run's status for other threads; after every event. */
    void publish() {
        status.publish();
    }

    /** Once every robot the file names (and a Geometry process, unless in-process) is there: the world is built. */
    private boolean start() {
        if (!roster.allConnected() || !geometry.canStart()) {
            return false;
        }
        List<RobotProperties> properties = new ArrayList<>(roster.size());
        for (Roster.Slot s : roster.all()) {
            properties.add(s.properties());
        }
        core = settings.liveMetrics() ? new SimulationCore(spec, properties, AreaCoveredMetric.DEFAULT_CELL_M)
                : new SimulationCore(spec, properties);
        try {
            core.startExperiment(settings.outputDir() == null ? java.nio.file.Path.of("") : settings.outputDir(), null);
        } catch (ExperimentFailure e) {
            experimentFailed(e);
            return false;
        }
        roster.start(core);
        admission.start(core);
        geometry.start(core.map().geometryWorld());
        progress.starting();
        LOG.info("all {} robot(s) connected: running{}", roster.size(),
                settings.maxSteps() > 0 ? " for " + settings.maxSteps() + " steps" : "");
        return true;
    }

    /** Once geometry is ready: every robot is sent step 0, unless the run is to hold before it; true if it began. */
    private boolean begin(long now) {
        if (!geometry.ready()) {
            return false;
        }
        long released = progress.released();
        if (control.holdWanted()) {
            if (!beginHeld) {
                beginHeld = true;
                control.held(released);
                published.ready(true);
                LOG.info("every client is here; paused before step 1 (start or step from the control port)");
                announce(new RunState(released, RunState.Phase.PAUSED));
            }
            return false;
        }
        if (beginHeld) {
            beginHeld = false;
            control.unheld(now, 0);
        }
        announce(new RunState(released, RunState.Phase.RUNNING));
        control.restartPace(now, 0);
        releasedNanos = now;
        progress.begun();
        roster.begin();
        world = ReleasedWorld.start(core);
        published.begin(now, world);
        published.ready(true);
        listener.started(roster.size());
        WorldSnapshot start = world.snapshot(); // (the recording opens before step 0 is computed)
        for (int i = 0; i < outputs.size(); i++) {
            outputs.get(i).begun(start);
        }
        return true;
    }

    // ---- stage 1: collecting -------------------------------------------------------------------------------

    /** A robot's request for the step being collected; one out of turn drops it. */
    void request(RobotPeer peer, StepRequest request) {
        roster.request(peer, request);
    }

    /** True once every running robot's request for the step is in (and the world waits for no lost robot). */
    private boolean collected() {
        int running = roster.count(Roster.Slot.State.RUNNING);
        if (running == 0 && !roster.anyAway()) {
            finish("every robot has left", false);
            return false;
        }
        if (!roster.requestsIn() || roster.worldWaits()) {
            return false;
        }
        if (running == 0) {
            roster.waitForAnyone(); // (nobody to step for: the world waits for a robot to come back)
            return false;
        }
        return true;
    }

    // ---- stage 2: resolving --------------------------------------------------------------------------------

    /** The core steps the world, its geometry resolved by the geometry link; true if it is computed already (in-process). */
    private boolean resolve() {
        StepRequest[] batch = roster.takeRequests();
        progress.resolving();
        try {
            return core.step(progress.step(), batch, geometry) && computed();
        } catch (ProtocolException e) {
            finish("step " + StepNumbers.shown(progress.step()) + " failed: " + e.getMessage(), false);
            return false;
        } catch (ExperimentFailure e) {
            experimentFailed(e);
            return false;
        }
    }

    /** The world's loop functions threw: the run ends with their line (exit code 4). */
    private void experimentFailed(ExperimentFailure e) {
        LOG.debug("the loop functions' failure", e);
        published.experimentFailed();
        finish(e.getMessage(), false);
    }

    /** Completes the step from an answer that came later; {@code from}: the Geometry process that gave it, or null (in-process). */
    private boolean complete(GeometryStepResponse answer, GeometryPeer from) {
        try {
            core.answer(answer);
        } catch (ExperimentFailure e) {
            experimentFailed(e);
            return false;
        } catch (ProtocolException e) {
            if (from == null) {
                finish("step " + StepNumbers.shown(progress.step()) + " failed: " + e.getMessage(), false);
            } else {
                geometryLost(from, "gave a bad answer: " + e.getMessage());
            }
            return false;
        }
        return computed();
    }

    /** The step is computed: the geometry link and the roster are told, the step waits for its release. */
    private boolean computed() {
        geometry.resolved();
        roster.resolved();
        progress.computed();
        return true;
    }

    String geometryJoins(GeometryPeer peer) {
        return progress.over() ? Progress.OVER : geometry.join(peer);
    }

    void geometryReady(GeometryPeer peer) {
        int before = geometry.attaches();
        if (progress.phase() == Progress.Phase.RESOLVING) {
            control.restartPace(clock.getAsLong(), progress.step()); // a step that waited for Geometry: no rush after
        }
        geometry.attached(peer);
        if (geometry.attaches() > before) {
            published.geometryAttaches(geometry.attaches());
            listener.geometryAttached(progress.step());
        }
    }

    void geometryAnswer(GeometryPeer peer, GeometryStepResponse answer) {
        GeometryStepResponse a = geometry.answer(peer, answer);
        if (a != null && progress.phase() == Progress.Phase.RESOLVING) {
            complete(a, peer);
        }
    }

    void geometryLost(GeometryPeer peer, String why) {
        int before = geometry.losses();
        GeometryStepResponse a = geometry.lost(peer, Printable.of(why), progress.step());
        if (geometry.losses() > before) {
            published.geometryLosses(geometry.losses());
            listener.geometryLost(progress.step());
        }
        if (a != null && progress.phase() == Progress.Phase.RESOLVING) {
            complete(a, null);
        }
    }

    // ---- stage 3: releasing --------------------------------------------------------------------------------

    /**
     * At the release point: every running robot's response with the next step number (or the end), then the
     * world after the step to every listener; false while the release point holds the step.
     */
    private boolean release(long now) {
        long step = progress.step();
        if (!releasePoint.pass(now, step, progress.released())) {
            return false;
        }
        control.releasing();
        String experimentEnd = core.experimentEnd();
        boolean last = settings.maxSteps() > 0 && step >= settings.maxSteps() || experimentEnd != null;
        SimulationEnd end = !last ? null : new SimulationEnd(step - 1, experimentEnd != null
                ? experimentEnd + " after " + step + " steps" : "completed " + step + " steps");
        if (last) {
            // the outcome is on record before any robot hears of it
            published.outcome(end.reason(), true);
        }
        List<Roster.Slot> slots = roster.all();
        for (int i = 0; i < slots.size(); i++) { // (every step: no iterator)
            Roster.Slot s = slots.get(i);
            if (!s.running()) {
                continue;
            }
            if (s.leaving()) {
                core.withhold(i); // it left during this step: it goes at the step's end, and gets nothing more
                continue;
            }
            try {
                s.peer().deliver(core.response(i), step, end);
            } catch (IOException e) {
                core.withhold(i);
                roster.drop(s, "could not send its response: " + e.getMessage());
            }
        }
        core.tally(releasedStep::tookPart); // (as it went out: to one that left during the step, nothing delivered)
        long out = clock.getAsLong();
        world = world.next(step, core);
        published.released(world, out);
        published.messages(core.messagesDelivered(), core.messagesOutOfRange(), core.messagesUndeliverable());
        for (int i = 0; i < outputs.size(); i++) {
            outputs.get(i).released(world, releasedStep);
        }
        releasedNanos = out;
        if (last) {
            progress.releaseLast();
            robotsTold = true;
            finish(end.reason(), true);
            return false;
        }
        progress.release();
        roster.stepReleased();
        publish();
        control.settle(progress.released(), false); // (step N callers answered once the status shows the step's end)
        return true;
    }

    // ---- deadlines -----------------------------------------------------------------------------------------

    /** Deadlines: a Geometry process late with its answer, robots late with requests. */
    void tick(long now) {
        GeometryPeer late = geometry.overdue(now);
        if (late != null) {
            LOG.warn("Geometry process has not answered within {} ms (step {}); dropping it",
                    settings.geometryTimeoutMs(), StepNumbers.shown(progress.step()));
            geometryLost(late, "no answer within " + settings.geometryTimeoutMs() + " ms");
        }
        if (progress.phase() == Progress.Phase.COLLECTING) {
            roster.late(now, releasedNanos, settings.design().readsInWorldOrder());
        }
    }

    // ---- robots coming and going ---------------------------------------------------------------------------

    /** Hellos: answered now, or once the step being resolved is complete. */
    void hellos(Hellos hellos) {
        admission.hellos(hellos);
    }

    /** Between steps: answers the next hellos held while a step was resolved; false if there were none. */
    boolean answerHeldHellos() {
        return admission.answerHeld();
    }

    /** A robot's connection has closed or failed. */
    void left(RobotPeer peer, String why) {
        roster.left(peer, why);
    }

    // ---- viewers -------------------------------------------------------------------------------------------

    /**
     * The world a viewer that joins now starts from: as the run last released it, or, before step 0 went out,
     * every robot at its start pose (as it said it is, or as the file expects it).
     */
    WorldSnapshot snapshot() {
        return world != null ? world.snapshot() : core != null ? ReleasedWorld.start(core).snapshot()
                : ReleasedWorld.expected(spec, roster.said()).snapshot();
    }

    /** What the run is doing now, as a viewer is told it: waiting, running or paused; null once it is over. */
    RunState state() {
        return progress.over() ? null : new RunState(progress.released(), progress.phase() == Progress.Phase.WAITING
                ? RunState.Phase.WAITING : control.holding() ? RunState.Phase.PAUSED : RunState.Phase.RUNNING);
    }

    /** The end, once the run is over; else null. */
    SimulationEnd end() {
        return progress.over() ? endMessage() : null;
    }

    /** A viewer the connection watch cut off has gone. */
    void viewerDropped(String viewer, String why) {
        listener.viewerDropped(viewer, why);
    }

    private void announce(RunState state) {
        for (int i = 0; i < outputs.size(); i++) {
            outputs.get(i).state(state);
        }
    }

    // ---- the control port ----------------------------------------------------------------------------------

    void pause(CompletableFuture<Void> held) {
        control.pause(held, progress.running() && !roster.everyoneAway()); // (nothing steps: held now)
    }

    void resume(CompletableFuture<Void> applied) {
        control.resume(progress.released());
        advance(clock.getAsLong()); // (a run that may begin now begins before the answer)
        publish();
        applied.complete(null);
    }

    void stepN(long n, CompletableFuture<Long> done) {
        control.stepN(n, done, progress.released(), progress.running());
    }

    /** The control port's {@code add}: null (a hello with the rule's name joins at its pose, once) or why not. */
    String add(JoinRule rule) {
        return admission.add(rule);
    }

    /** The control port's {@code remove NAME}: null (removed now, or at the end of the step in progress) or why not. */
    String remove(String name) {
        return admission.remove(name);
    }

    // ---- the end -------------------------------------------------------------------------------------------

    /** Ends the run (once): robots, viewers, the recording and Geometry are told why; held hellos are refused. */
    void finish(String reason, boolean asPlanned) {
        if (progress.over()) {
            return;
        }
        if (progress.phase() != Progress.Phase.WAITING) {
            roster.applyLeaving(); // (the departures held back are on record)
        }
        progress.end();
        String why = reason;
        boolean planned = asPlanned;
        if (core != null) {
            try {
                core.endExperiment(); // (first: a throw of its destroy is the run's end, on record everywhere)
            } catch (ExperimentFailure e) {
                if (planned) {
                    published.experimentFailed();
                    why = e.getMessage();
                    planned = false;
                } else {
                    LOG.warn("{}", e.getMessage()); // (the run failed already: its first reason stays)
                }
            }
        }
        published.ended(why, planned, clock.getAsLong());
        SimulationEnd end = endMessage();
        roster.end(end, robotsTold);
        for (int i = 0; i < outputs.size(); i++) {
            outputs.get(i).ended(end);
        }
        geometry.end(end);
        publish();
        LOG.info("simulation over after {} steps: {}", progress.released(), Printable.of(why));
        listener.ended(published.summary(roster.size()));
        closeOut();
    }

    /**
     * Once the run is over (and by the loop, last, whatever happened): whoever still waits is answered (held
     * hellos refused, pause and step N callers) and the last state is published. Again does nothing more.
     */
    void closeOut() {
        admission.refuseHeld();
        published.ready(false); // (whoever waits for a start that will not come; once it came, nothing)
        publish();
        control.settle(progress.released(), true);
    }

    /** The end; its last step is the last whose responses went out (a step computed and held by the pace is not). */
    private SimulationEnd endMessage() {
        return new SimulationEnd(progress.released() - 1, published.endReason());
    }
}

package robosim.environment.net;

import java.io.IOException;
import java.util.Arrays;
import java.util.concurrent.CompletableFuture;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.GeometryStepRequest;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.PoseUpdate;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotView;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;
import robosim.protocol.WorldSnapshot;
import robosim.protocol.RunState;

/**
 * The step as the {@link SimulationLoop} runs it, one phase after another: collecting every robot's
 * request, resolving (through the {@link GeometryLink}: at once in-process, or Geometry's round trip as
 * events), completing it in the core, releasing (at the {@link ReleasePoint}: every response with the
 * next step number, then the poses to the viewers), and the deadlines of each phase. The run's start
 * and end are {@link RunLifecycle}'s. Loop thread only.
 */
final class StepCycle extends JoinCycle {
    private static final Logger LOG = LoggerFactory.getLogger(StepCycle.class);

    /** The requests of the step last computed, kept until the next: what each robot asked (its view). */
    private StepRequest[] releasedRequests;

    StepCycle(ClientWorkerCoordinator coordinator, RunListener listener) {
        super(coordinator, listener);
        releasedRequests = new StepRequest[requests.length];
    }

    @Override
    void grow(int n) {
        super.grow(n);
        releasedRequests = Arrays.copyOf(releasedRequests, n);
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
                    startRecording(); // (before step 0 is computed: the world as it starts)
                }
                case COLLECTING -> {
                    if (activeCount == 0 && !away.any()) {
                        finish("every robot has left", false);
                        return;
                    }
                    if (arrived < activeCount || away.worldWaits()) {
                        return;
                    }
                    if (activeCount == 0) {
                        waitForAnyone(); // (nobody to step for: the world waits for a robot to come back)
                        return;
                    }
                    compute();
                }
                case RELEASING -> {
                    if (!releasePoint.mayRelease(now, step, released)) {
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

    // ---- collecting, resolving -----------------------------------------------------------------------

    void request(RobotPeer worker, StepRequest request) {
        int i = worker.index();
        if (i < 0 || robots[i] != worker || core == null || !core.present(i) || away.isAway(i) || phase == Phase.ENDED) {
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
        geometry.resolved();
        StepRequest[] done = inFlight;
        inFlight = releasedRequests;
        releasedRequests = done;
        Arrays.fill(inFlight, null);
        step++;
        record.stepsComputed = step;
        phase = Phase.RELEASING;
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

    // ---- releasing ------------------------------------------------------------------------------------

    /** When the computed step may go out by the pace (ns), if it waits for it; else far in the future. */
    long paceDue() {
        return phase == Phase.RELEASING ? releasePoint.paceDue(step) : Long.MAX_VALUE;
    }

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
        for (int i = 0; i < robots.length; i++) {
            if (!core.present(i) || away.isAway(i)) {
                continue;
            }
            if (leaving[i]) {
                core.withhold(i); // it left during this step: it goes at the step's end, and gets nothing more
                continue;
            }
            try {
                robots[i].deliver(core.response(i), step, end);
            } catch (IOException e) {
                robots[i].drop();
                core.withhold(i);
                depart(i, "could not send its response: " + e.getMessage());
            }
        }
        long now = System.nanoTime();
        released = step;
        record.released(released, now);
        record.messages(core.messagesDelivered(), core.messagesOutOfRange(), core.messagesUndeliverable());
        control.settle(released, false);
        boolean recording = recorder != null && recorder.recording();
        if (!viewers.isEmpty() || recording) {
            PoseUpdate update = core.viewerUpdate();
            WorldSnapshot roster = takeRosterChange(step - 1);
            if (!viewers.isEmpty()) {
                viewers.publish(roster, update, this::viewOf);
            }
            if (recording) {
                recorded(roster, update);
            }
        }
        releasedNanos = now; // robots are timed from here
        if (last) {
            robotsTold = true;
            finish(end.reason(), true);
        } else {
            phase = Phase.COLLECTING;
            departDeferred();
            bringBackReturning();
        }
    }

    /** Deadlines: a viewer stuck in a write, a Geometry process late with its answer, robots late with requests. */
    void tick(long now) {
        viewers.dropStuck(now);
        GeometryClientWorker late = geometry.overdue(now);
        if (late != null) {
            LOG.warn("Geometry process has not answered within {} ms (step {}); dropping it",
                    settings.geometryTimeoutMs(), step);
            geometryLost(late, "no answer within " + settings.geometryTimeoutMs() + " ms");
        }
        if (phase == Phase.COLLECTING) {
            removeOverdue(now);
        }
        if (phase == Phase.COLLECTING && now - releasedNanos > stepTimeoutNanos) {
            boolean sequential = settings.design() == CoordinatorDesign.SEQUENTIAL;
            for (int i = 0; i < robots.length; i++) {
                if (core.present(i) && requests[i] == null && away.lateSinceBack(i, now, stepTimeoutNanos)) {
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

    /** A viewer joins: it gets the snapshot it starts from, then the run's state (or its end). */
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

    // ---- the recording ---------------------------------------------------------------------------------

    /**
     * The step just released, to the recording: the viewers' update, the requests and responses of those that
     * took part (one that left during it: what it asked, and that nothing reached it).
     */
    private void recorded(WorldSnapshot roster, PoseUpdate update) {
        StepRequest[] asked = new StepRequest[robots.length];
        StepResponse[] responses = new StepResponse[robots.length];
        for (int i = 0; i < robots.length; i++) {
            if (core.present(i) && !away.isAway(i)) {
                asked[i] = releasedRequests[i];
                responses[i] = core.response(i);
            }
        }
        recorder.step(roster, update, asked, responses);
    }

    /** Robot i's view of the step just released, for a viewer that watches it; null if it did not take part. */
    private RobotView viewOf(int i) {
        if (i >= robots.length || !core.present(i) || away.isAway(i)) {
            return null;
        }
        return RobotView.of(step - 1, i, name(i), releasedRequests[i], core.response(i));
    }
}

package robosim.environment.net;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import robosim.environment.core.JoinRule;
import robosim.environment.server.ViewerSink;
import robosim.environment.server.Viewers;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.RobotHello;
import robosim.protocol.StepRequest;
import robosim.protocol.WorldSnapshot;

/**
 * What other threads post to the {@link SimulationLoop}, the one owner of simulation time, through its
 * {@link Inbox}: socket readers hand in requests and say who came and went, the Geometry worker hands in
 * answers, the control port asks for pause, resume, step N, add, remove and stop. Each applies itself to
 * the {@link Run} on the loop thread, and each knows how it is refused when the run is over, so nobody
 * waits on an answer that will not come. Nothing else changes the run.
 */
sealed interface LoopEvent extends Inbox.Event<Run> {
    /** Why an event that needs the run is refused once it is over. */
    String OVER = "the simulation is over";

    @Override
    default void refuse() {
    }

    /** A robot said hello (already checked against the file); the verdict is null (welcome sent) or a refusal. */
    record RobotJoins(RobotPeer worker, RobotHello hello, int index, CompletableFuture<String> verdict)
            implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.hello(this);
        }

        @Override
        public void refuse() {
            verdict.complete(OVER);
        }
    }

    /**
     * The robots of a shared connection said hello, each already checked: the loop answers them all at
     * once (each {@code RobotJoins}'s verdict), writes their welcomes in one frame, then completes
     * {@code answered} with true; false when the loop never took it (the worker then refuses them itself).
     */
    record SharedJoins(SharedConnection connection, List<RobotJoins> joins, CompletableFuture<Boolean> answered)
            implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.hello(this);
        }

        @Override
        public void refuse() {
            answered.complete(false);
        }
    }

    /** Several events read at once, in order (a shared connection's frame, the SEQUENTIAL stepper's requests). */
    record Batch(List<LoopEvent> events) implements LoopEvent {
        @Override
        public void apply(Run run) {
            for (LoopEvent e : events) {
                e.apply(run);
            }
        }

        @Override
        public void refuse() {
            events.forEach(LoopEvent::refuse);
        }
    }

    /** A robot's request for the step it was last given. */
    record Request(RobotPeer worker, StepRequest request) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.request(worker, request);
        }
    }

    /** Robots in the Environment's JVM: the last request owed has come from a control thread ({@link InMemoryRequests}). */
    record InMemoryArrived() implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.inMemoryArrived();
        }
    }

    /** A robot's connection has closed or failed, or it broke the protocol. */
    record RobotLeaves(RobotPeer worker, String why) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.left(worker, why);
        }
    }

    /** A Geometry process said hello; the verdict is null (accepted) or a refusal. */
    record GeometryJoins(GeometryClientWorker worker, CompletableFuture<String> verdict) implements LoopEvent {
        @Override
        public void apply(Run run) {
            verdict.complete(run.geometryJoins(worker));
        }

        @Override
        public void refuse() {
            verdict.complete(OVER);
        }
    }

    /** A Geometry process has been sent the world and takes steps now. */
    record GeometryReady(GeometryClientWorker worker) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.geometryReady(worker);
        }
    }

    /** A Geometry process's answer to the step it was asked. */
    record GeometryAnswer(GeometryClientWorker worker, GeometryStepResponse answer) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.geometryAnswer(worker, answer);
        }
    }

    /** A Geometry process's connection has closed or failed. */
    record GeometryLeaves(GeometryClientWorker worker, String why) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.geometryLost(worker, why);
        }
    }

    /** A viewer said hello; it gets the snapshot it starts from, and updates follow without a gap. */
    record ViewerJoins(ViewerSink viewer, CompletableFuture<WorldSnapshot> snapshot) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.addViewer(viewer, snapshot);
        }

        @Override
        public void refuse() {
            snapshot.completeExceptionally(new IOException(OVER));
        }
    }

    /**
     * A viewer's worker has ended; {@code cutOff}: the connection watch cut it off (it did not take a write). Once
     * the run is over it leaves {@code viewers} at once.
     */
    record ViewerLeaves(ViewerSink viewer, String why, boolean cutOff, Viewers viewers) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.viewerLeft(viewer, why, cutOff);
        }

        @Override
        public void refuse() {
            viewers.remove(viewer, why);
        }
    }

    /** A recording viewer that was full has taken updates: a step held for it may go out (the loop tries again). */
    record ViewerHasRoom() implements LoopEvent {
        @Override
        public void apply(Run run) {
        }
    }

    /** Pause after the step in progress; {@code held} completes once the run holds (or is not running). */
    record Pause(CompletableFuture<Void> held) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.pause(held);
        }

        @Override
        public void refuse() {
            held.complete(null);
        }
    }

    /** Run on; {@code applied} completes once the run's state says so (a status right after sees it). */
    record Resume(CompletableFuture<Void> applied) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.resume(applied);
        }

        @Override
        public void refuse() {
            applied.complete(null);
        }
    }

    /** Run {@code n} more steps, then hold; {@code done} completes with the steps released so far (null: refused). */
    record StepN(long n, CompletableFuture<Long> done) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.stepN(n, done);
        }

        @Override
        public void refuse() {
            done.complete(null);
        }
    }

    /** The control port adds a robot: its rule (its name, type and pose); {@code verdict}: null (it may join) or why not. */
    record AddRobot(JoinRule rule, CompletableFuture<String> verdict) implements LoopEvent {
        @Override
        public void apply(Run run) {
            String why = run.add(rule);
            run.publish(); // (a status asked once it is answered lists it)
            verdict.complete(why);
        }

        @Override
        public void refuse() {
            verdict.complete(OVER);
        }
    }

    /** The control port removes a robot; {@code verdict}: null (removed, or at the step's end) or why not. */
    record RemoveRobot(String name, CompletableFuture<String> verdict) implements LoopEvent {
        @Override
        public void apply(Run run) {
            String why = run.remove(name);
            run.publish(); // (a status asked once it is answered shows it)
            verdict.complete(why);
        }

        @Override
        public void refuse() {
            verdict.complete(OVER);
        }
    }

    /** Ends the run, for {@code reason}. */
    record Stop(String reason) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.finish(reason, false);
        }
    }
}

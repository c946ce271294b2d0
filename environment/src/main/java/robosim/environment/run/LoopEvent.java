package robosim.environment.run;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import robosim.environment.core.JoinRule;
import robosim.environment.server.ViewerSink;
import robosim.environment.server.Viewers;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.RobotHello;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.WorldSnapshot;

/**
 * What other threads post to the {@link SimulationLoop}, the one owner of simulation time, through its
 * {@link Inbox}: robots' transports hand in hellos, requests and departures, the Geometry worker hands in
 * answers, viewer workers say who came and went, the control port asks for pause, resume, step N, add, remove
 * and stop. Each applies itself to the {@link Run} on the loop thread, and each knows how it is refused when the
 * run is over, so nobody waits on an answer that will not come. Nothing else changes the run. No event is any
 * one transport's: a socket per robot, a shared connection and a robot in this JVM all post these.
 */
public sealed interface LoopEvent extends Inbox.Event<Run> {
    @Override
    default void refuse() {
    }

    /** Robots' hellos that came together, for the run's {@link Admission} (refused: each is told the run is over). */
    record HellosCome(Hellos hellos) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.hellos(hellos);
        }

        @Override
        public void refuse() {
            hellos.refuse();
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
    record Request(RobotPeer peer, StepRequest request) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.request(peer, request);
        }
    }

    /**
     * Something the loop looks at between events has changed: requests have come from robots in this JVM (a
     * {@link LoopHook} hands them in), a recording viewer has room again. The loop moves the run on.
     */
    record Wake() implements LoopEvent {
        @Override
        public void apply(Run run) {
        }
    }

    /** A robot's connection has closed or failed, or it broke the protocol. */
    record RobotLeaves(RobotPeer peer, String why) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.left(peer, why);
        }
    }

    /** A Geometry process said hello; the verdict is null (accepted) or a refusal. */
    record GeometryJoins(GeometryPeer peer, CompletableFuture<String> verdict) implements LoopEvent {
        @Override
        public void apply(Run run) {
            verdict.complete(run.geometryJoins(peer));
        }

        @Override
        public void refuse() {
            verdict.complete(Progress.OVER);
        }
    }

    /** A Geometry process has been sent the world and takes steps now. */
    record GeometryReady(GeometryPeer peer) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.geometryReady(peer);
        }
    }

    /** A Geometry process's answer to the step it was asked. */
    record GeometryAnswer(GeometryPeer peer, GeometryStepResponse answer) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.geometryAnswer(peer, answer);
        }
    }

    /** A Geometry process's connection has closed or failed. */
    record GeometryLeaves(GeometryPeer peer, String why) implements LoopEvent {
        @Override
        public void apply(Run run) {
            run.geometryLost(peer, why);
        }
    }

    /** A viewer said hello: it joins {@code viewers} and gets the snapshot it starts from; updates follow without a gap. */
    record ViewerJoins(ViewerSink viewer, Viewers viewers, CompletableFuture<WorldSnapshot> snapshot)
            implements LoopEvent {
        @Override
        public void apply(Run run) {
            viewers.add(viewer);
            snapshot.complete(run.snapshot());
            SimulationEnd end = run.end();
            if (end != null) {
                viewer.queue().end(end);
            } else {
                viewer.queue().state(run.state());
            }
        }

        @Override
        public void refuse() {
            snapshot.completeExceptionally(new IOException(Progress.OVER));
        }
    }

    /**
     * A viewer's worker has ended; {@code cutOff}: the connection watch cut it off (it did not take a write). Once
     * the run is over it leaves {@code viewers} at once.
     */
    record ViewerLeaves(ViewerSink viewer, String why, boolean cutOff, Viewers viewers) implements LoopEvent {
        @Override
        public void apply(Run run) {
            if (viewers.remove(viewer, why) && cutOff) {
                run.viewerDropped(viewer.viewerName(), why);
            }
        }

        @Override
        public void refuse() {
            viewers.remove(viewer, why);
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
            verdict.complete(Progress.OVER);
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
            verdict.complete(Progress.OVER);
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

package robosim.environment.net;

import java.util.List;
import java.util.concurrent.CompletableFuture;
import robosim.protocol.GeometryStepResponse;
import robosim.protocol.RobotHello;
import robosim.protocol.StepRequest;
import robosim.protocol.WorldSnapshot;

/**
 * What other threads post to the {@link SimulationLoop}, the one owner of simulation time: socket
 * readers hand in requests and say who came and went, the Geometry worker hands in answers, the
 * control port asks for pause, resume, step N and stop. Nothing else changes the run.
 */
sealed interface LoopEvent {
    /** A robot said hello (already checked against the file); the verdict is null (welcome sent) or a refusal. */
    record RobotJoins(RobotPeer worker, RobotHello hello, int index, CompletableFuture<String> verdict)
            implements LoopEvent {
    }

    /**
     * The robots of a shared connection said hello, each already checked: the loop answers them all at
     * once (each {@code RobotJoins}'s verdict), writes their welcomes in one frame, then completes
     * {@code answered} with true; false when the loop never took it (the worker then refuses them itself).
     */
    record SharedJoins(SharedConnection connection, List<RobotJoins> joins, CompletableFuture<Boolean> answered)
            implements LoopEvent {
    }

    /** Several events read at once, in order (the SEQUENTIAL stepper's requests): one wake-up for all. */
    record Batch(List<LoopEvent> events) implements LoopEvent {
    }

    /** A robot's request for the step it was last given. */
    record Request(RobotPeer worker, StepRequest request) implements LoopEvent {
    }

    /** A robot's connection has closed or failed, or it broke the protocol. */
    record RobotLeaves(RobotPeer worker, String why) implements LoopEvent {
    }

    /** A Geometry process said hello; the verdict is null (accepted) or a refusal. */
    record GeometryJoins(GeometryClientWorker worker, CompletableFuture<String> verdict) implements LoopEvent {
    }

    /** A Geometry process has been sent the world and takes steps now. */
    record GeometryReady(GeometryClientWorker worker) implements LoopEvent {
    }

    /** A Geometry process's answer to the step it was asked. */
    record GeometryAnswer(GeometryClientWorker worker, GeometryStepResponse answer) implements LoopEvent {
    }

    /** A Geometry process's connection has closed or failed. */
    record GeometryLeaves(GeometryClientWorker worker, String why) implements LoopEvent {
    }

    /** A viewer said hello; it gets the snapshot it starts from, and updates follow without a gap. */
    record ViewerJoins(ViewerClientWorker viewer, CompletableFuture<WorldSnapshot> snapshot) implements LoopEvent {
    }

    /** A recording viewer that was full has taken updates: a step held for it may go out. */
    record ViewerHasRoom(ViewerClientWorker viewer) implements LoopEvent {
    }

    /** Pause after the step in progress; {@code held} completes once the run holds (or is not running). */
    record Pause(CompletableFuture<Void> held) implements LoopEvent {
    }

    /** Run on; {@code applied} completes once the run's state says so (a status right after sees it). */
    record Resume(CompletableFuture<Void> applied) implements LoopEvent {
    }

    /** Run {@code n} more steps, then hold; {@code done} completes with the steps released so far. */
    record StepN(long n, CompletableFuture<Long> done) implements LoopEvent {
    }

    /** The control port adds a robot: its rule (its name, type and pose); {@code verdict}: null (it may join) or why not. */
    record AddRobot(robosim.environment.core.JoinRule rule, CompletableFuture<String> verdict) implements LoopEvent {
    }

    /** The control port removes a robot; {@code verdict}: null (removed, or at the step's end) or why not. */
    record RemoveRobot(String name, CompletableFuture<String> verdict) implements LoopEvent {
    }

    record Stop(String reason) implements LoopEvent {
    }
}

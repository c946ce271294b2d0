package robosim.environment.net;

import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotModels;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * Test fixture: a robot without a socket whose place in the world the loop assigns (a file's robot, one that
 * joins, one that takes over). It answers each step it is given at once, on the loop thread, by posting its
 * request - so nothing depends on timing - and at step {@code leaveAt} posts that its connection closed
 * instead.
 */
final class Bot implements RobotPeer {
    private final ClientWorkerCoordinator coordinator;
    final String name;
    private final long leaveAt;
    private volatile int index = -1;
    volatile RobotWelcome welcome;
    /** The first step it was given (-1 before). */
    volatile long firstStep = -1;
    final BlockingQueue<StepResponse> responses = new LinkedBlockingQueue<>();
    final CompletableFuture<SimulationEnd> end = new CompletableFuture<>();
    private volatile boolean closed;

    Bot(ClientWorkerCoordinator coordinator, String name, long leaveAt) {
        this.coordinator = coordinator;
        this.name = name;
        this.leaveAt = leaveAt;
    }

    /** Says hello (as the file's robot {@code fileIndex}, or -1 for one that is not in the file); the verdict. */
    CompletableFuture<String> hello(int fileIndex) {
        CompletableFuture<String> verdict = new CompletableFuture<>();
        coordinator.post(new LoopEvent.RobotJoins(this, new RobotHello(name, RobotModels.AR_ROBOT), fileIndex, verdict));
        return verdict;
    }

    /** Its connection closes now. */
    void leave(String why) {
        closed = true;
        coordinator.post(new LoopEvent.RobotLeaves(this, why));
    }

    @Override
    public int index() {
        return index;
    }

    @Override
    public void assign(int i) {
        index = i;
    }

    @Override
    public void welcome(RobotWelcome w) {
        welcome = w;
    }

    @Override
    public void begin(long first) {
        firstStep = first;
        answer(first);
    }

    @Override
    public void deliver(StepResponse response, long nextStep, SimulationEnd e) {
        responses.add(response);
        if (e != null) {
            end.complete(e);
        } else {
            answer(nextStep);
        }
    }

    private void answer(long k) {
        if (closed) {
            return;
        }
        if (k == leaveAt) {
            leave("its connection closed at step " + k);
            return;
        }
        coordinator.post(new LoopEvent.Request(this, new StepRequest(k, 100, 0, false, List.of(), List.of())));
    }

    @Override
    public void end(SimulationEnd e, boolean midStep) {
        end.complete(e);
    }

    @Override
    public boolean begun() {
        return firstStep >= 0;
    }

    @Override
    public boolean closed() {
        return closed;
    }

    @Override
    public void drop() {
        closed = true;
    }
}

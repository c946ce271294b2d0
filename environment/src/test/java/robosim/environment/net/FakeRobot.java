package robosim.environment.net;

import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * Test fixture: a robot without a socket. It answers each step it is given at once, on the thread that
 * gives it (the loop's), by posting its request for that step - so its request is in the loop's queue
 * before the loop starts timing it - until {@code silentFrom}, from which it says nothing.
 */
final class FakeRobot implements RobotPeer {
    private final ClientWorkerCoordinator coordinator;
    private final int index;
    private final long silentFrom;
    final BlockingQueue<StepResponse> responses = new LinkedBlockingQueue<>();
    final BlockingQueue<SimulationEnd> ends = new LinkedBlockingQueue<>();
    private volatile boolean begun;
    private volatile boolean dropped;

    FakeRobot(ClientWorkerCoordinator coordinator, int index, long silentFrom) {
        this.coordinator = coordinator;
        this.index = index;
        this.silentFrom = silentFrom;
    }

    @Override
    public int index() {
        return index;
    }

    @Override
    public void assign(int i) {
        if (i != index) {
            throw new IllegalStateException("robot " + index + " assigned " + i);
        }
    }

    @Override
    public void welcome(RobotWelcome welcome) {
    }

    @Override
    public void begin(long firstStep) {
        begun = true;
        answer(firstStep);
    }

    @Override
    public void deliver(StepResponse response, long nextStep, SimulationEnd end) {
        responses.add(response);
        if (end != null) {
            ends.add(end);
        } else {
            answer(nextStep);
        }
    }

    private void answer(long k) {
        if (k < silentFrom && !dropped) {
            coordinator.post(new LoopEvent.Request(this, new StepRequest(k, 100, 0, false, List.of(),
                    List.of("thread"))));
        }
    }

    @Override
    public void end(SimulationEnd end, boolean midStep) {
        ends.add(end);
    }

    @Override
    public boolean begun() {
        return begun;
    }

    @Override
    public boolean closed() {
        return dropped;
    }

    @Override
    public void drop() {
        dropped = true;
    }

    boolean dropped() {
        return dropped;
    }
}

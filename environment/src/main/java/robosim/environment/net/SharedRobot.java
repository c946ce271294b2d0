package robosim.environment.net;

import robosim.environment.run.RobotPeer;
import robosim.protocol.Protocol;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * One robot of a {@link SharedConnection}, as the {@link SimulationLoop} sees it: what the loop sends it
 * goes into the connection's next frame (written once the loop has done what it does now, see
 * {@link SharedOutput}); its requests come from the connection's reader. Dropping it ends this robot
 * alone: it is told the end in the next frame, and what it sends after is ignored.
 */
final class SharedRobot implements RobotPeer {
    private final SharedConnection connection;
    private final int slot;
    private final String name;
    private final RequestOrder order;
    private volatile int index = -1;
    /** Ended or dropped: nothing more goes to it, what it sends is ignored. */
    private volatile boolean ended;

    SharedRobot(SharedConnection connection, int slot, String name) {
        this.connection = connection;
        this.slot = slot;
        this.name = name;
        this.order = new RequestOrder(name);
    }

    String name() {
        return name;
    }

    int slot() {
        return slot;
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
    public void welcome(RobotWelcome welcome) {
        connection.replies().welcome(slot, welcome);
        connection.buffered();
    }

    /** Loop thread: its refusal goes into the connection's frame (written by the loop if a robot of it was welcomed). */
    @Override
    public void refused(String why) {
        connection.replies().welcome(slot, RobotWelcome.refused(why));
    }

    @Override
    public void begin(long firstStep) {
        order.begin(firstStep);
        connection.replies().step(slot, firstStep);
        connection.buffered();
    }

    @Override
    public void deliver(StepResponse response, long nextStep, SimulationEnd end) {
        if (end == null) {
            order.given(nextStep);
            connection.replies().response(slot, response, nextStep);
        } else {
            ended = true;
            connection.replies().response(slot, response, Protocol.END_OF_SIMULATION);
            connection.replies().end(slot, end);
        }
        connection.buffered();
    }

    @Override
    public void end(SimulationEnd end, boolean midStep) {
        if (!ended) {
            ended = true;
            connection.replies().end(slot, end);
            connection.buffered();
        }
    }

    @Override
    public boolean begun() {
        return order.begun();
    }

    @Override
    public boolean closed() {
        return ended || connection.closed();
    }

    /** Loop thread: ends this robot alone (the loop says why in its log and in the run's record). */
    @Override
    public void drop() {
        end(new SimulationEnd(order.given() - 1, "dropped by the Environment"), true);
    }

    /** True once it has been ended or dropped: what it sends is ignored. */
    boolean ended() {
        return ended;
    }

    /** The reader: checks this robot's request ({@link RequestOrder}). */
    void check(StepRequest request) throws ProtocolException {
        order.check(request);
    }
}

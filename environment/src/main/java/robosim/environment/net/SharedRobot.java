package robosim.environment.net;

import robosim.protocol.Printable;
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
    private volatile int index = -1;
    /** The last step number the loop has handed this robot (-1 before the first). */
    private volatile long given = -1;
    /** The first step number the loop handed this robot. */
    private volatile long first = -1;
    /** The reader's: the step this robot's next request must be for (-1: its first). */
    private long due = -1;
    /** Ended or dropped: nothing more goes to it, what it sends is ignored. */
    private volatile boolean ended;

    SharedRobot(SharedConnection connection, int slot, String name) {
        this.connection = connection;
        this.slot = slot;
        this.name = name;
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

    @Override
    public void begin(long firstStep) {
        first = firstStep;
        given = firstStep;
        connection.replies().step(slot, firstStep);
        connection.buffered();
    }

    @Override
    public void deliver(StepResponse response, long nextStep, SimulationEnd end) {
        if (end == null) {
            given = nextStep;
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
        return given >= 0;
    }

    @Override
    public boolean closed() {
        return ended || connection.closed();
    }

    /** Loop thread: ends this robot alone (the loop says why in its log and in the run's record). */
    @Override
    public void drop() {
        end(new SimulationEnd(given - 1, "dropped by the Environment"), true);
    }

    /** True once it has been ended or dropped: what it sends is ignored. */
    boolean ended() {
        return ended;
    }

    /**
     * The reader: checks this robot's request, which must be for the step due (its first, then one after
     * another), a step it has been given, with finite numbers.
     */
    void check(StepRequest request) throws ProtocolException {
        long g = given;
        if (g < 0) {
            throw new ProtocolException("sent a request for robot " + Printable.of(name)
                    + " before the simulation started");
        }
        long k = due < 0 ? first : due;
        if (request.step() != k || k > g) {
            throw new ProtocolException("sent a request for step " + request.step() + " for robot "
                    + Printable.of(name) + " where step " + Math.min(k, g) + " was due");
        }
        if (!Double.isFinite(request.moveMm()) || !Double.isFinite(request.turnDeg())) {
            throw new ProtocolException("asked robot " + Printable.of(name) + " to move " + request.moveMm()
                    + " mm and turn " + request.turnDeg() + " deg");
        }
        due = k + 1;
    }
}

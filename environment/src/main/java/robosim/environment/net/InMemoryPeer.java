package robosim.environment.net;

import robosim.environment.run.RobotPeer;
import java.util.concurrent.atomic.AtomicBoolean;
import robosim.protocol.InMemoryLink;
import robosim.protocol.Protocol;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * A robot in the Environment's own JVM (a one-JVM run), as the {@link SimulationLoop} sees it: its welcome,
 * step numbers, responses and end go straight to its Hardware Simulator ({@link InMemoryLink.Robot}), on the
 * loop thread, and its requests come back through {@link InMemoryTransport}, at once or from its control
 * thread. It cannot break the protocol (nothing is read), so it leaves only when the loop drops it or the run
 * ends.
 */
final class InMemoryPeer implements RobotPeer, InMemoryLink.Environment {
    private final InMemoryTransport transport;
    private final String name;
    private InMemoryLink.Robot robot;
    private volatile int index = -1;
    private volatile long given = -1;
    private volatile boolean closed;
    /** A step has been given whose request has not come yet (set by the loop, cleared by whoever settles it). */
    final AtomicBoolean owes = new AtomicBoolean();

    InMemoryPeer(InMemoryTransport transport, String name) {
        this.transport = transport;
        this.name = name;
    }

    /** Before its hello: the robot this peer speaks for. */
    void attach(InMemoryLink.Robot r) {
        robot = r;
    }

    String name() {
        return name;
    }

    /** Its hello, as its Hardware Simulator says it. */
    RobotHello hello() {
        return robot.hello();
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
        robot.welcome(welcome);
    }

    @Override
    public void begin(long firstStep) {
        given = firstStep;
        transport.owe(this);
        transport.given(this, robot.step(firstStep));
    }

    @Override
    public void deliver(StepResponse response, long nextStep, SimulationEnd end) {
        if (end != null) {
            robot.respond(response, Protocol.END_OF_SIMULATION);
            close(end);
            return;
        }
        given = nextStep;
        transport.owe(this);
        transport.given(this, robot.respond(response, nextStep));
    }

    @Override
    public void end(SimulationEnd end, boolean midStep) {
        close(end);
    }

    private void close(SimulationEnd end) {
        if (!closed) {
            closed = true;
            transport.forgive(this);
            robot.end(end);
        }
    }

    @Override
    public boolean begun() {
        return given >= 0;
    }

    @Override
    public boolean closed() {
        return closed;
    }

    /** Loop thread: ends this robot (the loop says why in its log and in the run's record). */
    @Override
    public void drop() {
        close(new SimulationEnd(given - 1, "dropped by the Environment"));
    }

    /** Its control thread: the request for the step it was last given. */
    @Override
    public void request(StepRequest request) {
        transport.arrived(this, request);
    }
}

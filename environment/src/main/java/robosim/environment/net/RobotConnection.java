package robosim.environment.net;

import robosim.environment.run.HelloCheck;
import robosim.environment.run.Hellos;
import robosim.environment.run.LoopEvent;
import robosim.environment.run.RobotPeer;
import java.io.IOException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.environment.server.ConnectionClock;
import robosim.environment.server.ClientWorker;
import robosim.environment.server.Handshake;
import robosim.protocol.ObjectConnection;
import robosim.protocol.Printable;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * One robot's Hardware Simulator over a socket of its own, as the loop sees it (a {@link RobotPeer}) and as its
 * worker thread serves it: the handshake, then its requests, read as the {@link Design} says (each posted to the
 * loop, or left to the {@code SEQUENTIAL} stepper after step 0) and checked in their {@link RequestOrder}. The
 * loop's writes go through its {@link RobotOutput} (the loop writes them itself, or a writer thread of its own
 * does). A request for a step this robot was not given, or with a non-finite action, drops this robot alone.
 */
final class RobotConnection implements RobotPeer {
    private static final Logger LOG = LoggerFactory.getLogger(RobotConnection.class);

    private final ClientWorker worker;
    private final RobotContext robots;
    private final ObjectConnection connection;
    private final String name;
    private final RequestOrder order = new RequestOrder(null);
    private volatile int index = -1;
    /** The loop's own writes (the welcome, the first step; every response unless the design has a writer). */
    private volatile LoopWrites loopWrites;
    private volatile RobotOutput output;
    private volatile boolean closed;
    /** SEQUENTIAL: counted down once the worker has read (or failed to read) the step-0 request. */
    private final CountDownLatch firstRead = new CountDownLatch(1);

    RobotConnection(ClientWorker worker, RobotContext robots, ObjectConnection connection, String name) {
        this.worker = worker;
        this.robots = robots;
        this.connection = connection;
        this.name = name;
        this.loopWrites = new LoopWrites(connection, worker.clock(), true);
        this.output = loopWrites;
    }

    /** The worker's thread: the handshake of {@code hello}, then every request until the connection ends. */
    void serve(RobotHello hello, Handshake handshake) throws IOException, InterruptedException {
        String refusal = handshake.heard("robot");
        HelloCheck.Checked checked = null;
        if (refusal == null) {
            checked = robots.check().admit(hello);
            refusal = checked.refusal();
        }
        if (refusal == null) {
            CompletableFuture<String> verdict = new CompletableFuture<>();
            robots.loop().post(new LoopEvent.HellosCome(Hellos.of(new Hellos.Hello(this, checked.hello(),
                    checked.index(), verdict))));
            refusal = handshake.verdict(verdict);
        }
        if (refusal != null) {
            handshake.refused(refusal);
            worker.send(RobotWelcome.refused(refusal));
            return;
        }
        worker.rename("robot-worker[" + Printable.of(name) + "]");
        handshake.accepted();
        try {
            robots.design().read(this, robots.loop());
        } finally {
            output.close();
        }
    }

    /** Reads and checks this robot's next request, on its worker's or the stepper's thread. */
    StepRequest readRequest() throws IOException {
        StepRequest request = connection.read(StepRequest.class);
        order.check(request);
        return request;
    }

    /** SEQUENTIAL, the stepper: true if this robot has sent something not read yet (a read would not block). */
    boolean hasInput() {
        return connection.hasInput();
    }

    /** SEQUENTIAL, the stepper: waits until the worker is done with the step-0 request. */
    void awaitFirstRead() throws InterruptedException {
        firstRead.await();
    }

    /** SEQUENTIAL, the worker: done with the step-0 request (read or failed); the stepper reads from now on. */
    void firstRead() {
        firstRead.countDown();
    }

    /** True once {@link #drop} was called: the stepper skips it. */
    boolean dropped() {
        return worker.dropped();
    }

    ConnectionClock clock() {
        return worker.clock();
    }

    /** Its connection, for a writer thread of its own ({@code TWO_THREADS}). */
    ObjectConnection connection() {
        return connection;
    }

    /** The name it said, for its threads' names. */
    String name() {
        return name;
    }

    @Override
    public int index() {
        return index;
    }

    @Override
    public void assign(int i) {
        index = i;
    }

    /** Loop thread: sends the welcome; its design's output takes the responses from now on. */
    @Override
    public void welcome(RobotWelcome welcome) throws IOException {
        LoopWrites writes = new LoopWrites(connection, worker.clock(), welcome.stepMessages());
        loopWrites = writes;
        writes.welcome(welcome);
        output = robots.design().output(this, writes, welcome.stepMessages());
    }

    /** Loop thread: sends the first step number. */
    @Override
    public void begin(long firstStep) throws IOException {
        order.begin(firstStep);
        loopWrites.step(firstStep);
    }

    /** Loop thread: this robot's response and then the next step number (unless step messages are off), or the end. */
    @Override
    public void deliver(StepResponse response, long nextStep, SimulationEnd end) throws IOException {
        if (end == null) {
            order.given(nextStep);
        }
        output.response(response, nextStep, end);
    }

    /**
     * Loop thread: ends the simulation for this robot out of turn. {@code midStep}: it has been given a step
     * number and will read an object next; otherwise it is waiting for a step number.
     */
    @Override
    public void end(SimulationEnd end, boolean midStep) {
        try {
            output.end(end, midStep);
        } catch (IOException | RuntimeException e) {
            LOG.info("{}: could not send the end of the simulation: {}", worker.label(),
                    Printable.of(String.valueOf(e.getMessage())));
        }
    }

    @Override
    public boolean begun() {
        return order.begun();
    }

    /** True once the connection has closed (the robot left, was dropped, or the run ended). */
    @Override
    public boolean closed() {
        return closed;
    }

    @Override
    public void drop() {
        worker.drop();
    }

    /** The worker's thread, once the connection has closed: the robot has left, if the loop knew it. */
    void exited(String why) {
        closed = true;
        firstRead.countDown();
        if (index >= 0) {
            robots.loop().post(new LoopEvent.RobotLeaves(this, why));
        }
    }
}

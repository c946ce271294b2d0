package robosim.environment.net;

import robosim.environment.server.Handshake;
import robosim.environment.server.ConnectionClock;
import robosim.protocol.Printable;
import java.io.IOException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.protocol.ObjectConnection;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * One robot's Hardware Simulator over a socket of its own, as the {@link SimulationLoop} sees it (a
 * {@link RobotPeer}) and as its worker thread serves it: the handshake, then its requests, read as the
 * {@link Design} says (each posted to the loop, or left to the {@code SEQUENTIAL} stepper after step 0).
 * The loop's writes go through its {@link RobotOutput} (the loop writes them itself, or a writer thread of
 * its own does). A request for a step this robot was not given, or with a non-finite action, drops this
 * robot alone.
 */
final class RobotConnection implements RobotPeer {
    private static final Logger LOG = LoggerFactory.getLogger(RobotConnection.class);
    /** {@link #readRequest}'s step for the first request, whichever step that is. */
    static final long FIRST = -1;

    private final RobotClientWorker worker;
    private final ClientWorkerCoordinator coordinator;
    private final ObjectConnection connection;
    private final String name;
    private volatile int index = -1;
    /** The last step number the loop has handed this robot (-1 before the first). */
    private volatile long given = -1;
    /** The first step number the loop handed this robot: 0, or a later one for a robot that came back. */
    private volatile long first = -1;
    /** The loop's own writes (the welcome, the first step; every response unless the design has a writer). */
    private volatile LoopWrites loopWrites;
    private volatile RobotOutput output;
    private volatile boolean closed;
    /** SEQUENTIAL: counted down once the worker has read (or failed to read) the step-0 request. */
    private final CountDownLatch firstRead = new CountDownLatch(1);

    RobotConnection(RobotClientWorker worker, ClientWorkerCoordinator coordinator, ObjectConnection connection,
            String name) {
        this.worker = worker;
        this.coordinator = coordinator;
        this.connection = connection;
        this.name = name;
        this.loopWrites = new LoopWrites(connection, worker.clock(), true);
        this.output = loopWrites;
    }

    /** The worker's thread: the handshake of {@code hello}, then every request until the connection ends. */
    void serve(RobotHello hello, Handshake handshake) throws IOException, InterruptedException {
        int wanted = hello.name() == null ? -1 : coordinator.spec().indexOf(hello.name());
        String refusal = handshake.heard("robot");
        if (refusal == null) {
            refusal = coordinator.admission().check(hello, wanted);
        }
        RobotHello typed = refusal == null ? coordinator.admission().typed(hello, wanted) : null;
        if (refusal == null && typed == null) {
            refusal = Admission.RULE_WENT;
        }
        if (refusal == null) {
            CompletableFuture<String> verdict = new CompletableFuture<>();
            coordinator.post(new LoopEvent.RobotJoins(this, typed, wanted, verdict));
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
            coordinator.design().read(this, coordinator);
        } finally {
            output.close();
        }
    }

    /**
     * Reads and checks this robot's request for step k ({@link #FIRST}: the first it was given), on its
     * worker's or the stepper's thread: it must be for that step, a step this robot has been given, with
     * finite numbers.
     */
    StepRequest readRequest(long due) throws IOException {
        StepRequest request = connection.read(StepRequest.class);
        if (given < 0) {
            throw new ProtocolException("sent a request before the simulation started");
        }
        long k = due == FIRST ? first : due;
        if (request.step() != k || k > given) {
            throw new ProtocolException("sent a request for step " + request.step() + " where step "
                    + Math.min(k, given) + " was due");
        }
        if (!Double.isFinite(request.moveMm()) || !Double.isFinite(request.turnDeg())) {
            throw new ProtocolException("asked to move " + request.moveMm() + " mm and turn "
                    + request.turnDeg() + " deg");
        }
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
        output = coordinator.design().output(this, writes, connection, welcome.stepMessages(), name);
    }

    /** Loop thread: sends the first step number. */
    @Override
    public void begin(long firstStep) throws IOException {
        first = firstStep;
        given = firstStep;
        loopWrites.step(firstStep);
    }

    /** Loop thread: this robot's response and then the next step number (unless step messages are off), or the end. */
    @Override
    public void deliver(StepResponse response, long nextStep, SimulationEnd end) throws IOException {
        if (end == null) {
            given = nextStep;
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
        return given >= 0;
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
            coordinator.post(new LoopEvent.RobotLeaves(this, why));
        }
    }
}

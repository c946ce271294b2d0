package robosim.environment.net;

import java.io.IOException;
import java.net.Socket;
import java.util.concurrent.CompletableFuture;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * Serves one robot's Hardware Simulator, the report's thread per client. Its thread,
 * {@code robot-worker[name]}, does the handshake and then reads this robot's requests and hands each
 * to the {@link SimulationLoop} (in {@code THREADS} and {@code TWO_THREADS}); in {@code SEQUENTIAL} it
 * reads only the step-0 request (so a robot leaving before the start is noticed) and the
 * {@link SequentialReader} reads the rest. The loop writes the welcome, the step numbers and the
 * responses itself ({@code THREADS}, {@code SEQUENTIAL}) or queues them to this robot's
 * {@link RobotWriter} ({@code TWO_THREADS}); a request for a step this robot was not given, or with a
 * non-finite action, drops this robot alone.
 */
final class RobotClientWorker extends ClientWorker implements RobotPeer {
    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(RobotClientWorker.class);
    private volatile int index = -1;
    /** The last step number the loop has handed this robot (-1 before the first). */
    private volatile long given = -1;
    /** The first step number the loop handed this robot: 0, or a later one for a robot that came back. */
    private volatile long first = -1;
    /** {@link #readRequest}'s step for the first request, whichever step that is. */
    static final long FIRST = -1;
    private volatile RobotWriter writer;
    private boolean stepMessages = true;
    private String robotName = "";
    /** SEQUENTIAL: counted down once this worker has read (or failed to read) the step-0 request. */
    private final java.util.concurrent.CountDownLatch firstRead = new java.util.concurrent.CountDownLatch(1);

    /** Its robots, when this is a shared connection; else null. */
    private volatile SharedConnection shared;
    private final int serial;

    RobotClientWorker(ClientWorkerCoordinator coordinator, Socket socket, int serial) {
        super(coordinator, socket, "robot-worker[#" + serial + "]");
        this.serial = serial;
    }

    @Override
    protected void serve() throws IOException, InterruptedException {
        java.io.Externalizable first = connection.read(java.io.Externalizable.class);
        if (first instanceof robosim.protocol.SharedHello h) {
            shared = new SharedConnection(this, coordinator, connection);
            rename("robot-worker[shared #" + serial + "]");
            shared.serve(h);
            return;
        }
        if (!(first instanceof RobotHello hello)) {
            throw new ProtocolException("expected a RobotHello or a SharedHello, got a " + first.getClass().getSimpleName());
        }
        int wanted = hello.name() == null ? -1 : coordinator.spec().indexOf(hello.name());
        robotName = String.valueOf(hello.name());
        String refusal = heardHello("robot");
        if (refusal == null) {
            refusal = coordinator.handshakes().check(hello, wanted);
        }
        if (refusal == null) {
            CompletableFuture<String> verdict = new CompletableFuture<>();
            coordinator.post(new LoopEvent.RobotJoins(this, hello, wanted, verdict));
            refusal = awaitVerdict(verdict);
        }
        if (refusal != null) {
            logRefused(refusal);
            send(RobotWelcome.refused(refusal));
            return;
        }
        rename("robot-worker[" + Printable.of(robotName) + "]");
        handshakeDone();
        try {
            coordinator.design().read(this, coordinator);
        } finally {
            RobotWriter w = writer;
            if (w != null) {
                w.stop();
            }
        }
    }

    /** SEQUENTIAL, the stepper: true if this robot has sent something not read yet (a read would not block). */
    boolean hasInput() {
        return connection.hasInput();
    }

    /** SEQUENTIAL, the stepper: waits until this worker is done with the step-0 request. */
    void awaitFirstRead() throws InterruptedException {
        firstRead.await();
    }

    /** SEQUENTIAL, this worker: done with the step-0 request (read or failed); the stepper reads from now on. */
    void firstRead() {
        firstRead.countDown();
    }

    /** True once the connection has closed (the robot left, was dropped, or the run ended). */
    @Override
    public boolean closed() {
        return exitedFlag;
    }

    @Override
    public int index() {
        return index;
    }

    @Override
    public void assign(int i) {
        index = i;
    }

    String robotName() {
        return robotName;
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

    /** Loop thread: sends the welcome; in TWO_THREADS starts the writer thread. */
    @Override
    public void welcome(RobotWelcome welcome) throws IOException {
        stepMessages = welcome.stepMessages();
        clock.writing();
        try {
            connection.write(welcome);
            connection.flush();
        } catch (IOException e) {
            throw cutOffOr(e);
        } finally {
            clock.written();
        }
        writer = coordinator.design().writer(this, connection, stepMessages, robotName);
    }

    /** Loop thread: sends the first step number. */
    @Override
    public void begin(long firstStep) throws IOException {
        first = firstStep;
        given = firstStep;
        clock.writing();
        try {
            connection.writeStep(firstStep);
            connection.flush();
        } catch (IOException e) {
            throw cutOffOr(e);
        } finally {
            clock.written();
        }
    }

    /**
     * Loop thread: this robot's response and then the next step number (unless step messages are
     * off), or the end, in one flush; in TWO_THREADS queued to the writer instead.
     */
    @Override
    public void deliver(StepResponse response, long nextStep, SimulationEnd end) throws IOException {
        if (end == null) {
            given = nextStep;
        }
        RobotWriter w = writer;
        if (w != null) {
            w.send(response, nextStep, end);
            return;
        }
        clock.writing();
        try {
            RobotWriter.writeResponse(connection, stepMessages, response, nextStep, end);
        } catch (IOException e) {
            throw cutOffOr(e);
        } finally {
            clock.written();
        }
    }

    /**
     * Loop thread: ends the simulation for this robot out of turn. {@code midStep}: it has been given
     * a step number and will read an object next; otherwise it is waiting for a step number.
     */
    @Override
    public void end(SimulationEnd end, boolean midStep) {
        try {
            RobotWriter w = writer;
            if (w != null) {
                w.sendEnd(end, midStep);
            } else {
                clock.writing();
                try {
                    RobotWriter.writeEnd(connection, end, midStep);
                } finally {
                    clock.written();
                }
            }
        } catch (IOException | RuntimeException e) {
            LOG.info("{}: could not send the end of the simulation: {}", name(),
                    Printable.of(String.valueOf(e.getMessage())));
        }
    }

    /** True once this robot has been given a step number. */
    @Override
    public boolean begun() {
        return given >= 0;
    }

    private volatile boolean exitedFlag;
    /** The failure of a write: the watch's reason if it cut this robot off, else {@code e} itself. */
    private IOException cutOffOr(IOException e) {
        String why = clock.cutOffReason();
        return why == null ? e : new IOException(why, e);
    }

    @Override
    protected void exited(String why) {
        exitedFlag = true;
        firstRead.countDown();
        SharedConnection s = shared;
        if (s != null) {
            s.exited(why);
        }
        if (index >= 0) {
            coordinator.post(new LoopEvent.RobotLeaves(this, why));
        }
    }
}

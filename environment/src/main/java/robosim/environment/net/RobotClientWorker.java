package robosim.environment.net;

import java.io.IOException;
import java.net.Socket;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.TimeUnit;
import robosim.protocol.Protocol;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * Serves one robot's Hardware Simulator. Its thread does the handshake and then only reads: each
 * request goes to the coordinator, which runs the step on the thread of the last robot to arrive.
 * Every write after the hello (welcome, first step, responses, end) happens under the coordinator's
 * lock, from whichever thread holds it. A request out of turn, for the wrong step or with a
 * non-finite action drops this robot alone. That thread writes every robot's response through {@link #deliver}
 * together with the next step number (or the end), in one flush; so between steps every worker
 * thread stays parked in its socket read instead of waking up to write.
 *
 * <p>In the {@link ClientWorkerCoordinator.Design#TWO_THREADS} design the worker has a second thread,
 * {@code robot-writer[name]}: the step's thread queues the response (and the next step number or the
 * end) and the writer writes it, so responses go out in parallel and out of the lock. Everything
 * after the first step number goes through that queue, in order.
 */
final class RobotClientWorker extends ClientWorker {
    /** What the writer thread sends next: a response with the next step, or the end alone. */
    private record Outgoing(StepResponse response, long nextStep, SimulationEnd end, boolean midStep) {
    }

    private static final Outgoing STOP = new Outgoing(null, 0, null, false);

    private int index = -1;
    private BlockingQueue<Outgoing> outgoing;
    private Thread writer;
    private volatile boolean stepMessages = true;
    private String robotName = "";

    RobotClientWorker(ClientWorkerCoordinator coordinator, Socket socket, int serial) {
        super(coordinator, socket, "robot-worker[#" + serial + "]");
    }

    @Override
    protected void serve() throws IOException, InterruptedException {
        RobotHello hello = connection.read(RobotHello.class);
        int wanted = hello.name() == null ? -1 : coordinator.spec().indexOf(hello.name());
        robotName = String.valueOf(hello.name());
        String refusal = coordinator.register(this, hello, wanted);
        if (refusal != null) {
            coordinator.log().warn("{} refused: {}", name(), refusal);
            connection.write(RobotWelcome.refused(refusal));
            connection.flush();
            return;
        }
        index = wanted;
        rename("robot-worker[" + hello.name() + "]");
        connection.setReadTimeoutMs(0);
        try {
            if (coordinator.sequential()) {
                // this thread reads the first request, so a robot that leaves before the start is noticed;
                // the stepper thread reads the rest, and this thread holds the session open
                StepRequest request = null;
                try {
                    request = readRequest(0);
                    if (!coordinator.isRunning()) {
                        throw new ProtocolException("sent a request before the simulation started");
                    }
                } finally {
                    handOverFirst(request);
                }
                coordinator.awaitEnd();
                return;
            }
            // read at once, also while waiting for the others: a robot that leaves before the start is noticed
            long k = 0;
            while (coordinator.accepts(index)) {
                coordinator.processMessage(index, k, readRequest(k));
                k++;
            }
        } finally {
            stopWriter();
        }
    }

    // SEQUENTIAL: the first request, read by this worker, handed to the stepper
    private final java.util.concurrent.locks.ReentrantLock firstLock = new java.util.concurrent.locks.ReentrantLock();
    private final java.util.concurrent.locks.Condition firstReady = firstLock.newCondition();
    private boolean firstHandedOver;
    private StepRequest first;

    private void handOverFirst(StepRequest request) {
        firstLock.lock();
        try {
            first = request;
            firstHandedOver = true;
            firstReady.signalAll();
        } finally {
            firstLock.unlock();
        }
    }

    /**
     * SEQUENTIAL, on the stepper thread: this robot's request for step 0, once its worker has read it;
     * null if the worker's read failed (the worker then reports the departure).
     */
    StepRequest takeFirst() throws InterruptedException {
        firstLock.lock();
        try {
            while (!firstHandedOver) {
                firstReady.await();
            }
            return first;
        } finally {
            firstLock.unlock();
        }
    }

    /** TWO_THREADS: lets the writer send what it holds (at most a few seconds), then stops it. */
    private void stopWriter() throws InterruptedException {
        Thread w = writer;
        if (w != null) {
            outgoing.offer(STOP);
            w.join(TimeUnit.SECONDS.toMillis(5));
            w.interrupt();
        }
    }

    private void writeLoop() {
        try {
            while (true) {
                Outgoing o = outgoing.take();
                if (o == STOP) {
                    return;
                }
                if (o.response() == null) {
                    writeEnd(o.end(), o.midStep());
                } else {
                    writeResponse(o.response(), o.nextStep(), o.end());
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (IOException | RuntimeException e) {
            // closing the connection makes this robot's reading thread fail; its exit reports the departure,
            // so this thread never runs a step (it may be interrupted by stopWriter)
            coordinator.log().info("{}: could not send its response: {}", name(), e.getMessage());
            drop();
        }
    }

    /** Reads and checks this robot's request for step k (its worker's or the stepper's thread). */
    StepRequest readRequest(long k) throws IOException {
        StepRequest request = connection.read(StepRequest.class);
        if (request.step() != k) {
            throw new ProtocolException("sent a request for step " + request.step() + " where step " + k
                    + " was due");
        }
        if (!Double.isFinite(request.moveMm()) || !Double.isFinite(request.turnDeg())) {
            throw new ProtocolException("asked to move " + request.moveMm() + " mm and turn "
                    + request.turnDeg() + " deg");
        }
        return request;
    }

    /**
     * Sends the welcome; called by the coordinator under its lock when the robot is accepted. In the
     * TWO_THREADS design this starts the writer thread.
     */
    void welcome(RobotWelcome welcome) throws IOException {
        stepMessages = welcome.stepMessages();
        connection.write(welcome);
        connection.flush();
        if (coordinator.settings().design() == ClientWorkerCoordinator.Design.TWO_THREADS) {
            outgoing = new ArrayBlockingQueue<>(4);
            writer = new Thread(this::writeLoop, "robot-writer[" + robotName + "]");
            writer.setDaemon(true);
            writer.start();
        }
    }


    /** Sends the first step number; called by the coordinator under its lock when the run starts. */
    void begin(long firstStep) throws IOException {
        connection.writeStep(firstStep);
        connection.flush();
    }

    /**
     * Writes this robot's response and then the next step number (unless step messages are off), or
     * the end of the simulation; called under the coordinator's lock by the thread that ran the step.
     * In the TWO_THREADS design it is queued for the writer thread instead.
     */
    void deliver(StepResponse response, long nextStep, SimulationEnd end) throws IOException {
        if (outgoing != null) {
            enqueue(new Outgoing(response, nextStep, end, true));
        } else {
            writeResponse(response, nextStep, end);
        }
    }

    private void writeResponse(StepResponse response, long nextStep, SimulationEnd end) throws IOException {
        connection.write(response);
        if (end == null) {
            if (stepMessages) {
                connection.writeStep(nextStep);
            }
        } else {
            if (stepMessages) {
                connection.writeStep(Protocol.END_OF_SIMULATION);
            }
            connection.write(end);
        }
        connection.flush();
    }

    private void enqueue(Outgoing o) throws IOException {
        try {
            // at most one response is ever outstanding (lock-step), plus the end: this never waits long
            if (!outgoing.offer(o, 5, TimeUnit.SECONDS)) {
                throw new IOException("its writer is stuck");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted");
        }
    }

    /**
     * Ends the simulation for this robot out of turn. {@code midStep}: it has been given a step number
     * and will read an object next; otherwise it is waiting for a step number.
     */
    void end(SimulationEnd end, boolean midStep) {
        try {
            if (outgoing != null) {
                enqueue(new Outgoing(null, 0, end, midStep));
            } else {
                writeEnd(end, midStep);
            }
        } catch (IOException | RuntimeException e) {
            coordinator.log().info("{}: could not send the end of the simulation: {}", name(), e.getMessage());
        }
    }

    private void writeEnd(SimulationEnd end, boolean midStep) throws IOException {
        if (!midStep) {
            connection.writeStep(Protocol.END_OF_SIMULATION);
        }
        connection.write(end);
        connection.flush();
    }

    @Override
    protected void exited(String why) {
        if (index >= 0) {
            coordinator.leave(this, index, why);
        }
    }
}

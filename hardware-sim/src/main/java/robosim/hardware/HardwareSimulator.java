package robosim.hardware;

import java.io.EOFException;
import java.io.Externalizable;
import java.io.IOException;
import java.net.Socket;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.api.Message;
import robosim.api.RobotControl;
import robosim.protocol.CommEvent;
import robosim.protocol.ObjectConnection;
import robosim.protocol.Protocol;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationEnd;
import robosim.protocol.StepRequest;
import robosim.protocol.StepResponse;

/**
 * One robot's Hardware Simulator: the handshake with the Environment, then the lock-step exchange on
 * the calling thread (or as {@link Exchange} says) while the control code runs on its own thread
 * ({@code control[name]}). Each
 * step it reads the step number, waits for the control code to block (see {@link ControlLink}),
 * sends this step's piece of the current call with the outgoing messages and a sonar request, and
 * applies the response. The robot state below is touched by one thread at a time, handed over by
 * the link.
 */
public final class HardwareSimulator {
    private static final Logger LOG = LoggerFactory.getLogger(HardwareSimulator.class);

    final String name;
    final RobotType type;
    final ControlLink link = new ControlLink();
    private ObjectConnection connection;
    private RobotWelcome welcome;
    private long steps;
    private String endReason = "";

    // robot state: written by the simulator thread, read by the control thread, handed over by the link
    double xMm;
    double yMm;
    double headingDeg;
    double[] sonarMm;
    String lastContact = "";
    double velocityMmPerS;
    double rotVelocityDegPerS;
    final ArrayDeque<Message> inbox = new ArrayDeque<>();
    /** Newest plug-in sensor readings by name. */
    final java.util.Map<String, double[]> readings = new java.util.HashMap<>();
    final List<CommEvent> outbox = new ArrayList<>();
    private final java.util.Set<String> seenNotices = new java.util.HashSet<>();

    public HardwareSimulator(String name, RobotType type) {
        this.name = name;
        this.type = type;
        this.velocityMmPerS = Math.min(type.defaultVelocityMmPerS(), type.properties().maxSpeedMmPerS());
        this.rotVelocityDegPerS = Math.min(type.defaultRotVelocityDegPerS(), type.properties().maxTurnDegPerS());
        this.sonarMm = new double[type.properties().sonars().size()];
        java.util.Arrays.fill(sonarMm, Double.NaN);
    }

    /**
     * Says hello over a connected socket and reads the answer.
     *
     * @throws ProtocolException naming the Environment's reason if the robot is refused
     */
    public void connect(Socket socket, int resetEvery) throws IOException {
        connection = new ObjectConnection(socket, resetEvery);
        connection.write(new RobotHello(name, type.properties()));
        connection.flush();
        welcome = connection.read(RobotWelcome.class);
        if (!welcome.isAccepted()) {
            connection.close();
            throw new ProtocolException("the Environment refused robot " + name + ": " + welcome.reason());
        }
        xMm = welcome.xMm();
        yMm = welcome.yMm();
        headingDeg = welcome.headingDeg();
    }

    /**
     * How the lock-step exchange is threaded on the robot's side: {@code ONE_THREAD} (the default),
     * the calling thread both sends each request and reads each response; {@code SEND_RECEIVE}, the
     * report's untested two-thread Hardware Simulator: a {@code receiver[name]} thread reads and applies
     * responses while the calling thread sends requests. Many robots in one process can also share one
     * exchange thread ({@link #runShared}).
     */
    public enum Exchange { ONE_THREAD, SEND_RECEIVE }

    /**
     * Runs {@code control} until the Environment ends the simulation; returns its reason. The
     * lock-step exchange runs on the calling thread.
     */
    public String run(RobotControl control) throws IOException, InterruptedException {
        return run(control, Exchange.ONE_THREAD);
    }

    /** Runs {@code control} until the Environment ends the simulation, threaded as {@code exchange}. */
    public String run(RobotControl control, Exchange exchange) throws IOException, InterruptedException {
        try {
            if (!begin(control)) {
                return endReason;
            }
            if (exchange == Exchange.SEND_RECEIVE) {
                return runSendReceive();
            }
            do {
                send();
            } while (receive());
            return endReason;
        } finally {
            finish();
            awaitControlCode(CONTROL_GRACE_MS);
        }
    }

    /** How long control code gets to clean up (finally blocks) once the simulation is over, ms. */
    static final long CONTROL_GRACE_MS = 2000;

    /** Waits up to {@code ms} for the control thread to end after {@link #finish}; true if it did. */
    private boolean awaitControlCode(long ms) throws InterruptedException {
        Thread t = controlThread;
        if (t == null) {
            return true;
        }
        t.join(Math.max(1, ms));
        return !t.isAlive();
    }

    /**
     * Runs many robots' exchanges on the calling thread (each robot's control code still has its own
     * thread): each step it sends every robot's request in the given order, then reads every
     * response in the same order. Returns when every robot's simulation is over.
     *
     * @param sims connected simulators, in world order (the order the Environment writes in)
     */
    public static void runShared(List<HardwareSimulator> sims, List<RobotControl> controls)
            throws IOException, InterruptedException {
        List<HardwareSimulator> running = new ArrayList<>();
        try {
            for (int i = 0; i < sims.size(); i++) {
                HardwareSimulator sim = sims.get(i);
                if (sim.begin(controls.get(i))) {
                    running.add(sim);
                } else {
                    sim.finish();
                }
            }
            while (!running.isEmpty()) {
                sendShared(running);
                for (int i = 0; i < running.size(); i++) {
                    HardwareSimulator sim = running.get(i);
                    if (sim == null) {
                        continue;
                    }
                    boolean more;
                    try {
                        more = sim.receive();
                    } catch (IOException e) {
                        LOG.warn("{}: {}; the other robots of this process go on", sim.name, e.getMessage());
                        sim.endReason = "connection lost: " + e.getMessage();
                        more = false;
                    }
                    if (!more) {
                        sim.finish();
                        running.set(i, null);
                    }
                }
                running.removeIf(java.util.Objects::isNull);
            }
        } finally {
            for (HardwareSimulator sim : sims) {
                sim.finish();
            }
            long deadline = System.nanoTime() + java.util.concurrent.TimeUnit.MILLISECONDS.toNanos(CONTROL_GRACE_MS);
            for (HardwareSimulator sim : sims) {
                sim.awaitControlCode(java.util.concurrent.TimeUnit.NANOSECONDS.toMillis(deadline - System.nanoTime()));
            }
        }
    }

    /** How long the shared exchange waits for one control code before looking whether the step went on. */
    private static final long SHARED_LOOK_NANOS = java.util.concurrent.TimeUnit.MILLISECONDS.toNanos(50);

    /**
     * The shared exchange's send phase: sends each robot's request as soon as its control code has
     * blocked, those that are ready first. A control code that does not yield holds up only its own
     * robot: if, while waiting for it, a response arrives for a robot already sent, the Environment has
     * gone on without it (its step timeout dropped it), and it is finished here too.
     */
    private static void sendShared(List<HardwareSimulator> running) throws InterruptedException {
        List<HardwareSimulator> sent = new ArrayList<>(running.size());
        List<Integer> late = new ArrayList<>();
        for (int i = 0; i < running.size(); i++) {
            HardwareSimulator sim = running.get(i);
            if (sim.link.awaitControlFor(0)) {
                if (sendOrFinish(sim)) {
                    sent.add(sim);
                } else {
                    running.set(i, null);
                }
            } else {
                late.add(i);
            }
        }
        for (int i : late) {
            HardwareSimulator sim = running.get(i);
            while (!sim.link.awaitControlFor(SHARED_LOOK_NANOS)) {
                if (sent.stream().anyMatch(s -> s.connection.hasInput())) {
                    LOG.warn("{}: its control code has not yielded and the Environment went on without it; "
                            + "the other robots of this process go on", sim.name);
                    sim.endReason = "its control code did not yield in time";
                    sim.finish();
                    running.set(i, null);
                    sim = null;
                    break;
                }
            }
            if (sim != null) {
                if (sendOrFinish(sim)) {
                    sent.add(sim);
                } else {
                    running.set(i, null);
                }
            }
        }
    }

    /** Sends one robot's request; on a failed connection finishes that robot alone and returns false. */
    private static boolean sendOrFinish(HardwareSimulator sim) throws InterruptedException {
        try {
            sim.send();
            return true;
        } catch (IOException e) {
            // this robot's connection failed (the Environment dropped it): only it stops
            LOG.warn("{}: {}; the other robots of this process go on", sim.name, e.getMessage());
            sim.endReason = "connection lost: " + e.getMessage();
            sim.finish();
            return false;
        }
    }

    // ---- the exchange, one step at a time -----------------------------------------------------

    private Thread controlThread;
    private long nextStep;
    private Command current;
    private double stepSeconds;
    private boolean sonarWanted;
    private List<String> sensorsWanted = List.of();

    /** Starts the control thread and reads the first step number; false if the simulation ended first. */
    private boolean begin(RobotControl control) throws IOException {
        if (welcome == null) {
            throw new IllegalStateException("connect first");
        }
        SimulatedRobot api = new SimulatedRobot(this, welcome.robotNames(), welcome.timeStepMs(), welcome.sensors());
        controlThread = new Thread(() -> runControl(control, api), "control[" + name + "]");
        controlThread.setDaemon(true);
        controlThread.start();
        stepSeconds = welcome.timeStepMs() / 1000.0;
        sonarWanted = !type.properties().sonars().isEmpty();
        sensorsWanted = welcome.sensors();
        return readStepNumber();
    }

    /** Reads the next step number; false (with the reason kept) at the end of the simulation. */
    private boolean readStepNumber() throws IOException {
        long k;
        try {
            k = connection.readStep();
        } catch (EOFException e) {
            endReason = "the Environment closed the connection";
            return false;
        }
        if (k == Protocol.END_OF_SIMULATION) {
            endReason = connection.read(SimulationEnd.class).reason();
            return false;
        }
        nextStep = k;
        return true;
    }

    /** Waits for the control code to block, then sends this step's request. */
    private void send() throws IOException, InterruptedException {
        Command command = link.awaitControl();
        double move = 0;
        double turn = 0;
        boolean tag = false;
        if (command != null) {
            command.plan(stepSeconds);
            move = command.plannedMoveMm;
            turn = command.plannedTurnDeg;
            tag = command.plannedTag;
        }
        current = command;
        List<CommEvent> messages = outbox.isEmpty() ? List.of() : List.copyOf(outbox);
        outbox.clear();
        connection.write(new StepRequest(nextStep, move, turn, sonarWanted, messages, sensorsWanted, tag));
        connection.flush();
    }

    /**
     * Reads the response to the request just sent, applies it and reads the next step number (or,
     * with step messages off, counts on); false (with the reason kept) at the end of the simulation.
     */
    private boolean receive() throws IOException {
        Externalizable answer;
        try {
            answer = connection.read(Externalizable.class);
        } catch (EOFException e) {
            endReason = "the Environment closed the connection";
            return false;
        }
        if (answer instanceof SimulationEnd end) {
            endReason = end.reason();
            return false;
        }
        if (!(answer instanceof StepResponse r)) {
            throw new ProtocolException("expected a StepResponse, got a " + answer.getClass().getSimpleName());
        }
        boolean arrived = apply(r);
        steps++;
        Command command = current;
        current = null;
        if (command != null && command.apply(r, arrived)) {
            link.complete(command);
        }
        if (welcome.stepMessages()) {
            return readStepNumber();
        }
        nextStep++;
        return true;
    }

    /** SEND_RECEIVE: the calling thread sends, a receiver thread reads; a baton passes between them. */
    private String runSendReceive() throws IOException, InterruptedException {
        Baton sent = new Baton();
        Baton received = new Baton();
        Throwable[] failure = new Throwable[1];
        Thread receiver = new Thread(() -> {
            try {
                while (sent.take()) {
                    received.give(receive());
                }
            } catch (IOException | RuntimeException | InterruptedException e) {
                failure[0] = e;
                received.give(false);
            }
        }, "receiver[" + name + "]");
        receiver.setDaemon(true);
        receiver.start();
        try {
            do {
                send();
                sent.give(true);
            } while (received.take());
        } finally {
            sent.give(false);
            receiver.join(5000);
        }
        if (failure[0] instanceof IOException e) {
            throw e;
        } else if (failure[0] instanceof RuntimeException e) {
            throw e;
        }
        return endReason;
    }

    /** A one-slot hand-over of a boolean between the sending and the receiving thread. */
    private static final class Baton {
        private final java.util.concurrent.locks.ReentrantLock lock = new java.util.concurrent.locks.ReentrantLock();
        private final java.util.concurrent.locks.Condition full = lock.newCondition();
        private boolean has;
        private boolean value;

        void give(boolean v) {
            lock.lock();
            try {
                value = v;
                has = true;
                full.signal();
            } finally {
                lock.unlock();
            }
        }

        boolean take() throws InterruptedException {
            lock.lock();
            try {
                while (!has) {
                    full.await();
                }
                has = false;
                return value;
            } finally {
                lock.unlock();
            }
        }
    }

    /** Stops the control code and closes the connection (idempotent). */
    private void finish() {
        link.shutdown();
        if (controlThread != null) {
            controlThread.interrupt();
        }
        if (connection != null) {
            connection.close();
        }
    }

    private boolean apply(StepResponse r) {
        xMm = r.xMm();
        yMm = r.yMm();
        headingDeg = r.headingDeg();
        if (r.sonarMm().length > 0) {
            sonarMm = r.sonarMm();
        }
        if (r.movedMm() != 0 || r.turnedDeg() != 0 || !r.contact().isEmpty()) {
            lastContact = r.contact();
        }
        for (robosim.protocol.SensorReading reading : r.readings()) {
            readings.put(reading.name(), reading.values());
        }
        for (CommEvent e : r.inbox()) {
            inbox.addLast(new Message(e.from(), e.payload()));
        }
        for (String notice : r.notices()) {
            // the same notice every step (e.g. messages to a robot that has left) is logged once
            if (seenNotices.size() < 1000 && seenNotices.add(notice)) {
                LOG.warn("{}: {} (repeats are logged at debug level)", name, notice);
            } else {
                LOG.debug("{}: {}", name, notice);
            }
        }
        return !r.inbox().isEmpty();
    }

    private void runControl(RobotControl control, SimulatedRobot api) {
        try {
            control.run(api);
            LOG.info("{}: control code returned; the robot stands still", name);
        } catch (InterruptedException e) {
            LOG.debug("{}: control code stopped", name);
        } catch (Exception | Error e) {
            LOG.error("{}: control code failed; the robot stands still", name, e);
        } finally {
            link.controlFinished();
        }
    }

    /** Steps this robot has taken. */
    public long steps() {
        return steps;
    }

    public String name() {
        return name;
    }

    public String endReason() {
        return endReason;
    }
}

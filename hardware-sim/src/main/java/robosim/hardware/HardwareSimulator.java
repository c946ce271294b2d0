package robosim.hardware;

import robosim.devices.RobotType;
import java.io.EOFException;
import java.io.Externalizable;
import java.io.IOException;
import java.net.Socket;
import java.util.List;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.api.RobotControl;
import robosim.protocol.CommEvent;
import robosim.protocol.ObjectConnection;
import robosim.protocol.Protocol;
import robosim.protocol.ProtocolException;
import robosim.protocol.RobotHello;
import robosim.protocol.RobotWelcome;
import robosim.protocol.SimulationKeys;
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

    private final String name;
    /** Its type: given, or (any type) the one its welcome names; then what it knows of itself. */
    private RobotType type;
    private RobotKnowledge state;
    private final ControlLink link = new ControlLink();
    private ObjectConnection connection;
    private RobotWelcome welcome;
    private long steps;
    private String endReason = "";
    private volatile ControlFailure controlFailure;

    /** @param type its type, or null: any type, the one the environment file gives it (a registered type) */
    public HardwareSimulator(String name, RobotType type) {
        this.name = name;
        this.type = type;
        this.state = type == null ? null : new RobotKnowledge(name, type);
    }

    /**
     * Says hello over a connected socket and reads the answer.
     *
     * @throws ProtocolException naming the Environment's reason if the robot is refused
     */
    public void connect(Socket socket, int resetEvery) throws IOException {
        connect(socket, resetEvery, SimulationKeys.fromEnvironment());
    }

    /** As above, proving {@code secret} if the Environment asks for one (null: this process has none). */
    public void connect(Socket socket, int resetEvery, SimulationKeys secret) throws IOException {
        connect(socket, resetEvery, secret, ObjectConnection.DEFAULT_ANSWER_MS);
    }

    /** As above, the Environment's first bytes awaited at most {@code answerWithinMs} (its connect timeout). */
    void connect(Socket socket, int resetEvery, SimulationKeys secret, long answerWithinMs) throws IOException {
        connection = ObjectConnection.client(socket, resetEvery, secret, answerWithinMs);
        connection.write(hello());
        connection.flush();
        Externalizable answer;
        try {
            answer = connection.answerChallenge(secret, "robot");
        } catch (IOException e) {
            connection.close(); // (e.g. asked for a secret this process does not have)
            throw e;
        }
        if (answer instanceof SimulationEnd refusal) { // (a port for another kind of client, or one that speaks TLS)
            connection.close();
            throw new ProtocolException(refusal.reason());
        }
        if (!(answer instanceof RobotWelcome w)) {
            connection.close();
            throw new ProtocolException("expected a RobotWelcome, got a " + answer.getClass().getSimpleName());
        }
        if (!w.isAccepted()) {
            connection.close();
            throw new ProtocolException("the Environment refused robot " + name + ": " + w.reason());
        }
        welcomed(w);
    }

    /**
     * The Environment has welcomed this robot (over its own connection or a shared one): it stands where it says,
     * and a robot of any type is of the type it names, which must be one every process knows by name.
     */
    void welcomed(RobotWelcome w) throws ProtocolException {
        if (type == null) {
            if (robosim.devices.RobotTypes.properties(w.type()) == null) {
                throw new ProtocolException("the Environment gave robot " + name + " the type \""
                        + robosim.protocol.Printable.of(w.type(), 64) + "\", which it cannot take unnamed: give --type");
            }
            type = robosim.devices.RobotTypes.byName(w.type());
            state = new RobotKnowledge(name, type);
        }
        welcome = w;
        state.place(w.xMm(), w.yMm(), w.headingDeg());
    }

    /** The hello this robot says (on a shared connection, one of several). */
    RobotHello hello() {
        return type == null ? RobotHello.anyType(name) : new RobotHello(name, type.properties());
    }

    /**
     * How the lock-step exchange is threaded on the robot's side: {@code ONE_THREAD} (the default),
     * the calling thread both sends each request and reads each response; {@code SEND_RECEIVE}, the
     * report's untested two-thread Hardware Simulator: a {@code receiver[name]} thread reads and applies
     * responses while the calling thread sends requests. Many robots of one process can also share one
     * exchange thread, and one connection ({@link ManyRobots}).
     */
    public enum Exchange {
        ONE_THREAD(OneThreadExchange::run),
        SEND_RECEIVE(SendReceiveExchange::run);

        /** One exchange's way of running, one class each. */
        interface Way {
            void run(HardwareSimulator sim) throws IOException, InterruptedException;
        }

        private final Way way;

        Exchange(Way way) {
            this.way = way;
        }
    }

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
            exchange.way.run(this);
            return endReason;
        } finally {
            finish();
            awaitControlCode(CONTROL_GRACE_MS);
            warnOfParameters(List.of(this));
        }
    }

    /**
     * Warns, once for the robots of a process ({@code sims}), of each parameter their control code asked for that
     * the world does not give them ({@link robosim.protocol.ParameterUse}; a one-JVM run's Environment, which sees
     * every robot, warns of parameters nothing asked for too).
     */
    static void warnOfParameters(List<HardwareSimulator> sims) {
        java.util.Map<String, java.util.Set<String>> asked = new java.util.LinkedHashMap<>();
        java.util.Map<String, java.util.Set<String>> given = new java.util.LinkedHashMap<>();
        for (HardwareSimulator sim : sims) {
            ParameterAsks a = sim.parameterAsks();
            asked.put(sim.name(), a.asked());
            given.put(sim.name(), a.given());
        }
        for (String line : robosim.protocol.ParameterUse.warnings(asked, given, null, java.util.Map.of())) {
            LOG.warn(line);
        }
    }

    /** The parameters its control code asked for so far and those it was given (none before it started). */
    public ParameterAsks parameterAsks() {
        SimulatedRobot a = api;
        return a == null ? ParameterAsks.NONE : a.asks();
    }

    /** How long control code gets to clean up (finally blocks) once the simulation is over, ms. */
    static final long CONTROL_GRACE_MS = 2000;

    /** Waits up to {@code ms} for the control thread to end after {@link #finish}; true if it did. */
    boolean awaitControlCode(long ms) throws InterruptedException {
        Thread t = controlThread;
        if (t == null) {
            return true;
        }
        t.join(Math.max(1, ms));
        return !t.isAlive();
    }

    // ---- the exchange, one step at a time -----------------------------------------------------

    private Thread controlThread;
    /** The robot its control code is given (null before it starts); its parameter asks are read at the end. */
    private volatile SimulatedRobot api;
    private long nextStep;
    private Command current;
    private double stepSeconds;
    private boolean sonarWanted;
    private List<String> sensorsWanted = List.of();

    /** Starts the control thread and reads the first step number; false if the simulation ended first. */
    boolean begin(RobotControl control) throws IOException {
        startControl(control);
        return readStepNumber();
    }

    /** Starts the control code on its own thread (see {@link ControlThreads}). */
    void startControl(RobotControl control) {
        if (welcome == null) {
            throw new IllegalStateException("connect first");
        }
        SimulatedRobot api = new SimulatedRobot(state, link, welcome.robotNames(), welcome.timeStepMs(),
                welcome.sensors(), welcome.actuators(), welcome.seed(), welcome.parameters());
        this.api = api;
        stepSeconds = robosim.devices.Drive.seconds(welcome.timeStepMs());
        sonarWanted = !type.properties().sonars().isEmpty();
        sensorsWanted = welcome.sensors();
        controlThread = ControlThreads.start("control[" + name + "]", () -> runControl(control, api));
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
    void send() throws IOException, InterruptedException {
        connection.write(request(nextStep));
        connection.flush();
    }

    /** Waits for the control code to block, then builds this step's request for step {@code k}. */
    StepRequest request(long k) throws InterruptedException {
        Command command = link.awaitControl();
        double move = 0;
        double turn = 0;
        boolean tag = false;
        StepRequest.Gripper gripper = StepRequest.Gripper.STAY;
        if (command != null) {
            command.plan(stepSeconds);
            move = command.plannedMoveMm;
            turn = command.plannedTurnDeg;
            tag = command.plannedTag;
            gripper = command.plannedGripper;
        }
        current = command;
        List<CommEvent> messages = state.takeOutbox();
        StepRequest q = new StepRequest(k, move, turn, sonarWanted, messages, sensorsWanted, tag, state.takeReports());
        List<robosim.protocol.Actuation> actuations = state.takeActuations();
        return actuations.isEmpty() && gripper == StepRequest.Gripper.STAY ? q : q.with(actuations, gripper);
    }

    /**
     * Reads the response to the request just sent, applies it and reads the next step number (or,
     * with step messages off, counts on); false (with the reason kept) at the end of the simulation.
     */
    boolean receive() throws IOException {
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
        apply(r);
        if (welcome.stepMessages()) {
            return readStepNumber();
        }
        nextStep++;
        return true;
    }

    /** Applies the response to the request last built; the control code's call goes on or returns. */
    void apply(StepResponse r) {
        boolean arrived = state.apply(r);
        steps++;
        Command command = current;
        current = null;
        if (command != null && command.apply(r, arrived)) {
            link.complete(command);
        }
    }

    /** Stops the control code and closes the connection (idempotent). */
    void finish() {
        link.shutdown();
        if (controlThread != null) {
            controlThread.interrupt();
        }
        if (connection != null) {
            connection.close();
        }
    }

    private void runControl(RobotControl control, SimulatedRobot api) {
        try {
            control.run(api);
            LOG.info("{}: control code returned; the robot stands still", name);
        } catch (InterruptedException e) {
            LOG.debug("{}: control code stopped", name);
        } catch (Exception | Error e) {
            if (!(link.over() && interrupted(e))) { // (the end's interrupt, however wrapped, is no failure)
                controlFailure = new ControlFailure(name, steps, e);
            }
            LOG.error("{}: control code failed; the robot stands still", name, e);
        } finally {
            link.controlFinished();
        }
    }

    /** Whether {@code e} is, or was caused by, an interrupt (the end of the simulation, told to a blocked call). */
    private static boolean interrupted(Throwable e) {
        for (Throwable t = e; t != null; t = t.getCause() == t ? null : t.getCause()) {
            if (t instanceof InterruptedException) {
                return true;
            }
        }
        return false;
    }

    ControlLink link() {
        return link;
    }

    /** What its control code threw out of {@code run} (its class and message, one line), or null if it did not. */
    public String controlFailure() {
        ControlFailure f = controlFailure;
        return f == null ? null : f.summary();
    }

    /** What its control code threw out of {@code run}, and when, or null if it did not. */
    public ControlFailure failure() {
        return controlFailure;
    }

    /**
     * The exit code of a robot process (and of {@code headless.sh}, {@code environment.sh --one-jvm}) whose run
     * went on but some robot's control code threw out of {@code run}.
     */
    public static final int EXIT_CONTROL_FAILED = 4;

    /** True if the Environment has sent something this robot has not read yet. */
    boolean hasInput() {
        return connection.hasInput();
    }

    /** Ends this robot's run here, for {@code why} (its exchange failed or its control code did not yield). */
    void endedHere(String why) {
        endReason = why;
        finish();
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

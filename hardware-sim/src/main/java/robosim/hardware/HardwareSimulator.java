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
 * the calling thread while the control code runs on its own thread ({@code control[name]}). Each
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
     * Runs {@code control} until the Environment ends the simulation; returns its reason. The
     * lock-step exchange runs on the calling thread.
     */
    public String run(RobotControl control) throws IOException, InterruptedException {
        if (welcome == null) {
            throw new IllegalStateException("connect first");
        }
        SimulatedRobot api = new SimulatedRobot(this, welcome.robotNames(), welcome.timeStepMs(), welcome.sensors());
        Thread controlThread = new Thread(() -> runControl(control, api), "control[" + name + "]");
        controlThread.setDaemon(true);
        controlThread.start();
        double stepSeconds = welcome.timeStepMs() / 1000.0;
        boolean sonar = !type.properties().sonars().isEmpty();
        List<String> sensors = welcome.sensors();
        try (ObjectConnection c = connection) {
            while (true) {
                long k;
                try {
                    k = c.readStep();
                } catch (EOFException e) {
                    endReason = "the Environment closed the connection";
                    return endReason;
                }
                if (k == Protocol.END_OF_SIMULATION) {
                    endReason = c.read(SimulationEnd.class).reason();
                    return endReason;
                }
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
                List<CommEvent> messages = outbox.isEmpty() ? List.of() : List.copyOf(outbox);
                outbox.clear();
                c.write(new StepRequest(k, move, turn, sonar, messages, sensors, tag));
                c.flush();
                Externalizable answer = c.read(Externalizable.class);
                if (answer instanceof SimulationEnd end) {
                    endReason = end.reason();
                    return endReason;
                }
                if (!(answer instanceof StepResponse r)) {
                    throw new ProtocolException("expected a StepResponse, got a " + answer.getClass().getSimpleName());
                }
                boolean arrived = apply(r);
                steps++;
                if (command != null && command.apply(r, arrived)) {
                    link.complete(command);
                }
            }
        } finally {
            link.shutdown();
            controlThread.interrupt();
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
            LOG.warn("{}: {}", name, notice);
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

package robosim.hardware;

import robosim.devices.RobotType;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import robosim.api.Message;
import robosim.protocol.CommEvent;
import robosim.protocol.SensorReading;
import robosim.protocol.StepResponse;

/**
 * What one robot knows about itself between steps: its pose, its newest sonar and plug-in sensor
 * readings, its last contact, its velocities and wheel speeds, what its gripper holds, the messages it has received
 * and those it is sending, and the actuators it has set since its last request.
 * Written by the exchange thread when a response arrives ({@link #apply}) and read or changed by the
 * control thread while that one holds the {@link ControlLink}: one thread at a time, handed over by
 * the link, which is what makes the plain fields safe.
 */
final class RobotKnowledge {
    private static final Logger LOG = LoggerFactory.getLogger(RobotKnowledge.class);
    /** Distinct notices logged at WARN per robot; repeats and any beyond go to debug. */
    private static final int NOTICES_LOGGED = 1000;

    private final String name;
    private final RobotType type;
    private double xMm;
    private double yMm;
    private double headingDeg;
    private double[] sonarMm;
    private String lastContact = "";
    private double velocityMmPerS;
    private double rotVelocityDegPerS;
    private final ArrayDeque<Message> inbox = new ArrayDeque<>();
    /** Its wheels' speeds, left and right, mm/s. */
    private double[] wheels = {0, 0};
    private String gripped = "";
    /** The actuators set since the last request: the newest values of each, in first-set order. */
    private final java.util.LinkedHashMap<String, double[]> actuations = new java.util.LinkedHashMap<>();
    /** Newest plug-in sensor readings by name. */
    private final Map<String, double[]> readings = new HashMap<>();
    private final List<CommEvent> outbox = new ArrayList<>();
    /** What the control code reported since the last request: the newest value of each name, in first-report order. */
    private final java.util.LinkedHashMap<String, Double> reports = new java.util.LinkedHashMap<>();
    private final Set<String> seenNotices = new HashSet<>();

    RobotKnowledge(String name, RobotType type) {
        this.name = name;
        this.type = type;
        this.velocityMmPerS = Math.min(type.defaultVelocityMmPerS(), type.properties().maxSpeedMmPerS());
        this.rotVelocityDegPerS = Math.min(type.defaultRotVelocityDegPerS(), type.properties().maxTurnDegPerS());
        this.sonarMm = new double[type.properties().sonars().size()];
        Arrays.fill(sonarMm, Double.NaN);
    }

    String name() {
        return name;
    }

    RobotType type() {
        return type;
    }

    /** The start pose from the welcome. */
    void place(double x, double y, double heading) {
        xMm = x;
        yMm = y;
        headingDeg = heading;
    }

    /**
     * Takes in one step's response: pose, sonar, contact, readings, messages; notices are logged (each
     * distinct one once at WARN). True if messages arrived.
     */
    boolean apply(StepResponse r) {
        xMm = r.xMm();
        yMm = r.yMm();
        headingDeg = r.headingDeg();
        if (r.sonarMm().length > 0) {
            sonarMm = r.sonarMm();
        }
        if (r.movedMm() != 0 || r.turnedDeg() != 0 || !r.contact().isEmpty()) {
            lastContact = r.contact();
        }
        gripped = r.gripped();
        for (SensorReading reading : r.readings()) {
            readings.put(reading.name(), reading.values());
        }
        for (CommEvent e : r.inbox()) {
            inbox.addLast(new Message(e.from(), e.payload()));
        }
        for (String notice : r.notices()) {
            // the same notice every step (e.g. messages to a robot that has left) is logged once
            if (seenNotices.size() < NOTICES_LOGGED && seenNotices.add(notice)) {
                LOG.warn("{}: {} (repeats are logged at debug level)", name, notice);
            } else {
                LOG.debug("{}: {}", name, notice);
            }
        }
        return !r.inbox().isEmpty();
    }

    /** The messages to send with this step's request; the outbox is empty afterwards. */
    List<CommEvent> takeOutbox() {
        if (outbox.isEmpty()) {
            return List.of();
        }
        List<CommEvent> out = List.copyOf(outbox);
        outbox.clear();
        return out;
    }

    /** The actuators to set with this step's request; none are kept afterwards. */
    List<robosim.protocol.Actuation> takeActuations() {
        if (actuations.isEmpty()) {
            return List.of();
        }
        List<robosim.protocol.Actuation> out = new ArrayList<>(actuations.size());
        actuations.forEach((device, values) -> out.add(new robosim.protocol.Actuation(device, values)));
        actuations.clear();
        return out;
    }

    /** Keeps {@code values} as the newest setting of actuator {@code device}, sent with the next request. */
    void actuate(String device, double[] values) {
        if (!actuations.containsKey(device) && actuations.size() == robosim.protocol.Actuation.MAX_PER_STEP) {
            throw new IllegalArgumentException("more than " + robosim.protocol.Actuation.MAX_PER_STEP
                    + " actuators set in one step");
        }
        actuations.put(device, values.clone());
    }

    /** Its wheels' speeds, left and right, mm/s (a copy). */
    double[] wheels() {
        return wheels.clone();
    }

    void wheels(double left, double right) {
        wheels = new double[] {left, right};
    }

    /** The object its gripper holds as of the last step, or "". */
    String gripped() {
        return gripped;
    }

    /** The reports to send with this step's request; none are kept afterwards. */
    List<robosim.protocol.Report> takeReports() {
        if (reports.isEmpty()) {
            return List.of();
        }
        List<robosim.protocol.Report> out = new ArrayList<>(reports.size());
        reports.forEach((name, value) -> out.add(new robosim.protocol.Report(name, value)));
        reports.clear();
        return out;
    }

    /** Keeps {@code value} as the newest report of {@code name}; at most {@link robosim.protocol.Report#MAX_PER_STEP} names a step. */
    void report(String name, double value) {
        if (!reports.containsKey(name) && reports.size() == robosim.protocol.Report.MAX_PER_STEP) {
            throw new IllegalArgumentException("more than " + robosim.protocol.Report.MAX_PER_STEP
                    + " report names in one step");
        }
        reports.put(name, value);
    }

    void send(String to, String text) {
        outbox.add(new CommEvent(name, to, text));
    }

    /** The oldest message not yet taken, or null. */
    Message nextMessage() {
        return inbox.pollFirst();
    }

    boolean hasMessage() {
        return !inbox.isEmpty();
    }

    double xMm() {
        return xMm;
    }

    double yMm() {
        return yMm;
    }

    double headingDeg() {
        return headingDeg;
    }

    /** A copy of the newest sonar ranges (NaN before the first). */
    double[] sonarMm() {
        return sonarMm.clone();
    }

    /** The newest values of the plug-in sensor {@code sensor}, or null before its first reading. */
    double[] reading(String sensor) {
        return readings.get(sensor);
    }

    String lastContact() {
        return lastContact;
    }

    double velocityMmPerS() {
        return velocityMmPerS;
    }

    /** Sets the velocity, capped at the type's speed limit. */
    void velocityMmPerS(double mmPerS) {
        velocityMmPerS = Math.min(mmPerS, type.properties().maxSpeedMmPerS());
    }

    double rotVelocityDegPerS() {
        return rotVelocityDegPerS;
    }

    /** Sets the turning velocity, capped at the type's limit. */
    void rotVelocityDegPerS(double degPerS) {
        rotVelocityDegPerS = Math.min(degPerS, type.properties().maxTurnDegPerS());
    }
}

package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.ArrayList;
import java.util.List;

/**
 * Environment -> a viewer that watches one robot ({@link ViewerHello#watch}), right after each
 * {@link PoseUpdate} it gets: that robot's step as the robot itself saw it - the command it sent (move,
 * turn, whether it asked for sonar and a tag), what it touched and tagged, its plug-in sensor readings
 * (laser, heat, bump...), the messages it sent and was delivered, and the notices it got. Its pose and
 * sonar ranges are in the update just before. A live viewer that skipped steps gets the newest view with
 * the messages and notices of every step since the last one it got ({@link #sinceStep}); merged views keep
 * at most {@link #MAX_LOG} of each, the newest, and count the older ones they left out ({@link #leftOut}).
 * A single step's are all carried. Immutable.
 */
public final class RobotView implements java.io.Externalizable {
    /** The most messages sent, delivered and notices a view carries, each. */
    public static final int MAX_LOG = 256;
    static final byte SONAR = 1;
    static final byte TAG = 2;
    private static final byte MORE = 4;

    private long step;
    private long sinceStep;
    private int leftOut;
    private int robot;
    private double moveMm;
    private double turnDeg;
    private byte flags;
    private String contact = "";
    private String tagged = "";
    private List<SensorReading> readings = List.of();
    private List<CommEvent> sent = List.of();
    private List<CommEvent> delivered = List.of();
    private List<String> notices = List.of();
    private List<Report> reports = List.of();

    public RobotView() {
    }

    /** Robot {@code robot} (world order), named {@code name}, in the step released as {@code step}. */
    public static RobotView of(long step, int robot, String name, StepRequest request, StepResponse response) {
        RobotView v = new RobotView();
        v.step = step;
        v.sinceStep = step;
        v.robot = robot;
        if (request != null) {
            v.moveMm = request.moveMm();
            v.turnDeg = request.turnDeg();
            v.flags = (byte) ((request.wantsSonar() ? SONAR : 0) | (request.wantsTag() ? TAG : 0));
            v.sent = fromIs(name, request.messages());
            v.reports = request.reports();
        }
        v.contact = response.contact();
        v.tagged = response.tagged();
        v.readings = response.readings();
        v.delivered = response.inbox();
        v.notices = response.notices();
        return v;
    }

    private static List<CommEvent> fromIs(String name, List<CommEvent> messages) {
        if (messages.isEmpty()) {
            return List.of();
        }
        List<CommEvent> out = new ArrayList<>(messages.size());
        for (CommEvent m : messages) {
            out.add(m.from().equals(name) ? m : new CommEvent(name, m.to(), m.payload()));
        }
        return out;
    }

    /**
     * This view with the messages and notices of {@code earlier} (a view of the same robot, of an earlier
     * step, a viewer has not been sent) before its own, the newest {@link #MAX_LOG} of each kept; this view
     * alone if {@code earlier} is none, another robot's or not earlier (a replay sought back, a new run).
     */
    public RobotView after(RobotView earlier) {
        if (earlier == null || earlier.robot != robot || earlier.step >= sinceStep) {
            return this;
        }
        RobotView v = copy();
        v.sinceStep = earlier.sinceStep;
        int[] cut = new int[1];
        v.sent = joined(earlier.sent, sent, cut);
        v.delivered = joined(earlier.delivered, delivered, cut);
        v.notices = joined(earlier.notices, notices, cut);
        v.leftOut = earlier.leftOut + leftOut + cut[0];
        v.reports = newest(earlier.reports, reports);
        return v;
    }

    private static <T> List<T> joined(List<T> older, List<T> newer, int[] cut) {
        if (older.isEmpty()) {
            return newer;
        }
        List<T> all = new ArrayList<>(older.size() + newer.size());
        all.addAll(older);
        all.addAll(newer);
        int over = all.size() - MAX_LOG;
        if (over > 0) {
            cut[0] += over;
            return List.copyOf(all.subList(over, all.size()));
        }
        return all;
    }

    /** The reports of both, the newer's value where a name is in both; at most {@link #MAX_LOG}, the newest. */
    private static List<Report> newest(List<Report> older, List<Report> newer) {
        if (older.isEmpty()) {
            return newer;
        }
        java.util.LinkedHashMap<String, Report> byName = new java.util.LinkedHashMap<>();
        for (Report r : older) {
            byName.put(r.name(), r);
        }
        for (Report r : newer) {
            byName.remove(r.name());
            byName.put(r.name(), r);
        }
        List<Report> all = new ArrayList<>(byName.values());
        return List.copyOf(all.subList(Math.max(0, all.size() - MAX_LOG), all.size()));
    }

    private RobotView copy() {
        RobotView v = new RobotView();
        v.step = step;
        v.sinceStep = sinceStep;
        v.leftOut = leftOut;
        v.robot = robot;
        v.moveMm = moveMm;
        v.turnDeg = turnDeg;
        v.flags = flags;
        v.contact = contact;
        v.tagged = tagged;
        v.readings = readings;
        v.sent = sent;
        v.delivered = delivered;
        v.notices = notices;
        v.reports = reports;
        return v;
    }

    /** The step this is. */
    public long step() {
        return step;
    }

    /** The first step whose messages and notices this view carries (= {@link #step} unless merged). */
    public long sinceStep() {
        return sinceStep;
    }

    /** Messages and notices since {@link #sinceStep} beyond {@link #MAX_LOG} of a kind, not carried. */
    public int leftOut() {
        return leftOut;
    }

    /** The robot, in world (snapshot) order. */
    public int robot() {
        return robot;
    }

    /** ACTION: the move it asked for, mm (signed). */
    public double moveMm() {
        return moveMm;
    }

    /** ACTION: the turn it asked for, degrees (counter-clockwise). */
    public double turnDeg() {
        return turnDeg;
    }

    public boolean askedSonar() {
        return (flags & SONAR) != 0;
    }

    public boolean askedTag() {
        return (flags & TAG) != 0;
    }

    /** What it touched this step ("" for nothing). */
    public String contact() {
        return contact;
    }

    /** What its tag hit this step ("" for nothing). */
    public String tagged() {
        return tagged;
    }

    public List<SensorReading> readings() {
        return readings;
    }

    /** Its outbox: messages it sent (from = its name). */
    public List<CommEvent> sent() {
        return sent;
    }

    /** Its inbox: messages delivered to it. */
    public List<CommEvent> delivered() {
        return delivered;
    }

    public List<String> notices() {
        return notices;
    }

    /**
     * The values its control code reported in this step ({@code Robot.report}), the newest of each name (a
     * merged view: since {@link #sinceStep}).
     */
    public List<Report> reports() {
        return reports;
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeLong(step);
        out.writeLong(sinceStep);
        out.writeInt(leftOut);
        writeBody(out);
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        step = in.readLong();
        sinceStep = in.readLong();
        if (sinceStep < 0 || sinceStep > step) {
            throw new ProtocolException("a robot view of step " + step + " since step " + sinceStep);
        }
        leftOut = Math.max(0, in.readInt());
        readBody(in, step);
    }

    /** The robot's part (also a recording's, per robot and step): robot, command, and what it got. */
    void writeBody(ObjectOutput out) throws IOException {
        write(out, robot, moveMm, turnDeg, flags, contact, tagged, readings, sent, null, delivered, notices, reports);
    }

    /**
     * Writes what {@code of(step, robot, name, request, response).writeBody(out)} writes, allocating nothing
     * (the recorder, for every robot of every step).
     */
    static void writeBody(ObjectOutput out, int robot, String name, StepRequest request, StepResponse response,
            boolean readings) throws IOException {
        write(out, robot, request == null ? 0 : request.moveMm(), request == null ? 0 : request.turnDeg(),
                request == null ? 0 : (byte) ((request.wantsSonar() ? SONAR : 0) | (request.wantsTag() ? TAG : 0)),
                response.contact(), response.tagged(), readings ? response.readings() : List.of(),
                request == null ? List.of() : request.messages(), name, response.inbox(), response.notices(),
                request == null ? List.of() : request.reports());
    }

    /** The body; {@code sender}: the name every sent message is from (null: each one's own {@code from}). */
    private static void write(ObjectOutput out, int robot, double moveMm, double turnDeg, byte flags, String contact,
            String tagged, List<SensorReading> readings, List<CommEvent> sent, String sender, List<CommEvent> delivered,
            List<String> notices, List<Report> reports) throws IOException {
        boolean more = !contact.isEmpty() || !tagged.isEmpty() || !readings.isEmpty() || !sent.isEmpty()
                || !delivered.isEmpty() || !notices.isEmpty() || !reports.isEmpty();
        out.writeInt(robot);
        out.writeDouble(moveMm);
        out.writeDouble(turnDeg);
        out.writeByte(flags | (more ? MORE : 0));
        if (more) {
            out.writeUTF(contact);
            out.writeUTF(tagged);
            Wire.writeReadings(out, readings);
            out.writeInt(sent.size());
            for (CommEvent m : sent) {
                out.writeUTF(sender == null ? m.from() : sender);
                out.writeUTF(m.to());
                out.writeUTF(m.payload());
            }
            Wire.writeEvents(out, delivered);
            Wire.writeStrings(out, notices);
            Report.write(out, reports);
        }
    }

    /** Reads a body as {@link #writeBody} wrote it, for the step released as {@code stepNumber}. */
    void readBody(ObjectInput in, long stepNumber) throws IOException {
        readBody(in, stepNumber, true);
    }

    /** As {@link #readBody(ObjectInput, long)}; without {@code reports} for a recording made before views had them. */
    private void readBody(ObjectInput in, long stepNumber, boolean withReports) throws IOException {
        step = stepNumber;
        robot = Limits.checkCount("robot index", in.readInt(), Limits.MAX_ROBOTS - 1);
        moveMm = in.readDouble();
        turnDeg = in.readDouble();
        int f = in.readByte();
        flags = (byte) (f & (SONAR | TAG));
        if ((f & MORE) != 0) {
            contact = in.readUTF();
            tagged = in.readUTF();
            readings = List.copyOf(Wire.readReadings(in));
            sent = List.copyOf(Wire.readEvents(in, "sent message count"));
            delivered = List.copyOf(Wire.readEvents(in, "delivered message count"));
            notices = Wire.readStrings(in, "notice count", Limits.MAX_MESSAGES_PER_STEP);
            reports = withReports ? Report.read(in, MAX_LOG) : List.of();
        }
    }

    /** A view read from a recording: the step it was recorded in, nothing merged; {@code withReports}: version 4 on. */
    static RobotView readRecorded(ObjectInput in, long stepNumber, boolean withReports) throws IOException {
        RobotView v = new RobotView();
        v.readBody(in, stepNumber, withReports);
        v.sinceStep = stepNumber;
        return v;
    }
}

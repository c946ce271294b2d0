package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.List;

/**
 * Robot -> Environment, once per step, after the step number: this step's ACTION (turn, then move
 * along the new heading), whether SENSOR sonar ranges are wanted, and the COMMEVENT messages to
 * route. {@code moveMm} is signed (negative drives backwards); {@code turnDeg} is counter-clockwise.
 * {@code sensors} names the plug-in sensors (laser, heat, bump, ...) to read at the end of the step.
 * {@code tag} (ACTION) tags the nearest robot or taggable object in front, after the move.
 * {@code reports}: the values the control code reported since the last request ({@link Report}), the newest
 * of each name. {@code actuations}: the actuators set since the last request ({@link Actuation}; LEDs,
 * range-and-bearing). {@code gripper}: take what is in reach of the gripper after the move, or let go of what it
 * holds ({@link Gripper}).
 */
public final class StepRequest implements java.io.Externalizable {
    /** What a robot's gripper does this step. */
    public enum Gripper {
        /** Nothing: it holds what it held. */
        STAY,
        /** Take the object in reach after the step's move, if any. */
        GRIP,
        /** Let go of what it holds. */
        RELEASE
    }

    private long step;
    private double moveMm;
    private double turnDeg;
    private boolean sonar;
    private List<CommEvent> messages = List.of();
    private List<String> sensors = List.of();
    private boolean tag;
    private List<Report> reports = List.of();
    private List<Actuation> actuations = List.of();
    private Gripper gripper = Gripper.STAY;

    public StepRequest() {
    }

    public StepRequest(long step, double moveMm, double turnDeg, boolean sonar, List<CommEvent> messages) {
        this(step, moveMm, turnDeg, sonar, messages, List.of());
    }

    public StepRequest(long step, double moveMm, double turnDeg, boolean sonar, List<CommEvent> messages,
            List<String> sensors) {
        this(step, moveMm, turnDeg, sonar, messages, sensors, false);
    }

    public StepRequest(long step, double moveMm, double turnDeg, boolean sonar, List<CommEvent> messages,
            List<String> sensors, boolean tag) {
        this(step, moveMm, turnDeg, sonar, messages, sensors, tag, List.of());
    }

    public StepRequest(long step, double moveMm, double turnDeg, boolean sonar, List<CommEvent> messages,
            List<String> sensors, boolean tag, List<Report> reports) {
        if (reports.size() > Report.MAX_PER_STEP) {
            throw new IllegalArgumentException(reports.size() + " reports in one step, at most " + Report.MAX_PER_STEP);
        }
        this.reports = List.copyOf(reports);
        this.tag = tag;
        this.step = step;
        this.moveMm = moveMm;
        this.turnDeg = turnDeg;
        this.sonar = sonar;
        this.messages = List.copyOf(messages);
        this.sensors = List.copyOf(sensors);
    }

    /** This request with {@code devices} set and the gripper doing {@code grip} (the rest as it is). */
    public StepRequest with(List<Actuation> devices, Gripper grip) {
        if (devices.size() > Actuation.MAX_PER_STEP) {
            throw new IllegalArgumentException(devices.size() + " actuations in one step, at most "
                    + Actuation.MAX_PER_STEP);
        }
        StepRequest r = new StepRequest(step, moveMm, turnDeg, sonar, messages, sensors, tag, reports);
        r.actuations = List.copyOf(devices);
        r.gripper = java.util.Objects.requireNonNull(grip);
        return r;
    }

    /** The actuators set since the last request, in the order set. */
    public List<Actuation> actuations() {
        return actuations;
    }

    public Gripper gripper() {
        return gripper;
    }

    /** ACTION tag: tag what is nearest in front after this step's move. */
    public boolean wantsTag() {
        return tag;
    }

    /** Plug-in sensors to read at the end of this step, by name. */
    public List<String> sensors() {
        return sensors;
    }

    /** The values reported since the last request, the newest of each name. */
    public List<Report> reports() {
        return reports;
    }

    public long step() {
        return step;
    }

    public double moveMm() {
        return moveMm;
    }

    public double turnDeg() {
        return turnDeg;
    }

    public boolean wantsSonar() {
        return sonar;
    }

    public List<CommEvent> messages() {
        return messages;
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeLong(step);
        out.writeDouble(moveMm);
        out.writeDouble(turnDeg);
        out.writeBoolean(sonar);
        Wire.writeEvents(out, messages);
        Wire.writeStrings(out, sensors);
        out.writeBoolean(tag);
        Report.write(out, reports);
        Actuation.write(out, actuations);
        out.writeByte(gripper.ordinal());
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        step = in.readLong();
        moveMm = in.readDouble();
        turnDeg = in.readDouble();
        sonar = in.readBoolean();
        messages = Wire.readEvents(in, "outgoing message count");
        sensors = Wire.readStrings(in, "sensor count", Limits.MAX_SENSORS);
        tag = in.readBoolean();
        reports = Report.read(in, Report.MAX_PER_STEP);
        actuations = Actuation.read(in);
        int g = in.readUnsignedByte();
        if (g >= Gripper.values().length) {
            throw new ProtocolException("a gripper doing " + g + ", not one of " + java.util.Arrays.toString(
                    Gripper.values()));
        }
        gripper = Gripper.values()[g];
    }
}

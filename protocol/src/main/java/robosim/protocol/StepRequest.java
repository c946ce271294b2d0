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
 * of each name.
 */
public final class StepRequest implements java.io.Externalizable {
    private long step;
    private double moveMm;
    private double turnDeg;
    private boolean sonar;
    private List<CommEvent> messages = List.of();
    private List<String> sensors = List.of();
    private boolean tag;
    private List<Report> reports = List.of();

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
    }
}

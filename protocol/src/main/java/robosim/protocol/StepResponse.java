package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.List;

/**
 * Environment -> robot, once per step: how far the robot actually moved (mm) and turned (deg),
 * what it touched ("" for nothing), its pose at the end of the step, the sonar ranges (mm, in the
 * order of its sonar layout; empty when not asked for), the messages delivered to it (in send
 * order), notices about its own requests (for example a message to an unknown robot) and the
 * readings of the plug-in sensors it asked for, in the order it asked.
 */
public final class StepResponse implements java.io.Externalizable {
    private static final double[] NO_RANGES = new double[0];

    private long step;
    private double movedMm;
    private double turnedDeg;
    private String contact = "";
    private double xMm;
    private double yMm;
    private double headingDeg;
    private double[] sonarMm = NO_RANGES;
    private List<CommEvent> inbox = List.of();
    private List<String> notices = List.of();
    private List<SensorReading> readings = List.of();
    private String tagged = "";
    /** The object its gripper holds after the step, "" for none. */
    private String gripped = "";

    public StepResponse() {
    }

    /** The arrays and lists are taken as they are: the caller must not change them afterwards. */
    public StepResponse(long step, double movedMm, double turnedDeg, String contact, double xMm, double yMm,
            double headingDeg, double[] sonarMm, List<CommEvent> inbox, List<String> notices) {
        this(step, movedMm, turnedDeg, contact, xMm, yMm, headingDeg, sonarMm, inbox, notices, List.of());
    }

    /** The arrays and lists are taken as they are: the caller must not change them afterwards. */
    public StepResponse(long step, double movedMm, double turnedDeg, String contact, double xMm, double yMm,
            double headingDeg, double[] sonarMm, List<CommEvent> inbox, List<String> notices,
            List<SensorReading> readings) {
        this(step, movedMm, turnedDeg, contact, xMm, yMm, headingDeg, sonarMm, inbox, notices, readings, "");
    }

    /** As above, with what a tag this step hit ("" for nothing or no tag). */
    public StepResponse(long step, double movedMm, double turnedDeg, String contact, double xMm, double yMm,
            double headingDeg, double[] sonarMm, List<CommEvent> inbox, List<String> notices,
            List<SensorReading> readings, String tagged) {
        this.tagged = tagged;
        this.readings = readings;
        this.step = step;
        this.movedMm = movedMm;
        this.turnedDeg = turnedDeg;
        this.contact = contact;
        this.xMm = xMm;
        this.yMm = yMm;
        this.headingDeg = headingDeg;
        this.sonarMm = sonarMm;
        this.inbox = inbox;
        this.notices = notices;
    }

    public long step() {
        return step;
    }

    public double movedMm() {
        return movedMm;
    }

    public double turnedDeg() {
        return turnedDeg;
    }

    public String contact() {
        return contact;
    }

    public double xMm() {
        return xMm;
    }

    public double yMm() {
        return yMm;
    }

    public double headingDeg() {
        return headingDeg;
    }

    public double[] sonarMm() {
        return sonarMm;
    }

    public List<CommEvent> inbox() {
        return inbox;
    }

    public List<String> notices() {
        return notices;
    }

    /** The object the robot's gripper holds after the step, "" for none. */
    public String gripped() {
        return gripped;
    }

    /** This response with its gripper holding {@code object} ("" for none). */
    public StepResponse withGripped(String object) {
        StepResponse r = new StepResponse(step, movedMm, turnedDeg, contact, xMm, yMm, headingDeg, sonarMm, inbox,
                notices, readings, tagged);
        r.gripped = object;
        return r;
    }

    /** The name of what this step's tag hit, or "" when nothing was tagged. */
    public String tagged() {
        return tagged;
    }

    /** Readings of the plug-in sensors asked for, in the order asked. */
    public List<SensorReading> readings() {
        return readings;
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        out.writeLong(step);
        out.writeDouble(movedMm);
        out.writeDouble(turnedDeg);
        out.writeUTF(contact);
        out.writeDouble(xMm);
        out.writeDouble(yMm);
        out.writeDouble(headingDeg);
        out.writeInt(sonarMm.length);
        Wire.writeDoubles(out, sonarMm, sonarMm.length);
        Wire.writeEvents(out, inbox);
        Wire.writeStrings(out, notices);
        Wire.writeReadings(out, readings);
        out.writeUTF(tagged);
        out.writeUTF(gripped);
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        step = in.readLong();
        movedMm = in.readDouble();
        turnedDeg = in.readDouble();
        contact = in.readUTF();
        xMm = in.readDouble();
        yMm = in.readDouble();
        headingDeg = in.readDouble();
        sonarMm = Wire.readDoubles(in, Limits.checkCount("sonar range count", in.readInt(), Limits.MAX_SONARS));
        inbox = Wire.readEvents(in, "inbox message count");
        notices = Wire.readStrings(in, "notice count", Limits.MAX_MESSAGES_PER_STEP);
        readings = Wire.readReadings(in);
        tagged = in.readUTF();
        gripped = in.readUTF();
    }
}

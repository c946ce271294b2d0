package robosim.protocol;

import java.io.IOException;
import java.io.ObjectInput;
import java.io.ObjectOutput;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Environment -> robot, once, in answer to {@link RobotHello}: either a refusal with a reason
 * (the connection is then closed), or the time step (ms), the robot's start pose (world mm, degrees
 * counter-clockwise from +x), the names of every robot in the world, in world order, and the names
 * of this robot's sensors (its type's and the environment file's), which it may ask for each step; and
 * whether the Environment sends the next step number after each response ({@link #stepMessages()},
 * the default) or only the first one (the report's untested idea: the robot counts the steps itself,
 * and the end of the simulation arrives as a {@link SimulationEnd} where a response would be); and the run's
 * seed and this robot's parameters from the environment file ({@link #seed()}, {@link #parameters()}); and the names
 * of its actuators ({@link #actuators()}).
 */
public final class RobotWelcome implements java.io.Externalizable {
    private boolean accepted;
    private String reason = "";
    private long timeStepMs;
    private double xMm;
    private double yMm;
    private double headingDeg;
    private List<String> robotNames = List.of();
    private List<String> sensors = List.of();
    private boolean stepMessages = true;
    private long seed;
    private Map<String, String> parameters = Map.of();
    private String type = "";
    private List<String> actuators = List.of();

    public RobotWelcome() {
    }

    public static RobotWelcome refused(String reason) {
        RobotWelcome w = new RobotWelcome();
        w.reason = reason;
        return w;
    }

    public static RobotWelcome accepted(long timeStepMs, double xMm, double yMm, double headingDeg,
            List<String> robotNames) {
        return accepted(timeStepMs, xMm, yMm, headingDeg, robotNames, List.of());
    }

    public static RobotWelcome accepted(long timeStepMs, double xMm, double yMm, double headingDeg,
            List<String> robotNames, List<String> sensors) {
        RobotWelcome w = new RobotWelcome();
        w.accepted = true;
        w.timeStepMs = timeStepMs;
        w.xMm = xMm;
        w.yMm = yMm;
        w.headingDeg = headingDeg;
        w.robotNames = List.copyOf(robotNames);
        w.sensors = List.copyOf(sensors);
        return w;
    }

    /** This welcome with step numbers after every response ({@code true}) or only before the first step. */
    public RobotWelcome withStepMessages(boolean on) {
        stepMessages = on;
        return this;
    }

    /**
     * This welcome with the run's seed (the world's, for the control code's random numbers) and this robot's
     * parameters (name to value, at most {@link Limits#MAX_PARAMETERS}).
     */
    public RobotWelcome withRun(long seed, Map<String, String> parameters) {
        if (parameters.size() > Limits.MAX_PARAMETERS) {
            throw new IllegalArgumentException(parameters.size() + " parameters, at most " + Limits.MAX_PARAMETERS);
        }
        this.seed = seed;
        this.parameters = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(parameters));
        return this;
    }

    /** This welcome naming the robot's type as the environment file gives it (a robot that said any type takes it). */
    public RobotWelcome withType(String robotType) {
        this.type = robotType;
        return this;
    }

    /** This welcome naming the robot's actuators (its LEDs, range-and-bearing), which it may set each step. */
    public RobotWelcome withActuators(List<String> names) {
        this.actuators = List.copyOf(names);
        return this;
    }

    /** This robot's actuators, by name. */
    public List<String> actuators() {
        return actuators;
    }

    /** The robot's type in the environment file ("" in a refusal). */
    public String type() {
        return type;
    }

    /** The world's seed. */
    public long seed() {
        return seed;
    }

    /** This robot's parameters: the world's {@code <param>}s with its own over them. */
    public Map<String, String> parameters() {
        return parameters;
    }

    /** True: a step number follows every response; false: only step 0 is sent, the robot counts on. */
    public boolean stepMessages() {
        return stepMessages;
    }

    public boolean isAccepted() {
        return accepted;
    }

    public String reason() {
        return reason;
    }

    public long timeStepMs() {
        return timeStepMs;
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

    public List<String> robotNames() {
        return robotNames;
    }

    /** This robot's plug-in sensors, by the names the environment file gives them. */
    public List<String> sensors() {
        return sensors;
    }

    @Override
    public void writeExternal(ObjectOutput out) throws IOException {
        write(out, true);
    }

    @Override
    public void readExternal(ObjectInput in) throws IOException {
        read(in, null);
    }

    /** Writes this welcome; without its robot names when {@code withNames} is false (a frame's later welcomes). */
    void write(ObjectOutput out, boolean withNames) throws IOException {
        out.writeBoolean(accepted);
        out.writeUTF(reason);
        out.writeLong(timeStepMs);
        out.writeDouble(xMm);
        out.writeDouble(yMm);
        out.writeDouble(headingDeg);
        if (withNames) {
            Wire.writeStrings(out, robotNames);
        }
        Wire.writeStrings(out, sensors);
        out.writeBoolean(stepMessages);
        out.writeLong(seed);
        out.writeInt(parameters.size());
        for (Map.Entry<String, String> p : parameters.entrySet()) {
            out.writeUTF(p.getKey());
            out.writeUTF(p.getValue());
        }
        out.writeUTF(type);
        Wire.writeStrings(out, actuators);
    }

    /** Reads a welcome; {@code names}: the robot names it was written without, or null when they are on the wire. */
    void read(ObjectInput in, List<String> names) throws IOException {
        accepted = in.readBoolean();
        reason = in.readUTF();
        timeStepMs = in.readLong();
        xMm = in.readDouble();
        yMm = in.readDouble();
        headingDeg = in.readDouble();
        robotNames = names != null ? names : Wire.readStrings(in, "robot name count", Limits.MAX_ROBOTS);
        sensors = Wire.readStrings(in, "sensor count", Limits.MAX_SENSORS);
        stepMessages = in.readBoolean();
        seed = in.readLong();
        int n = Limits.checkCount("parameter count", in.readInt(), Limits.MAX_PARAMETERS);
        Map<String, String> read = new LinkedHashMap<>();
        for (int i = 0; i < n; i++) {
            String name = in.readUTF();
            String value = in.readUTF();
            if (name.isEmpty() || name.length() > Limits.MAX_PARAMETER_NAME_CHARS
                    || Limits.utfLength(value) > Limits.MAX_PARAMETER_BYTES || read.put(name, value) != null) {
                throw new ProtocolException("parameter '" + Printable.of(name, Limits.MAX_PARAMETER_NAME_CHARS)
                        + "': a name of 1 to " + Limits.MAX_PARAMETER_NAME_CHARS + " characters, given once, a value of at "
                        + "most " + Limits.MAX_PARAMETER_BYTES + " bytes");
            }
        }
        parameters = java.util.Collections.unmodifiableMap(read);
        type = in.readUTF();
        actuators = Wire.readStrings(in, "actuator count", Limits.MAX_SENSORS);
    }
}

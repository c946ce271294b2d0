package robosim.hardware;

import java.util.List;
import java.util.Map;
import java.util.Set;
import robosim.api.Message;
import robosim.api.Robot;
import robosim.devices.Actuators;
import robosim.devices.Attribute;
import robosim.devices.DeviceSpec;
import robosim.devices.RobotActuator;
import robosim.protocol.CommEvent;
import robosim.protocol.Limits;
import robosim.protocol.Report;
import robosim.protocol.SonarSpec;
import robosim.protocol.StepRequest;

/** The {@link Robot} the control code gets: blocking calls become {@link Command}s on the link. */
final class SimulatedRobot implements Robot {
    private final RobotKnowledge state;
    private final ControlLink link;
    private final List<String> robotNames;
    private final long stepMs;
    private final double[] sonarAngles;

    private final List<String> sensorNames;
    private final List<String> actuatorNames;
    /** Its actuators as its type declares them, for checking values at once; by name (a type's of one's own: none). */
    private final Map<String, RobotActuator> actuators = new java.util.LinkedHashMap<>();
    /** Its LEDs' colours as the control code last set them. */
    private final double[] leds;
    private final long seed;
    private final Map<String, String> parameters;
    /** The names its control code asked for ({@link #parameter}), for the warnings at the end ({@code ParameterUse}). */
    private final Set<String> asked = java.util.concurrent.ConcurrentHashMap.newKeySet();
    /** The most names not given that are kept as asked. */
    static final int MAX_ASKED = 256;

    /**
     * The robot {@code state} is of, its calls going through {@code link}; {@code worldSeed} and {@code parameters}
     * from its welcome.
     */
    SimulatedRobot(RobotKnowledge state, ControlLink link, List<String> robotNames, long stepMs, List<String> sensorNames,
            List<String> actuatorNames, long worldSeed, Map<String, String> parameters) {
        this.state = state;
        this.seed = seed(worldSeed, state.name());
        this.parameters = Map.copyOf(parameters);
        this.link = link;
        this.sensorNames = List.copyOf(sensorNames);
        this.actuatorNames = List.copyOf(actuatorNames);
        for (DeviceSpec d : state.type().devices()) {
            if (d.actuator() && actuatorNames.contains(d.name())) {
                actuators.put(d.name(), Actuators.create(d.kind(), d.attributes(), state.type().properties()));
            }
        }
        RobotActuator l = actuators.get("leds");
        this.leds = new double[l == null ? 0 : l.values().count()];
        this.robotNames = List.copyOf(robotNames);
        this.stepMs = stepMs;
        List<SonarSpec> sonars = state.type().properties().sonars();
        this.sonarAngles = new double[sonars.size()];
        for (int i = 0; i < sonarAngles.length; i++) {
            sonarAngles[i] = sonars.get(i).angleDeg();
        }
    }

    @Override
    public String name() {
        return state.name();
    }

    @Override
    public long stepMs() {
        return stepMs;
    }

    @Override
    public List<String> robotNames() {
        return robotNames;
    }

    @Override
    public double move(double mm) throws InterruptedException {
        checkFinite("move distance", mm);
        if (mm == 0) {
            return 0;
        }
        Command c = Command.move(mm, state.velocityMmPerS());
        link.execute(c);
        return c.result;
    }

    @Override
    public double turn(double deg) throws InterruptedException {
        checkFinite("turn angle", deg);
        if (deg == 0) {
            return 0;
        }
        Command c = Command.turn(deg, state.rotVelocityDegPerS());
        link.execute(c);
        return c.result;
    }

    private static void checkFinite(String what, double v) {
        if (!Double.isFinite(v)) {
            throw new IllegalArgumentException(what + " must be a finite number, got " + v);
        }
    }

    @Override
    public void setVelocity(double mmPerS) {
        if (!(mmPerS > 0)) {
            throw new IllegalArgumentException("velocity must be > 0 mm/s, got " + mmPerS);
        }
        state.velocityMmPerS(mmPerS);
    }

    @Override
    public double velocity() {
        return state.velocityMmPerS();
    }

    @Override
    public void setRotVelocity(double degPerS) {
        if (!(degPerS > 0)) {
            throw new IllegalArgumentException("rotational velocity must be > 0 deg/s, got " + degPerS);
        }
        state.rotVelocityDegPerS(degPerS);
    }

    @Override
    public double rotVelocity() {
        return state.rotVelocityDegPerS();
    }

    @Override
    public String tag() throws InterruptedException {
        Command c = Command.tag();
        link.execute(c);
        return c.text;
    }

    @Override
    public void sleep(long ms) throws InterruptedException {
        link.execute(Command.idle(stepsFor(ms), false, state.wheels(), state.type().body().wheelBaseMm()));
    }

    @Override
    public void setWheelSpeeds(double leftMmPerS, double rightMmPerS) {
        double top = state.type().properties().maxSpeedMmPerS();
        for (double v : new double[] {leftMmPerS, rightMmPerS}) {
            if (!(Math.abs(v) <= top)) {
                throw new IllegalArgumentException("a wheel speed must be a number from -" + Attribute.plain(top)
                        + " to " + Attribute.plain(top) + " mm/s (" + state.name() + "'s top speed), got " + v);
            }
        }
        double turn = Math.toDegrees(Math.abs(rightMmPerS - leftMmPerS) / state.type().body().wheelBaseMm());
        double most = state.type().properties().maxTurnDegPerS();
        if (turn > most * (1 + 1e-9)) {
            throw new IllegalArgumentException("wheels at " + Attribute.plain(leftMmPerS) + " and "
                    + Attribute.plain(rightMmPerS) + " mm/s turn at " + Attribute.plain(Math.round(turn * 10) / 10.0)
                    + " deg/s, beyond " + state.name() + "'s " + Attribute.plain(most) + " deg/s");
        }
        state.wheels(leftMmPerS, rightMmPerS);
    }

    @Override
    public List<String> actuatorNames() {
        return actuatorNames;
    }

    @Override
    public void actuate(String name, double... values) {
        if (!actuatorNames.contains(name)) {
            throw new IllegalArgumentException("no actuator named " + name + " on " + state.name() + " (it has "
                    + actuatorNames + ")");
        }
        RobotActuator a = actuators.get(name);
        if (a != null) {
            a.set(values); // (its values checked: a bad one refused here, at once)
        }
        if (name.equals("leds") && values.length == leds.length) {
            System.arraycopy(values, 0, leds, 0, leds.length);
        }
        state.actuate(name, values);
    }

    @Override
    public int ledCount() {
        return leds.length;
    }

    @Override
    public void setLed(int index, int rgb) {
        if (index < 0 || index >= leds.length) {
            throw new IllegalArgumentException(state.name() + " has LEDs 0 to " + (leds.length - 1) + ", not " + index);
        }
        double[] now = leds.clone();
        now[index] = rgb;
        actuate("leds", now);
    }

    @Override
    public String grip() throws InterruptedException {
        return gripper(StepRequest.Gripper.GRIP);
    }

    @Override
    public void release() throws InterruptedException {
        gripper(StepRequest.Gripper.RELEASE);
    }

    private String gripper(StepRequest.Gripper what) throws InterruptedException {
        if (state.type().properties().gripper() == null) {
            throw new UnsupportedOperationException(state.name() + " (a " + state.type().name() + ") has no gripper");
        }
        Command c = Command.gripper(what);
        link.execute(c);
        return c.text;
    }

    @Override
    public String gripped() {
        return state.gripped();
    }

    private long stepsFor(long ms) {
        if (ms < 0) {
            throw new IllegalArgumentException("time must be >= 0 ms, got " + ms);
        }
        long whole = ms / stepMs + (ms % stepMs == 0 ? 0 : 1); // rounded up, without overflow near Long.MAX_VALUE
        return Math.max(1, whole);
    }

    @Override
    public double[] sonarRanges() {
        return state.sonarMm();
    }

    @Override
    public double[] sonarAnglesDeg() {
        return sonarAngles.clone();
    }

    @Override
    public List<String> sensorNames() {
        return sensorNames;
    }

    @Override
    public double[] sensor(String name) {
        if (!sensorNames.contains(name)) {
            throw new IllegalArgumentException("no sensor named " + name + " on " + state.name() + " (it has "
                    + sensorNames + ")");
        }
        double[] values = state.reading(name);
        return values == null ? new double[0] : values.clone();
    }

    @Override
    public double xMm() {
        return state.xMm();
    }

    @Override
    public double yMm() {
        return state.yMm();
    }

    @Override
    public double headingDeg() {
        return state.headingDeg();
    }

    @Override
    public String lastContact() {
        return state.lastContact();
    }

    @Override
    public void send(String to, String text) {
        if (to == null || text == null) {
            throw new IllegalArgumentException("recipient and text must not be null");
        }
        int bytes = Limits.utfLength(text);
        if (bytes > Limits.MAX_UTF_BYTES || Limits.utfLength(to) > Limits.MAX_UTF_BYTES) {
            throw new IllegalArgumentException("a message of " + bytes + " bytes is more than the wire's limit of "
                    + Limits.MAX_UTF_BYTES);
        }
        state.send(to, text);
    }

    @Override
    public void broadcast(String text) {
        send(CommEvent.EVERYONE, text);
    }

    @Override
    public Message receive() {
        return state.nextMessage();
    }

    @Override
    public Message waitForMessage(long timeoutMs) throws InterruptedException {
        if (!state.hasMessage()) {
            link.execute(Command.idle(stepsFor(timeoutMs), true, state.wheels(), state.type().body().wheelBaseMm()));
        }
        return state.nextMessage();
    }

    @Override
    public long seed() {
        return seed;
    }

    /** The run's seed and the robot's name mixed (SplitMix64's finaliser): the same on every JVM. */
    static long seed(long worldSeed, String name) {
        long h = worldSeed * 0x9E3779B97F4A7C15L + name.hashCode();
        h = (h ^ (h >>> 30)) * 0xBF58476D1CE4E5B9L;
        h = (h ^ (h >>> 27)) * 0x94D049BB133111EBL;
        return h ^ (h >>> 31);
    }

    @Override
    public String parameter(String name, String defaultValue) {
        if (asked.size() < MAX_ASKED || parameters.containsKey(name)) { // (a bound: names from a link are anyone's)
            asked.add(name);
        }
        return parameters.getOrDefault(name, defaultValue);
    }

    /** The parameters its control code asked for so far, and those it was given. */
    ParameterAsks asks() {
        return new ParameterAsks(Set.copyOf(asked), parameters.keySet());
    }

    @Override
    public void report(String name, double value) {
        String bad = Report.problem(name, value);
        if (bad != null) {
            throw new IllegalArgumentException(bad);
        }
        state.report(name, value);
    }
}

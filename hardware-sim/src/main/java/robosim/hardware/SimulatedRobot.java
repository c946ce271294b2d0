package robosim.hardware;

import java.util.List;
import java.util.Map;
import robosim.api.Message;
import robosim.api.Robot;
import robosim.protocol.CommEvent;
import robosim.protocol.Limits;
import robosim.protocol.Report;
import robosim.protocol.SonarSpec;

/** The {@link Robot} the control code gets: blocking calls become {@link Command}s on the link. */
final class SimulatedRobot implements Robot {
    private final RobotKnowledge state;
    private final ControlLink link;
    private final List<String> robotNames;
    private final long stepMs;
    private final double[] sonarAngles;

    private final List<String> sensorNames;
    private final long seed;
    private final Map<String, String> parameters;

    /**
     * The robot {@code state} is of, its calls going through {@code link}; {@code worldSeed} and {@code parameters}
     * from its welcome.
     */
    SimulatedRobot(RobotKnowledge state, ControlLink link, List<String> robotNames, long stepMs, List<String> sensorNames,
            long worldSeed, Map<String, String> parameters) {
        this.state = state;
        this.seed = seed(worldSeed, state.name());
        this.parameters = Map.copyOf(parameters);
        this.link = link;
        this.sensorNames = List.copyOf(sensorNames);
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
        link.execute(Command.idle(stepsFor(ms), false));
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
            link.execute(Command.idle(stepsFor(timeoutMs), true));
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
        return parameters.getOrDefault(name, defaultValue);
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

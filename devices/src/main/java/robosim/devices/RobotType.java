package robosim.devices;

import java.util.List;
import robosim.protocol.RobotProperties;
import robosim.protocol.SonarSpec;

/**
 * A kind of robot, declared once: its name, a line on what it is, its {@link Body} and the devices it carries (its
 * sonar ring). What the Hardware Simulator sends in its handshake ({@link #properties}), what the file reader, the
 * Control Panel's add form and {@code describe.sh robots} know of it, all come from here. A built-in type is
 * registered for {@link java.util.ServiceLoader} ({@code @AutoService(RobotType.class)}) with a public no-argument
 * constructor, and named by its name; a type of one's own may be that too, or be named by its class (the file then
 * gives its radius). {@link RobotTypes} finds them. Immutable.
 */
public abstract class RobotType {
    private final String name;
    private final String summary;
    private final Body body;
    private final List<SonarSpec> sonars;
    private final RobotProperties properties;

    /** A type named {@code name}, a {@code body} carrying the sonar ring {@code sonars}. */
    protected RobotType(String name, String summary, Body body, List<SonarSpec> sonars) {
        this.name = name;
        this.summary = summary;
        this.body = body;
        this.sonars = List.copyOf(sonars);
        this.properties = new RobotProperties(name, body.radiusMm(), body.maxSpeedMmPerS(), body.maxTurnDegPerS(),
                this.sonars);
    }

    public final String name() {
        return name;
    }

    public final String summary() {
        return summary;
    }

    public final Body body() {
        return body;
    }

    /** Its sonar ring, in the transducers' order. */
    public final List<SonarSpec> sonars() {
        return sonars;
    }

    /** What it is, as a handshake says it. */
    public final RobotProperties properties() {
        return properties;
    }

    /** Speed {@code move} starts with, mm/s. */
    public final double defaultVelocityMmPerS() {
        return body.velocityMmPerS();
    }

    /** Rate {@code turn} starts with, deg/s. */
    public final double defaultRotVelocityDegPerS() {
        return body.rotVelocityDegPerS();
    }

    /** {@code count} transducers on the rim of a body of {@code radiusMm}, facing out at each of {@code anglesDeg}. */
    public static List<SonarSpec> ring(double radiusMm, double coneDeg, double rangeMm, double... anglesDeg) {
        SonarSpec[] ring = new SonarSpec[anglesDeg.length];
        for (int i = 0; i < anglesDeg.length; i++) {
            ring[i] = SonarSpec.onRim(radiusMm, anglesDeg[i], coneDeg, rangeMm);
        }
        return List.of(ring);
    }
}

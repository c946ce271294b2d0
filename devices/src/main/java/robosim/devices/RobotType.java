package robosim.devices;

import java.util.List;
import robosim.protocol.LedSpec;
import robosim.protocol.RaySpec;
import robosim.protocol.RobotProperties;
import robosim.protocol.SonarSpec;

/**
 * A kind of robot, declared once: its name, a line on what it is, its {@link Body} and the devices it carries: its
 * sonar ring, the rays of its proximity sensors, its LEDs, its gripper, and the sensors and actuators every robot of
 * the type has ({@link #devices}: a file may configure or switch off each). What the Hardware Simulator sends in its
 * handshake ({@link #properties}), what the file reader, the Control Panel's add form and {@code describe.sh robots}
 * know of it, all come from here. A built-in type is registered for {@link java.util.ServiceLoader}
 * ({@code @AutoService(RobotType.class)}) with a public no-argument constructor, and named by its name; a type of one's
 * own may be that too, or be named by its class (the file then gives its radius). {@link RobotTypes} finds them.
 * Immutable.
 */
public abstract class RobotType {
    private final String name;
    private final String summary;
    private final Body body;
    private final List<SonarSpec> sonars;
    private final List<DeviceSpec> devices;
    private final RobotProperties properties;

    /** A type named {@code name}, a {@code body} carrying the sonar ring {@code sonars} and nothing else. */
    protected RobotType(String name, String summary, Body body, List<SonarSpec> sonars) {
        this(name, summary, body, sonars, List.of(), List.of(), null, List.of());
    }

    /**
     * A type named {@code name}: a {@code body} carrying the sonar ring {@code sonars}, the proximity rays
     * {@code rays} (read by its {@code proximity} device), the LEDs {@code leds}, a {@code gripper} (null for none)
     * and the sensors and actuators {@code devices}.
     */
    protected RobotType(String name, String summary, Body body, List<SonarSpec> sonars, List<RaySpec> rays,
            List<LedSpec> leds, RobotProperties.Gripper gripper, List<DeviceSpec> devices) {
        this.name = name;
        this.summary = summary;
        this.body = body;
        this.sonars = List.copyOf(sonars);
        this.devices = List.copyOf(devices);
        this.properties = new RobotProperties(name, body.radiusMm(), body.heightMm(), body.massKg(),
                body.maxSpeedMmPerS(), body.maxTurnDegPerS(), this.sonars, rays, leds, gripper);
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

    /** The sensors and actuators every robot of the type has, in their order (its sonar aside). */
    public final List<DeviceSpec> devices() {
        return devices;
    }

    /**
     * How it meets what blocks its move: false (the report's robots) it stops where it touches; true (the swarm
     * robots, as ARGoS's dynamics2d moves them) it slides along it with what is left of the move.
     */
    public boolean slides() {
        return false;
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

    /** Rays from the rim of a body of {@code radiusMm}, straight out at each of {@code anglesDeg}. */
    public static List<RaySpec> rays(double radiusMm, double rangeMm, double... anglesDeg) {
        RaySpec[] rays = new RaySpec[anglesDeg.length];
        for (int i = 0; i < anglesDeg.length; i++) {
            rays[i] = RaySpec.onRim(radiusMm, anglesDeg[i], rangeMm);
        }
        return List.of(rays);
    }

    /** {@code count} angles, degrees, the first at {@code first}, evenly round. */
    public static double[] evenly(int count, double first) {
        double[] a = new double[count];
        for (int i = 0; i < count; i++) {
            a[i] = first + 360.0 * i / count;
        }
        return a;
    }
}

package robosim.hardware;

import robosim.protocol.RobotProperties;

/**
 * A kind of robot: its shape, speed limits and sonar layout, sent to the Environment in the
 * handshake, and its default velocities. One subclass per type.
 */
public abstract class RobotType {
    /** The properties sent in the handshake. */
    public abstract RobotProperties properties();

    /** Speed {@code move} starts with, mm/s. */
    public double defaultVelocityMmPerS() {
        return 500;
    }

    /** Rate {@code turn} starts with, deg/s. */
    public double defaultRotVelocityDegPerS() {
        return 90;
    }

    /** {@code ArRobot}, {@code Scout}, or the fully qualified name of a RobotType subclass. */
    public static RobotType byName(String name) {
        switch (name) {
            case "ArRobot":
                return new ArRobot();
            case "Scout":
                return new Scout();
            default:
                try {
                    return Class.forName(name).asSubclass(RobotType.class).getDeclaredConstructor().newInstance();
                } catch (ReflectiveOperationException | ClassCastException e) {
                    throw new IllegalArgumentException("robot type \"" + name + "\" is neither ArRobot, Scout nor a "
                            + "RobotType class on the class path");
                }
        }
    }
}

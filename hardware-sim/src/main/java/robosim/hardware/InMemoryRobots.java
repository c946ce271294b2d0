package robosim.hardware;

import robosim.api.RobotControl;
import robosim.protocol.InMemoryLink;

/**
 * The Hardware Simulator's robots for a one-JVM run, found by the Environment through
 * {@code META-INF/services/robosim.protocol.InMemoryLink$Starter}: each an {@link InMemoryRobot} with its
 * type and a new instance of its control class, found on this JVM's class path; or, for a caller that
 * holds the control object itself (the testkit), {@link #robot}.
 */
public final class InMemoryRobots implements InMemoryLink.Starter {
    @Override
    public InMemoryLink.Robot start(String name, String type, String controlClass,
            InMemoryLink.Environment environment) {
        return robot(name, type, RobotLauncher.control(controlClass), environment);
    }

    /**
     * A robot named {@code name} of {@code type} ({@code ArRobot}, {@code Scout} or a RobotType class) running
     * {@code control}, whose requests go to {@code environment}.
     *
     * @throws IllegalArgumentException naming an unknown type
     */
    public static InMemoryLink.Robot robot(String name, String type, RobotControl control,
            InMemoryLink.Environment environment) {
        return new InMemoryRobot(new HardwareSimulator(name, RobotType.byName(type)), control, environment);
    }
}

package robosim.hardware;

import robosim.protocol.InMemoryLink;

/**
 * The Hardware Simulator's robots for a one-JVM run, found by the Environment through
 * {@code META-INF/services/robosim.protocol.InMemoryLink$Starter}: each an {@link InMemoryRobot} with its
 * type and a new instance of its control class, found on this JVM's class path.
 */
public final class InMemoryRobots implements InMemoryLink.Starter {
    @Override
    public InMemoryLink.Robot start(String name, String type, String controlClass,
            InMemoryLink.Environment environment) {
        RobotType t = RobotType.byName(type);
        return new InMemoryRobot(new HardwareSimulator(name, t), RobotLauncher.control(controlClass), environment);
    }
}

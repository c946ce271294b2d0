package robosim.devices;

import robosim.protocol.RobotProperties;

/**
 * A kind of actuator: one class, which declares what it is ({@link ActuatorInfo}), reads its attributes
 * ({@link #configure}), takes the body it is mounted on ({@link #mount}), says the shape of the values it is set to
 * ({@link #values}) and keeps the last ones set ({@link #set}), which the world reads (the LEDs cameras see, the
 * bytes the range-and-bearing medium carries). A built-in actuator is registered for {@link java.util.ServiceLoader}
 * ({@code @AutoService(RobotActuator.class)}) and named by its name in a robot type's devices; {@link Actuators} finds
 * them. Needs a public no-argument constructor. One instance per robot and actuator; set and read on the thread that
 * steps the world.
 */
public abstract class RobotActuator {
    private final ActuatorInfo info;

    protected RobotActuator(ActuatorInfo info) {
        this.info = info;
    }

    public final ActuatorInfo info() {
        return info;
    }

    /** Reads its attributes (each declared in its {@link ActuatorInfo}); the default takes none. */
    protected void configure(Attributes attributes) {
    }

    /** Takes the body it is mounted on (null when not known); the default ignores it. */
    protected void mount(RobotProperties robot) {
    }

    /** The values it is set to: how many, their range. */
    public abstract ActuatorValues values();

    /**
     * Sets it to {@code values}, checked first ({@link ActuatorValues#problem}): an IllegalArgumentException naming the
     * value when they cannot be set, and nothing changes.
     */
    public final void set(double[] values) {
        String problem = values().problem(info.name(), values);
        if (problem != null) {
            throw new IllegalArgumentException(problem);
        }
        apply(values.clone());
    }

    /** Keeps {@code values}, which are checked. */
    protected abstract void apply(double[] values);
}

package robosim.devices;

import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;
import java.util.TreeMap;
import robosim.protocol.RobotProperties;

/**
 * The registered actuators: every {@link RobotActuator} registered for {@link ServiceLoader} on the class path, by
 * name. What names an actuator reads it here: a robot type's devices, the file reader, {@code describe.sh actuators},
 * the Environment, the learners' action spaces. Any thread.
 */
public final class Actuators {
    private static final Map<String, ServiceLoader.Provider<RobotActuator>> PROVIDERS = load();
    private static final List<ActuatorInfo> REGISTERED = PROVIDERS.values().stream().map(p -> p.get().info())
            .sorted(Comparator.comparing(ActuatorInfo::name)).toList();

    private Actuators() {
    }

    /** Every registered actuator, by name. */
    public static List<ActuatorInfo> all() {
        return REGISTERED;
    }

    /** The registered actuator named {@code name}, or null. */
    public static ActuatorInfo info(String name) {
        ServiceLoader.Provider<RobotActuator> p = PROVIDERS.get(name);
        return p == null ? null : p.get().info();
    }

    /**
     * A configured actuator of kind {@code name} mounted on {@code robot} (null: not known); an unknown kind or a bad
     * or unknown attribute is an IllegalArgumentException saying what.
     */
    public static RobotActuator create(String name, Map<String, String> attributes, RobotProperties robot) {
        ServiceLoader.Provider<RobotActuator> p = PROVIDERS.get(name);
        if (p == null) {
            throw new IllegalArgumentException("no actuator \"" + robosim.protocol.Printable.of(name, 64)
                    + "\" (the actuators: " + String.join(", ", PROVIDERS.keySet()) + ")");
        }
        RobotActuator actuator = p.get();
        Attributes a = new Attributes(attributes);
        actuator.configure(a);
        if (!a.unread().isEmpty()) {
            throw new IllegalArgumentException("unknown attribute(s) " + a.unread() + " for a " + name + " actuator "
                    + "(it takes: " + String.join(", ", actuator.info().attributes().stream().map(Attribute::name)
                    .toList()) + ")");
        }
        actuator.mount(robot);
        return actuator;
    }

    private static Map<String, ServiceLoader.Provider<RobotActuator>> load() {
        Map<String, ServiceLoader.Provider<RobotActuator>> all = new TreeMap<>();
        ServiceLoader.load(RobotActuator.class, Actuators.class.getClassLoader()).stream().forEach(p -> {
            ServiceLoader.Provider<RobotActuator> was = all.put(p.get().info().name(), p);
            if (was != null) {
                throw new IllegalStateException("two actuators are named " + p.get().info().name() + ": "
                        + was.type().getName() + " and " + p.type().getName());
            }
        });
        return all;
    }
}
